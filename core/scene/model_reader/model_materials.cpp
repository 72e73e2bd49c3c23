#include "model_reader/model_materials.hpp"

#include "io/file_bytes.hpp"
#include "jtracer/texture.hpp"

#include <assimp/material.h>
#include <assimp/texture.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>

namespace jt {

namespace {

constexpr std::uint32_t kNoIndex = 0xffffffffu;

std::string lower(std::string_view text) {
    std::string s(text);
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

bool blank(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && blank(s.front())) s.remove_prefix(1);
    while (!s.empty() && blank(s.back())) s.remove_suffix(1);
    return s;
}

std::vector<std::string_view> words(std::string_view s) {
    std::vector<std::string_view> out;
    std::size_t at = 0;
    while (at < s.size()) {
        while (at < s.size() && blank(s[at])) ++at;
        const std::size_t start = at;
        while (at < s.size() && !blank(s[at])) ++at;
        if (at > start) out.push_back(s.substr(start, at - start));
    }
    return out;
}

// Calls `line(keyword, rest, number)` for every line of `text`, a backslash
// at the end of a line joining it to the next as OBJ files allow (`number`,
// from 1, is then the first line's).
template <typename Line>
void for_each_line(std::string_view text, Line line) {
    std::string joined;
    std::size_t at = 0, number = 0, first = 1;
    while (at < text.size()) {
        ++number;
        std::size_t end = text.find('\n', at);
        if (end == std::string_view::npos) end = text.size();
        std::string_view piece = text.substr(at, end - at);
        at = end + 1;
        if (!piece.empty() && piece.back() == '\r') piece.remove_suffix(1);
        if (!piece.empty() && piece.back() == '\\') {
            if (joined.empty()) first = number;
            joined.append(piece.substr(0, piece.size() - 1)).push_back(' ');
            continue;
        }
        if (joined.empty()) first = number;
        joined.append(piece);
        const std::string_view whole = trim(joined);
        std::size_t key_end = 0;
        while (key_end < whole.size() && !blank(whole[key_end])) ++key_end;
        line(whole.substr(0, key_end), trim(whole.substr(key_end)), first);
        joined.clear();
    }
}

std::string_view as_text(const std::vector<std::uint8_t>& bytes) {
    return {reinterpret_cast<const char*>(bytes.data()), bytes.size()};
}

// What an OBJ's material library says of one material.
struct LibraryMaterial {
    std::optional<Colour> kd;
    // The file map_Kd names: the words after its options, blanks and all;
    // then, after an option not known, the line's last word. Empty without
    // map_Kd.
    std::vector<std::string> map_kd;
    std::string map_kd_line;       // "line N of 'LIBRARY'", for messages
    std::filesystem::path folder;  // of the library, where map_Kd is found
};

// `Kd r [g b]`: nullopt when not three (or one) finite numbers.
std::optional<Colour> read_kd(std::string_view rest) {
    rest = rest.substr(0, rest.find('#'));  // a comment after the numbers
    const std::vector<std::string_view> w = words(rest);
    if (w.size() != 1 && w.size() != 3) return std::nullopt;
    double v[3] = {0.0, 0.0, 0.0};
    for (std::size_t i = 0; i < w.size(); ++i) {
        const auto [end, error] = std::from_chars(w[i].data(), w[i].data() + w[i].size(), v[i]);
        if (error != std::errc() || end != w[i].data() + w[i].size() || !std::isfinite(v[i]))
            return std::nullopt;
    }
    if (w.size() == 1) v[1] = v[2] = v[0];
    return Colour(v[0], v[1], v[2]);
}

// How many numbers each option of a texture line takes (the MTL format's
// list); -o, -s and -t take one to three.
int option_arguments(std::string_view option) {
    static const std::map<std::string, int, std::less<>> counts{
        {"-blendu", 1},  {"-blendv", 1}, {"-boost", 1}, {"-cc", 1},   {"-clamp", 1},
        {"-imfchan", 1}, {"-texres", 1}, {"-bm", 1},    {"-type", 1}, {"-mm", 2},
        {"-o", 3},       {"-s", 3},      {"-t", 3}};
    const auto known = counts.find(lower(option));
    return known == counts.end() ? -1 : known->second;
}

bool is_number(std::string_view word) {
    double value = 0.0;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    return error == std::errc() && end == word.data() + word.size();
}

// The file a map_Kd line names (see LibraryMaterial::map_kd), folders
// separated by '/' (files written on Windows use backslashes).
std::vector<std::string> texture_names(std::string_view rest) {
    const std::vector<std::string_view> w = words(rest);
    if (w.empty()) return {};
    std::size_t k = 0;
    while (k < w.size()) {
        const int count = option_arguments(w[k]);
        if (count < 0) break;
        ++k;
        // -o, -s and -t take up to three numbers, the others all they name.
        const bool up_to = count == 3;
        for (int n = 0; n < count && k < w.size(); ++n, ++k)
            if (up_to && n > 0 && !is_number(w[k])) break;
    }
    std::vector<std::string> names;
    if (k < w.size()) {
        // From the first word of the name to the line's end, inner blanks kept.
        const std::size_t from = static_cast<std::size_t>(w[k].data() - rest.data());
        names.emplace_back(trim(rest.substr(from)));
    }
    // An option this list does not know: its words cannot be told from the
    // name's, so the last word may be the file too.
    if (names.empty() || (names.front()[0] == '-' && names.front() != w.back()))
        names.emplace_back(w.back());
    for (std::string& name : names) std::replace(name.begin(), name.end(), '\\', '/');
    return names;
}

// Every material of the libraries Assimp opened, in order; a later one of
// the same name adds to (and overrides) the earlier, as Assimp does.
Expected<std::map<std::string, LibraryMaterial>> read_libraries(
    const std::vector<std::filesystem::path>& libraries) {
    std::map<std::string, LibraryMaterial> materials;
    for (const std::filesystem::path& library : libraries) {
        const Expected<std::vector<std::uint8_t>> bytes = read_file_bytes(library);
        if (!bytes) return Error{"its material library cannot be read: " + bytes.error().message};
        LibraryMaterial* current = nullptr;
        std::string problem;
        for_each_line(
            as_text(*bytes), [&](std::string_view key, std::string_view rest, std::size_t number) {
                const std::string k = lower(key);
                if (k == "newmtl") {
                    current = &materials[std::string(rest)];
                    current->folder = library.parent_path();
                } else if (current && k == "kd") {
                    current->kd = read_kd(rest);
                    if (!current->kd && problem.empty())
                        problem = "its material library '" + library.string() +
                                  "' has a Kd that is not one or three finite numbers: 'Kd " +
                                  std::string(rest) + "'";
                } else if (current && k == "map_kd") {
                    current->map_kd = texture_names(rest);
                    current->map_kd_line =
                        "line " + std::to_string(number) + " of '" + library.string() + "'";
                }
            });
        if (!problem.empty()) return Error{problem};
    }
    return materials;
}

// Every face of an OBJ as Assimp lists them (a `p` line of n points gives n
// faces, an `l` line of n corners n - 1 lines), with the material name in
// force (kNoIndex before any `usemtl`). `reliable` is false when the order
// of Assimp's meshes need not follow the file's (an object named twice).
struct ObjFaces {
    std::vector<std::string> names;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> faces;  // (name, corners)
    bool reliable = true;
};

ObjFaces scan_obj(std::string_view text) {
    ObjFaces scan;
    std::uint32_t current = kNoIndex;
    // Owned copies: the line for_each_line hands over lives in a buffer it
    // reuses for the next line.
    std::set<std::string, std::less<>> objects;
    for_each_line(text, [&](std::string_view key, std::string_view rest, std::size_t) {
        if (key == "usemtl") {
            const auto known = std::find(scan.names.begin(), scan.names.end(), rest);
            current = static_cast<std::uint32_t>(known - scan.names.begin());
            if (known == scan.names.end()) scan.names.emplace_back(rest);
        } else if (key == "o") {
            if (!objects.emplace(rest).second) scan.reliable = false;
        } else if (key == "f" || key == "l" || key == "p") {
            const auto n = static_cast<std::uint32_t>(words(rest).size());
            if (n == 0) return;
            if (key == "f") scan.faces.emplace_back(current, n);
            if (key == "l")
                for (std::uint32_t i = 1; i < n; ++i) scan.faces.emplace_back(current, 2);
            if (key == "p")
                for (std::uint32_t i = 0; i < n; ++i) scan.faces.emplace_back(current, 1);
        }
    });
    return scan;
}

// Whether the scanned faces are Assimp's, in order, with the same corners.
bool scan_matches(const ObjFaces& scan, const aiScene& scene) {
    if (!scan.reliable) return false;
    std::size_t k = 0;
    for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
        const aiMesh* mesh = scene.mMeshes[m];
        if (!mesh) continue;
        for (unsigned f = 0; f < mesh->mNumFaces; ++f, ++k)
            if (k >= scan.faces.size() || scan.faces[k].second != mesh->mFaces[f].mNumIndices)
                return false;
    }
    return k == scan.faces.size();
}

// Parts made as faces name them: one for the faces without a material, one
// for each material used.
class PartList {
  public:
    std::uint32_t none() {
        if (none_ == kNoIndex) {
            none_ = add({});
        }
        return none_;
    }
    std::optional<std::uint32_t> find(const std::string& key) const {
        const auto at = by_key_.find(key);
        if (at == by_key_.end()) return std::nullopt;
        return at->second;
    }
    std::uint32_t of(const std::string& key, ModelPart part) {
        const auto [at, added] = by_key_.emplace(key, 0);
        if (added) at->second = add(std::move(part));
        return at->second;
    }
    std::vector<ModelPart> take() && { return std::move(parts_); }

