// The model reader module (io/model_reader.hpp): read_model's work on a file,
// through Assimp.
#include "io/file_bytes.hpp"
#include "io/model_reader.hpp"
#include "jtracer/version.hpp"
#include "model_reader/cerr_capture.hpp"
#include "model_reader/confined_io_system.hpp"
#include "model_reader/gltf_rules.hpp"
#include "model_reader/model_materials.hpp"
#include "model_reader/model_messages.hpp"
#include "model_reader/polygon.hpp"

#include <assimp/BaseImporter.h>
#include <assimp/importerdesc.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <fstream>
#include <limits>
#include <memory>
#include <new>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

// Debian's Assimp is built with its internal assertions on, and a failed one
// aborts the process: a malformed model file would end the program. This
// definition takes the library's place (its calls go through the PLT, and this
// module, which exports it, is searched before the libraries it loads) and
// throws instead; the importer turns the exception into its error string,
// which read_model reports as the model's.
namespace Assimp {
JT_MODEL_READER_EXPORT void aiAssertViolation(const char* expression, const char* file, int line) {
    std::string where = file ? file : "?";
    where = where.substr(where.find_last_of('/') + 1) + ":" + std::to_string(line);
    throw std::runtime_error("malformed model (Assimp's check '" +
                             std::string(expression ? expression : "?") + "' failed at " + where +
                             ")");
}
}  // namespace Assimp

namespace jt {

namespace {

std::string lower_extension(const std::filesystem::path& file) {
    std::string ext = file.extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

// What a PLY header must be before Assimp reads the file, or "" when it is
// one (or the file is no PLY, whose first line starts "ply" in any case):
// - it ends with a line that is "end_header" alone: Assimp 5.2 reads for ever
//   through a header without one, and through one whose data starts on the
//   end_header line itself;
// - it declares each element once: Assimp corrupts its heap on a binary file
//   that declares one twice;
// - its element counts fit in the file (each instance takes a byte at least),
//   so that a short file cannot make the reader reserve room for billions.
constexpr int kMaxPlyHeaderLines = 10000;
std::string ply_header_problem(const std::filesystem::path& file, std::uintmax_t size) {
    std::ifstream in(file, std::ios::binary);
    std::string line;
    // Assimp takes "ply" in any case as the magic word.
    if (!std::getline(in, line) || line.size() < 3) return "";
    for (std::size_t i = 0; i < 3; ++i)
        if (std::tolower(static_cast<unsigned char>(line[i])) != "ply"[i]) return "";
    std::vector<std::string> elements;
    for (int lines = 0; lines < kMaxPlyHeaderLines && std::getline(in, line); ++lines) {
        if (line.rfind("end_header", 0) == 0) {
            if (line.find_first_not_of(" \t\r", 10) == std::string::npos) return "";
            return "its PLY header's end_header line has more on it (the data must start on the "
                   "next line)";
        }
        std::istringstream words(line);
        std::string keyword, name;
        double count = 0.0;
        if (!(words >> keyword) || keyword != "element") continue;
        if (!(words >> name >> count)) return "a PLY element line without a count: " + line;
        if (std::find(elements.begin(), elements.end(), name) != elements.end())
            return "its PLY header declares the element '" + name + "' twice";
        elements.push_back(name);
        if (!(count <= static_cast<double>(size)))
            return "its header claims " + line.substr(8) + ", more than the file's " +
                   std::to_string(size) + " bytes can hold";
    }
    return "its PLY header does not end (no end_header line within " +
           std::to_string(kMaxPlyHeaderLines) + " lines)";
}

// The words at the start of a text file as Assimp's OFF reader takes them:
// separated by blanks and line ends, with lines that start with '#' skipped.
class HeaderWords {
  public:
    explicit HeaderWords(const std::filesystem::path& file) : in_(file, std::ios::binary) {}
    // The next word, or "" at the end of the file or past kMaxWord characters
    // (no header of numbers and keywords has such words).
    std::string next() {
        int c = in_.get();
        for (;;) {
            while (c != EOF && std::isspace(c)) c = in_.get();
            if (c != '#') break;
            while (c != EOF && c != '\n') c = in_.get();
        }
        std::string word;
        for (; c != EOF && !std::isspace(c) && c != '#'; c = in_.get()) {
            if (word.size() == kMaxWord) return "";
            word += static_cast<char>(c);
        }
        return word;
    }

  private:
    static constexpr std::size_t kMaxWord = 64;
    std::ifstream in_;
};

// What an OFF header must be before Assimp reads the file, or "" when it is
// one (or the file is no OFF): its counts of vertices and faces must fit in
// the file (each takes a line, a byte at least). Assimp 5.2 allocates and
// fills its vertices from the count before reading a line, so a short file
// claiming billions took all the memory. The keyword ([ST][C][N][4][n]OFF,
// a dimension after it for nOFF) marks an OFF file whatever its extension,
// and a .off file may leave it out and start with the counts.
std::string off_header_problem(const std::filesystem::path& file, std::uintmax_t size) {
    HeaderWords words(file);
    std::string word = words.next();
    std::string_view keyword = word;
    bool dimension = false;
    for (const std::string_view prefix : {"ST", "C", "N", "4", "n"})
        if (keyword.substr(0, prefix.size()) == prefix) {
            keyword.remove_prefix(prefix.size());
            dimension = prefix == "n";
        }
    if (keyword == "OFF") {
        if (dimension) words.next();
        word = words.next();
    } else if (lower_extension(file) != ".off") {
        return "";
    }
    const std::string faces = words.next();
    for (const auto& [count, what] : {std::pair{word, "vertices"}, std::pair{faces, "faces"}}) {
        // Assimp reads a count's leading digits.
        const std::string digits = count.substr(0, count.find_first_not_of("0123456789"));
        if (digits.empty()) continue;
        if (digits.size() > std::numeric_limits<std::uintmax_t>::digits10 ||
            std::stoull(digits) > size)
            return "its OFF header claims " + digits + " " + what + ", more than the file's " +
                   std::to_string(size) + " bytes can hold";
    }
    return "";
}

// Where the files a model refers to may be: the scene's folder when the
// model lies in it, else the model's own folder.
std::filesystem::path reference_folder(const std::filesystem::path& file,
                                       const std::filesystem::path& folder) {
    std::error_code error;
    const auto model = std::filesystem::weakly_canonical(std::filesystem::absolute(file), error);
    const auto scene = std::filesystem::weakly_canonical(
        std::filesystem::absolute(folder.empty() ? "." : folder), error);
    const auto relative = model.lexically_relative(scene);
    if (!relative.empty() && *relative.begin() != "..") return scene;
    return model.parent_path();
}

// The language reads glTF 2.0 (docs/language.md §13.5). Assimp's glTF 1.0
// importer is left out: on malformed input it reads past its buffers
// (found by fuzz/model_fuzzer), and no current tool writes glTF 1.0.
// The file's first bytes, enough to tell a format by its signature; fewer
// when it is shorter or cannot be read (Assimp then says why).
std::vector<std::uint8_t> file_head(const std::filesystem::path& file) {
    std::vector<std::uint8_t> head(16);
    std::ifstream in(file, std::ios::binary);
    in.read(reinterpret_cast<char*>(head.data()), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(std::max<std::streamsize>(0, in.gcount())));
    return head;
}

void leave_out_gltf1(Assimp::Importer& importer) {
    for (std::size_t i = 0; i < importer.GetImporterCount(); ++i) {
        const aiImporterDesc* info = importer.GetImporterInfo(i);
        if (info && std::string_view(info->mName) == "glTF Importer") {
            // Once unregistered, the loader is ours to delete.
            std::unique_ptr<Assimp::BaseImporter> gltf1(importer.GetImporter(i));
            if (importer.UnregisterLoader(gltf1.get()) != aiReturn_SUCCESS) gltf1.release();
            return;
        }
    }
}

glm::dmat4 to_glm(const aiMatrix4x4& m) {
    // Assimp's matrices are row-major, glm's column-major.
    return glm::dmat4(m.a1, m.b1, m.c1, m.d1, m.a2, m.b2, m.c2, m.d2, m.a3, m.b3, m.c3, m.d3, m.a4,
                      m.b4, m.c4, m.d4);
}

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The triangles of one aiMesh placed by `to_model`, each polygon cut as
// polygon.hpp says; zero-area and broken ones are skipped, and the
// broken ones, points and lines counted (ModelLeftOut).
class ModelBuilder {
  public:
    // With `plan`, each triangle's part and the vertex colours are kept too.
    ModelBuilder(bool use_normals, const MaterialPlan* plan)
        : use_normals_(use_normals), plan_(plan) {
        if (plan_) model_.parts = plan_->parts;
    }

    bool add(const aiMesh& mesh, unsigned mesh_index, const glm::dmat4& to_model, bool identity) {
        const auto first = static_cast<std::uint32_t>(model_.positions.size());
        if (model_.positions.size() + mesh.mNumVertices > kMaxModelTriangles) return false;
        const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(glm::dmat3(to_model)));
        const bool normals = use_normals_ && mesh.mNormals;
        const bool uvs = mesh.mTextureCoords[0] != nullptr;
        // Vertices and no face: a point cloud (OBJ's v lines alone, a PLY of vertices).
        if (mesh.mNumFaces == 0) model_.left_out.points += mesh.mNumVertices;
        // The first mesh with normals (or UVs) gives the earlier ones zeros:
        // corners without.
        if (normals && !has_normals_) model_.normals.assign(first, glm::vec3(0.0f));
        if (uvs && !has_uvs_) model_.uvs.assign(first, glm::vec2(0.0f));
        has_normals_ = has_normals_ || normals;
        has_uvs_ = has_uvs_ || uvs;
        if (plan_) add_colours(mesh, first);
        for (unsigned i = 0; i < mesh.mNumVertices; ++i) {
            const aiVector3D& v = mesh.mVertices[i];
            const glm::dvec3 p = identity ? glm::dvec3(v.x, v.y, v.z)
                                          : glm::dvec3(to_model * glm::dvec4(v.x, v.y, v.z, 1.0));
            model_.positions.emplace_back(p);
            if (has_normals_) {
                glm::vec3 n(0.0f);
                if (normals) {
                    const aiVector3D& s = mesh.mNormals[i];
                    n = identity ? glm::vec3(s.x, s.y, s.z)
                                 : glm::vec3(normal_matrix * glm::dvec3(s.x, s.y, s.z));
                    if (!finite(n)) n = glm::vec3(0.0f);
                }
                model_.normals.push_back(n);
            }
            if (has_uvs_) {
                glm::vec2 uv(0.0f);
                if (uvs) uv = {mesh.mTextureCoords[0][i].x, mesh.mTextureCoords[0][i].y};
                model_.uvs.push_back(uv);
            }
        }
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace& face = mesh.mFaces[f];
            if (!face.mIndices) continue;
            if (face.mNumIndices == 1) ++model_.left_out.points;
            if (face.mNumIndices == 2) ++model_.left_out.lines;
            for (const std::array<unsigned, 3>& t : polygon_triangles(face, mesh, first)) {
                const unsigned a = t[0], b = t[1], c = t[2];
                if (a >= mesh.mNumVertices || b >= mesh.mNumVertices || c >= mesh.mNumVertices) {
                    ++model_.left_out.out_of_range;
                    continue;
                }
                const std::size_t before = model_.triangles.size();
                add_triangle({first + a, first + b, first + c});
                if (plan_ && model_.triangles.size() > before)
                    model_.part_of.push_back(plan_->part(mesh_index, f));
                if (model_.triangles.size() > kMaxModelTriangles) return false;
            }
        }
        // No triangle names a corner that is not finite: it becomes a harmless zero.
        for (std::size_t i = first; i < model_.positions.size(); ++i)
            if (!finite(model_.positions[i])) model_.positions[i] = glm::vec3(0.0f);
        return true;
    }