  private:
    std::uint32_t add(ModelPart part) {
        parts_.push_back(std::move(part));
        return static_cast<std::uint32_t>(parts_.size() - 1);
    }
    std::vector<ModelPart> parts_;
    std::map<std::string, std::uint32_t> by_key_;
    std::uint32_t none_ = kNoIndex;
};

// A texture file named by the model: confined as the files Assimp opens are,
// and decoded (and cached) as image maps are.
Expected<std::shared_ptr<const Texture>> texture_file(const std::filesystem::path& path,
                                                      const std::string& name,
                                                      const ConfinedIOSystem& io,
                                                      const ModelReaderHost& host) {
    if (!io.contains(path))
        return Error{"its texture '" + name + "' lies outside the folder '" + io.folder().string() +
                     "'"};
    Expected<std::shared_ptr<const Texture>> texture = host.load_texture(path);
    if (!texture) return Error{"its texture '" + name + "': " + texture.error().message};
    return texture;
}

// A texture inside the file (a .glb's or a data URI's image): compressed
// bytes, or (formats of old) texels given as they are, top row first.
Expected<std::shared_ptr<const Texture>> embedded_texture(const aiTexture& embedded,
                                                          const std::string& name,
                                                          const ModelReaderHost& host) {
    Texture texture;
    if (!embedded.pcData) return Error{"its texture '" + name + "' has no data"};
    if (embedded.mHeight == 0) {
        const auto* bytes = reinterpret_cast<const std::uint8_t*>(embedded.pcData);
        Expected<Texture> decoded = host.decode_texture({bytes, embedded.mWidth});
        if (!decoded) return Error{"its texture '" + name + "': " + decoded.error().message};
        texture = std::move(*decoded);
    } else {
        const std::int64_t texels = std::int64_t{embedded.mWidth} * embedded.mHeight;
        if (embedded.mWidth > kMaxTextureTexels || embedded.mHeight > kMaxTextureTexels ||
            texels > kMaxTextureTexels)
            return Error{"its texture '" + name + "' is too large"};
        texture.width = static_cast<int>(embedded.mWidth);
        texture.height = static_cast<int>(embedded.mHeight);
        texture.rgb8.resize(3 * static_cast<std::size_t>(texels));
        for (int j = 0; j < texture.height; ++j)
            for (int i = 0; i < texture.width; ++i) {
                const aiTexel& t =
                    embedded
                        .pcData[static_cast<std::size_t>(texture.height - 1 - j) * texture.width +
                                i];
                std::uint8_t* out =
                    &texture.rgb8[3 * (static_cast<std::size_t>(j) * texture.width + i)];
                out[0] = t.r;
                out[1] = t.g;
                out[2] = t.b;
            }
    }
    return std::make_shared<const Texture>(std::move(texture));
}

Expected<MaterialPlan> obj_plan(const aiScene& scene, const std::filesystem::path& file,
                                const ConfinedIOSystem& io, const ModelReaderHost& host) {
    if (!io.library_failure().empty()) return Error{io.library_failure()};
    Expected<std::map<std::string, LibraryMaterial>> library = read_libraries(io.libraries());
    if (!library) return library.error();
    const Expected<std::vector<std::uint8_t>> bytes = read_file_bytes(file);
    if (!bytes) return bytes.error();
    const ObjFaces scan = scan_obj(as_text(*bytes));

    MaterialPlan plan;
    PartList parts;
    // Each textured material's file: its name, path and map_Kd line.
    struct TextureFile {
        std::string name;
        std::filesystem::path path;
        std::string line;
    };
    std::map<std::string, TextureFile> textures;
    auto part_named = [&](const std::string* name) -> std::uint32_t {
        if (!name) return parts.none();
        const auto known = library->find(*name);
        if (known == library->end()) return parts.none();  // an unknown name: the block's
        ModelPart part;
        part.name = *name;
        part.has_material = true;
        part.base = known->second.kd.value_or(Colour(1.0));
        const LibraryMaterial& material = known->second;
        if (!material.map_kd.empty()) {
            // The whole name when such a file exists, else the last word when
            // that one does, else the whole name, which is then reported missing.
            part.texture_name = material.map_kd.front();
            for (const std::string& candidate : material.map_kd) {
                std::error_code error;
                const std::filesystem::path path = material.folder / candidate;
                if (io.contains(path) && std::filesystem::is_regular_file(path, error)) {
                    part.texture_name = candidate;
                    break;
                }
            }
            textures[*name] = {part.texture_name, material.folder / part.texture_name,
                               material.map_kd_line};
        }
        return parts.of(*name, std::move(part));
    };
    plan.face_parts.resize(scene.mNumMeshes);
    const bool by_scan = scan_matches(scan, scene);
    std::vector<std::uint32_t> part_of_name(scan.names.size(), kNoIndex);
    std::size_t k = 0;
    for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
        const aiMesh* mesh = scene.mMeshes[m];
        if (!mesh) continue;
        if (!by_scan) {
            // Assimp's own word, which is right but for faces before a `usemtl`.
            aiString name;
            const aiMaterial* material = mesh->mMaterialIndex < scene.mNumMaterials
                                             ? scene.mMaterials[mesh->mMaterialIndex]
                                             : nullptr;
            const bool named = material && material->Get(AI_MATKEY_NAME, name) == aiReturn_SUCCESS;
            const std::string text = named ? name.C_Str() : "";
            plan.face_parts[m] = {part_named(named ? &text : nullptr)};
            continue;
        }
        std::vector<std::uint32_t>& faces = plan.face_parts[m];
        faces.reserve(mesh->mNumFaces);
        for (unsigned f = 0; f < mesh->mNumFaces; ++f, ++k) {
            const std::uint32_t name = scan.faces[k].first;
            if (name == kNoIndex) {
                faces.push_back(parts.none());
                continue;
            }
            // Looked up once a name, not once a face.
            if (part_of_name[name] == kNoIndex) part_of_name[name] = part_named(&scan.names[name]);
            faces.push_back(part_of_name[name]);
        }
    }
    plan.parts = std::move(parts).take();
    for (ModelPart& part : plan.parts) {
        if (part.texture_name.empty()) continue;
        const TextureFile& named = textures.at(part.name);
        Expected<std::shared_ptr<const Texture>> texture =
            texture_file(named.path, named.name, io, host);
        if (!texture) return Error{texture.error().message + " (map_Kd on " + named.line + ")"};
        part.texture = std::move(*texture);
    }
    return plan;
}