    Model take() && {
        // A part has vertex colours when one of its triangles has them at every corner.
        if (!model_.colours.empty())
            for (std::size_t t = 0; t < model_.triangles.size(); ++t) {
                const auto& c = model_.triangles[t];
                if (model_.colours[c[0]].x != kNoVertexColour &&
                    model_.colours[c[1]].x != kNoVertexColour &&
                    model_.colours[c[2]].x != kNoVertexColour)
                    model_.parts[model_.part_of[t]].vertex_colours = true;
            }
        return std::move(model_);
    }
    ModelLeftOut& left_out() { return model_.left_out; }

  private:
    // The mesh's vertex colours (first set), clipped to [0, 1]; the first mesh
    // with colours gives the earlier ones none.
    void add_colours(const aiMesh& mesh, std::uint32_t first) {
        const aiColor4D* colours = plan_->vertex_colours ? mesh.mColors[0] : nullptr;
        if (colours && !has_colours_)
            model_.colours.assign(first, glm::vec3(kNoVertexColour, 0.0f, 0.0f));
        has_colours_ = has_colours_ || colours;
        if (!has_colours_) return;
        for (unsigned i = 0; i < mesh.mNumVertices; ++i) {
            glm::vec3 c(kNoVertexColour, 0.0f, 0.0f);
            if (colours) {
                const glm::vec3 read(colours[i].r, colours[i].g, colours[i].b);
                // NaN has no place in [0, 1]: such a corner has no colour.
                if (finite(read)) c = glm::clamp(read, 0.0f, 1.0f);
            }
            model_.colours.push_back(c);
        }
    }

    // A face's triangles as the mesh's vertex indices (polygon.hpp). A face
    // naming a corner the mesh does not have, or one at infinity or NaN, is
    // fanned: the triangles that can be used are kept, the others counted.
    // Both vectors are the builder's, so that a face costs no allocation.
    const std::vector<std::array<unsigned, 3>>& polygon_triangles(const aiFace& face,
                                                                  const aiMesh& mesh,
                                                                  std::uint32_t first) {
        std::vector<std::array<unsigned, 3>>& out = face_triangles_;
        std::vector<glm::dvec3>& corners = face_corners_;
        out.clear();
        corners.clear();
        const unsigned* index = face.mIndices;
        if (face.mNumIndices > 3) {
            for (unsigned k = 0; k < face.mNumIndices && index[k] < mesh.mNumVertices; ++k) {
                const glm::vec3& p = model_.positions[first + index[k]];
                if (!finite(p)) break;
                corners.emplace_back(p);
            }
        }
        if (corners.size() == face.mNumIndices) {
            for (const auto& t : triangulate_polygon(corners, ear_budget_))
                out.push_back({index[t[0]], index[t[1]], index[t[2]]});
            return out;
        }
        for (unsigned k = 2; k < face.mNumIndices; ++k)
            out.push_back({index[0], index[k - 1], index[k]});
        return out;
    }

    void add_triangle(const std::array<std::uint32_t, 3>& corners) {
        const glm::vec3 &a = model_.positions[corners[0]], &b = model_.positions[corners[1]],
                        &c = model_.positions[corners[2]];
        if (!finite(a) || !finite(b) || !finite(c)) {
            ++model_.left_out.not_finite;
            return;
        }
        const glm::dvec3 normal =
            glm::cross(glm::dvec3(b) - glm::dvec3(a), glm::dvec3(c) - glm::dvec3(a));
        if (normal == glm::dvec3(0.0)) return;  // zero area: skipped silently
        model_.triangles.push_back(corners);
    }