Expected<MaterialPlan> gltf_plan(const aiScene& scene, const std::filesystem::path& file,
                                 const ConfinedIOSystem& io, std::uint64_t gltf_materials,
                                 const ModelReaderHost& host) {
    MaterialPlan plan;
    PartList parts;
    plan.face_parts.resize(scene.mNumMeshes);
    for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
        const aiMesh* mesh = scene.mMeshes[m];
        const unsigned index = mesh ? mesh->mMaterialIndex : scene.mNumMaterials;
        if (index >= gltf_materials || index >= scene.mNumMaterials || !scene.mMaterials[index]) {
            plan.face_parts[m] = {parts.none()};
            continue;
        }
        const std::string key = std::to_string(index);
        if (const std::optional<std::uint32_t> known = parts.find(key)) {
            plan.face_parts[m] = {*known};
            continue;
        }
        const aiMaterial& material = *scene.mMaterials[index];
        ModelPart part;
        aiString name;
        if (material.Get(AI_MATKEY_NAME, name) == aiReturn_SUCCESS) part.name = name.C_Str();
        if (part.name.empty()) part.name = "material " + std::to_string(index);
        part.has_material = true;
        aiColor4D base(1.0f, 1.0f, 1.0f, 1.0f);
        if (material.Get(AI_MATKEY_BASE_COLOR, base) == aiReturn_SUCCESS ||
            material.Get(AI_MATKEY_COLOR_DIFFUSE, base) == aiReturn_SUCCESS)
            part.base = Colour(base.r, base.g, base.b);
        if (!std::isfinite(part.base.x) || !std::isfinite(part.base.y) ||
            !std::isfinite(part.base.z))
            return Error{"its material '" + part.name + "' has a base colour that is not finite"};
        aiString texture;
        if (material.GetTexture(aiTextureType_BASE_COLOR, 0, &texture) == aiReturn_SUCCESS ||
            material.GetTexture(aiTextureType_DIFFUSE, 0, &texture) == aiReturn_SUCCESS) {
            const std::string uri = texture.C_Str();
            if (const aiTexture* embedded = scene.GetEmbeddedTexture(uri.c_str())) {
                part.texture_name = "embedded image " + uri.substr(uri.rfind('*') + 1);
                Expected<std::shared_ptr<const Texture>> decoded =
                    embedded_texture(*embedded, part.texture_name, host);
                if (!decoded) return decoded.error();
                part.texture = std::move(*decoded);
            } else if (!uri.empty()) {
                part.texture_name = uri;
                Expected<std::shared_ptr<const Texture>> read =
                    texture_file(file.parent_path() / uri, uri, io, host);
                if (!read) return read.error();
                part.texture = std::move(*read);
            }
        }
        plan.face_parts[m] = {parts.of(key, std::move(part))};
    }
    plan.parts = std::move(parts).take();
    return plan;
}