    std::vector<std::array<unsigned, 3>> face_triangles_;
    std::vector<glm::dvec3> face_corners_;
    std::uint64_t ear_budget_ = kEarClippingBudget;
    bool use_normals_;
    const MaterialPlan* plan_;
    bool has_normals_ = false, has_uvs_ = false, has_colours_ = false;
    Model model_;
};

std::string too_many() {
    return "the model has more than " + std::to_string(kMaxModelTriangles) +
           " triangles or vertices";
}

// Every mesh of every node, each placed by its node's transform and its
// parents'; an explicit stack, since a hostile file can nest nodes deeply.
//
// `declared_triangles`, when the file says how many it has (glTF), tells how
// many the reader dropped: those it gave fewer named corners out of range.
Expected<Model> gather(const aiScene& scene, bool use_normals, std::uint64_t declared_triangles,
                       const MaterialPlan* plan) {
    ModelBuilder builder(use_normals, plan);
    std::uint64_t read = 0;
    for (unsigned m = 0; m < scene.mNumMeshes; ++m)
        if (const aiMesh* mesh = scene.mMeshes[m])
            for (unsigned f = 0; f < mesh->mNumFaces; ++f)
                if (mesh->mFaces[f].mNumIndices >= 3) read += mesh->mFaces[f].mNumIndices - 2;
    if (declared_triangles > read) builder.left_out().out_of_range += declared_triangles - read;
    struct Pending {
        const aiNode* node;
        glm::dmat4 to_model;
    };
    std::vector<Pending> stack;
    if (scene.mRootNode) {
        stack.push_back({scene.mRootNode, to_glm(scene.mRootNode->mTransformation)});
    } else {
        for (unsigned m = 0; m < scene.mNumMeshes; ++m)
            if (scene.mMeshes[m] && !builder.add(*scene.mMeshes[m], m, glm::dmat4(1.0), true))
                return Error{too_many()};
    }
    std::size_t visited = 0;
    while (!stack.empty()) {
        const Pending at = stack.back();
        stack.pop_back();
        if (++visited > kMaxModelTriangles) return Error{"the model has too many nodes"};
        const bool identity = at.to_model == glm::dmat4(1.0);
        for (unsigned k = 0; k < at.node->mNumMeshes; ++k) {
            const unsigned m = at.node->mMeshes[k];
            if (m >= scene.mNumMeshes || !scene.mMeshes[m]) continue;
            if (!builder.add(*scene.mMeshes[m], m, at.to_model, identity)) return Error{too_many()};
        }
        for (unsigned c = at.node->mNumChildren; c-- > 0;) {
            const aiNode* child = at.node->mChildren[c];
            if (child) stack.push_back({child, at.to_model * to_glm(child->mTransformation)});
        }
    }
    return std::move(builder).take();
}

// Why the material libraries named `opened` were left out, as a phrase after
// the model's name, from `reason`, the import's failure in words: "refers to
// the material library 'a.mtl', which cannot be read (line 2, column 10 ...)".
// The model read without them, a line "of the file or of its material
// library" that ends early is the library's.
std::string library_fault(const std::string& reason, const std::vector<std::string>& opened) {
    std::string fault = "refers to the material library";
    for (std::size_t i = 0; i < opened.size(); ++i)
        fault.append(i == 0 ? " '" : " or '").append(opened[i]).append("'");
    fault.append(", which cannot be read (");
    constexpr std::string_view kLocated = "its material library '";
    if (reason.starts_with(kLocated)) {
        // "its material library 'a.mtl', line 2, ...": the name is said.
        const std::size_t after = reason.find("', ", kLocated.size());
        fault.append(after == std::string::npos ? reason : reason.substr(after + 3));
    } else if (reason.starts_with("a line of the file or of its material librar")) {
        fault.append("a line of it ends where a number was expected");
    } else {
        fault.append(reason);
    }
    return fault.append(")");
}

// read_model's work (jtracer/model_file.hpp): the checks in front of Assimp,
// Assimp's import, and the model gathered from what it read.
Expected<Model> import_model(const std::filesystem::path& file, const std::filesystem::path& folder,
                             bool file_materials, const ModelReaderHost& host) {
    std::error_code error;
    const auto status = std::filesystem::status(file, error);
    if (error || !std::filesystem::exists(status))
        return Error{"cannot read " + file_message(file, read_failure_reason(file, ENOENT))};
    if (!std::filesystem::is_regular_file(status))
        return Error{"cannot read " + file_message(file, "not a regular file")};
    const std::uintmax_t size = std::filesystem::file_size(file, error);
    if (error) return Error{"cannot read " + file_message(file, error.message())};
    if (size > kMaxModelFileBytes)
        return Error{file_message(file, "the model file is too large (" + std::to_string(size) +
                                            " bytes; at most " +
                                            std::to_string(kMaxModelFileBytes) + ")")};
    if (std::string problem = ply_header_problem(file, size); !problem.empty())
        return Error{file_message(file, problem)};
    if (std::string problem = off_header_problem(file, size); !problem.empty())
        return Error{file_message(file, problem)};
    std::uint64_t declared_triangles = 0, gltf_materials = 0;
    if (const std::string ext = lower_extension(file); ext == ".gltf" || ext == ".glb") {
        const Expected<std::vector<std::uint8_t>> bytes = read_file_bytes(file);
        if (!bytes) return bytes.error();
        const GltfCheck check = check_gltf(*bytes);
        if (!check.problem.empty()) return Error{file_message(file, check.problem)};
        declared_triangles = check.declared_triangles;
        gltf_materials = check.materials;
    }
    // The file's own bytes say more than Assimp's words for some failures
    // (model_reader/model_messages.hpp); read only when it failed.
    // The material libraries it read are named from the model's folder.
    auto library_name = [&](const std::filesystem::path& library) {
        // Absolute, as the io system opens them (a scene run from its own
        // folder names the model "ball.obj").
        std::error_code ignored;
        const std::filesystem::path name =
            library.lexically_relative(std::filesystem::absolute(file, ignored).parent_path())
                .lexically_normal();
        return name.empty() ? library.string() : name.generic_string();
    };
    auto failure_reason = [&](const std::string& reason,
                              const std::vector<std::filesystem::path>& opened) -> std::string {
        const Expected<std::vector<std::uint8_t>> bytes = read_file_bytes(file);
        if (!bytes) return reason;
        if (std::string wide = wide_text_problem(*bytes); !wide.empty()) return wide;
        std::vector<ReadAlongside> libraries;
        for (const std::filesystem::path& library : opened) {
            Expected<std::vector<std::uint8_t>> read = read_file_bytes(library);
            if (!read) continue;
            libraries.push_back({library_name(library), std::move(*read)});
        }
        return import_failure(reason, *bytes, libraries);
    };
    try {
        Assimp::Importer importer;
        leave_out_gltf1(importer);
        if (std::string problem =
                unread_format_problem(file_head(file), importer.IsExtensionSupported(".wrl"),
                                      importer.IsExtensionSupported(".m3d"));
            !problem.empty())
            return Error{file_message(file, problem)};
        auto* io = new ConfinedIOSystem(reference_folder(file, folder), file);
        importer.SetIOHandler(io);  // the importer owns it
        std::vector<std::pair<std::string, std::size_t>> said;
        // The scene read, or nullptr with Assimp's reason in `why`.
        auto read = [&](std::string& why) -> const aiScene* {
            const CerrCapture capture;
            // Absolute, as the io system takes every relative name from the
            // model's folder (model_reader/confined_io_system.hpp).
            const aiScene* got = importer.ReadFile(std::filesystem::absolute(file).string(), 0);
            said = capture.lines();
            if (got) return got;
            // Assimp turns every exception into its error string, running out
            // of memory too; that one is the programs' to report (error.hpp).
            why = importer.GetErrorString();
            if (why == std::bad_alloc().what()) throw std::bad_alloc();
            return nullptr;
        };
        std::string why;
        const aiScene* scene = read(why);
        std::string broken_library;  // why a material library was left out
        if (!scene) {
            // A refused file the model needed is the reason it failed.
            if (!io->refusal().empty()) return Error{file_message(file, "it " + io->refusal())};
            // Assimp's glTF reader drops faces whose indices are out of range,
            // and fails when that leaves a mesh none.
            if (declared_triangles > 0 && why.find("has no faces") != std::string::npos)
                return Error{file_message(
                    file, "none of its " + std::to_string(declared_triangles) +
                              " triangles can be read: they name corners the file does not "
                              "have (indices out of range)")};
            const std::vector<std::filesystem::path> opened = io->libraries();
            const std::string reason = failure_reason(why, opened);
            if (file_materials || opened.empty()) return Error{file_message(file, reason)};
            // The scene's materials need no material library: one that broke
            // the import is left out, the model read again without it, and
            // what was wrong with it becomes a warning (docs/language.md §13.5).
            io = new ConfinedIOSystem(reference_folder(file, folder), file);
            io->leave_out_libraries();
            importer.SetIOHandler(io);  // frees the first one
            // If it fails still, the model's own fault, which the library's hid.
            if (scene = read(why); !scene)
                return Error{file_message(file, failure_reason(why, {}))};
            std::vector<std::string> names;
            for (const std::filesystem::path& library : opened)
                names.push_back(library_name(library));
            broken_library = library_fault(reason, names);
        }
        std::optional<MaterialPlan> plan;
        if (file_materials) {
            Expected<MaterialPlan> planned =
                plan_materials(*scene, file, *io, gltf_materials, host);
            if (!planned) return Error{file_message(file, planned.error().message)};
            plan = std::move(*planned);
        }
        // STL's normals are one a facet, not a vertex (docs/language.md §13.5).
        Expected<Model> model = gather(*scene, lower_extension(file) != ".stl", declared_triangles,
                                       plan ? &*plan : nullptr);
        if (model) {
            model->left_out.refused_file = broken_library.empty() ? io->refusal() : broken_library;
            model->left_out.reader_said = std::move(said);
            if (plan) model->left_out.colours_not_read = plan->unread;
        }
        if (model && model->triangles.empty()) {
            // Text Assimp could not read shows as a model of nothing.
            const Expected<std::vector<std::uint8_t>> bytes = read_file_bytes(file);
            if (bytes)
                if (std::string wide = wide_text_problem(*bytes); !wide.empty())
                    return Error{file_message(file, wide)};
        }
        return model;
    } catch (const std::bad_alloc&) {
        throw;
    } catch (const std::exception& e) {
        return Error{file_message(file, std::string("cannot load the model: ") + e.what())};
    }
}

}  // namespace

}  // namespace jt

// The module's one entry point (io/model_reader.hpp).
extern "C" JT_MODEL_READER_EXPORT const jt::ModelReader* jt_model_reader() {
    static constexpr jt::ModelReader reader{jt::project_version.data(), jt::model_reader_layout(),
                                            jt::import_model};
    return &reader;
}