// What a file of a format whose colours are not read holds that a 3D tool
// would show: textures, vertex colours (but PLY's, which are read), or faces
// of materials of different colours.
std::string colours_not_read(const aiScene& scene, bool ply) {
    std::vector<std::string> held;
    std::set<std::tuple<float, float, float>> colours;
    bool textures = false;
    for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
        const aiMesh& mesh = *scene.mMeshes[m];
        if (mesh.mMaterialIndex >= scene.mNumMaterials) continue;
        const aiMaterial& material = *scene.mMaterials[mesh.mMaterialIndex];
        textures = textures || material.GetTextureCount(aiTextureType_DIFFUSE) > 0 ||
                   material.GetTextureCount(aiTextureType_BASE_COLOR) > 0;
        if (aiColor3D c; material.Get(AI_MATKEY_COLOR_DIFFUSE, c) == aiReturn_SUCCESS)
            colours.insert({c.r, c.g, c.b});
    }
    bool vertex_colours = false;
    for (unsigned m = 0; m < scene.mNumMeshes && !ply; ++m)
        vertex_colours = vertex_colours || scene.mMeshes[m]->mColors[0] != nullptr;
    if (textures) held.push_back("textures");
    if (colours.size() > 1) held.push_back("material colours");
    if (vertex_colours) held.push_back("vertex colours");
    std::string said;
    for (std::size_t i = 0; i < held.size(); ++i)
        said += (i == 0 ? "" : i + 1 == held.size() ? " and " : ", ") + held[i];
    return said;
}

}  // namespace

Expected<MaterialPlan> plan_materials(const aiScene& scene, const std::filesystem::path& file,
                                      const ConfinedIOSystem& io, std::uint64_t gltf_materials,
                                      const ModelReaderHost& host) {
    const std::string ext = lower(file.extension().string());
    Expected<MaterialPlan> plan = MaterialPlan{};
    if (ext == ".obj")
        plan = obj_plan(scene, file, io, host);
    else if (ext == ".gltf" || ext == ".glb")
        plan = gltf_plan(scene, file, io, gltf_materials, host);
    else {
        plan->parts.emplace_back();
        plan->face_parts.assign(scene.mNumMeshes, {0});
    }
    if (plan) plan->vertex_colours = ext == ".obj" || ext == ".ply";
    if (plan && ext != ".obj" && ext != ".gltf" && ext != ".glb")
        plan->unread = colours_not_read(scene, ext == ".ply");
    return plan;
}

}  // namespace jt
