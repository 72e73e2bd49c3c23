#include "model_reader/gltf_rules.hpp"

#include <nlohmann/json.hpp>

#include <cstring>
#include <optional>
#include <string_view>

namespace jt {

namespace {

using nlohmann::json;

// A .glb file: a 12-byte header ("glTF", version, length), then chunks of
// (length, type, data): the JSON chunk first, then the binary one.
constexpr std::uint32_t kGlbMagic = 0x46546C67;       // "glTF"
constexpr std::uint32_t kJsonChunkType = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kBinChunkType = 0x004E4942;   // "BIN\0"

std::uint32_t read_u32(std::span<const std::uint8_t> bytes, std::size_t at) {
    std::uint32_t value = 0;
    for (int i = 3; i >= 0; --i) value = (value << 8) | bytes[at + static_cast<std::size_t>(i)];
    return value;
}

struct GltfText {
    std::string_view json;
    std::optional<std::uint64_t> bin_chunk_bytes;  // a .glb's binary chunk
};

std::optional<GltfText> gltf_text(std::span<const std::uint8_t> bytes) {
    const auto as_text = [](std::span<const std::uint8_t> part) {
        return std::string_view(reinterpret_cast<const char*>(part.data()), part.size());
    };
    if (bytes.size() >= 20 && read_u32(bytes, 0) == kGlbMagic) {
        const std::uint64_t json_bytes = read_u32(bytes, 12);
        if (read_u32(bytes, 16) != kJsonChunkType || 20 + json_bytes > bytes.size())
            return std::nullopt;
        GltfText text{as_text(bytes.subspan(20, json_bytes)), std::nullopt};
        const std::uint64_t bin_at = 20 + ((json_bytes + 3) & ~std::uint64_t{3});
        if (bin_at + 8 <= bytes.size() && read_u32(bytes, bin_at + 4) == kBinChunkType)
            text.bin_chunk_bytes = read_u32(bytes, bin_at);
        return text;
    }
    const std::string_view text = as_text(bytes);
    const std::size_t first = text.find_first_not_of(" \t\r\n\xEF\xBB\xBF");
    if (first == std::string_view::npos || text[first] != '{') return std::nullopt;
    return GltfText{text, std::nullopt};
}

// A non-negative integer member (or `fallback` when absent); nullopt when it
// is something else.
std::optional<std::uint64_t> whole(const json& object, const char* key, std::uint64_t fallback) {
    const auto it = object.find(key);
    if (it == object.end()) return fallback;
    if (!it->is_number_unsigned()) return std::nullopt;
    return it->get<std::uint64_t>();
}

std::uint64_t component_bytes(std::uint64_t component_type) {
    switch (component_type) {
        case 5120:
        case 5121:
            return 1;  // byte, unsigned byte
        case 5122:
        case 5123:
            return 2;  // short, unsigned short
        case 5125:
        case 5126:
            return 4;  // unsigned int, float
        default:
            return 0;
    }
}

std::uint64_t components(const json& type) {
    if (!type.is_string()) return 0;
    const std::string& name = type.get_ref<const std::string&>();
    if (name == "SCALAR") return 1;
    if (name == "VEC2") return 2;
    if (name == "VEC3") return 3;
    if (name == "VEC4" || name == "MAT2") return 4;
    if (name == "MAT3") return 9;
    if (name == "MAT4") return 16;
    return 0;
}

// Whether `count` elements of `size` bytes, `stride` apart from `offset`,
// end within `length` bytes (in long double, so that no claim overflows).
bool fits(std::uint64_t offset, std::uint64_t count, std::uint64_t stride, std::uint64_t size,
          std::uint64_t length) {
    if (count == 0) return offset <= length;
    const long double end = static_cast<long double>(offset) +
                            static_cast<long double>(count - 1) * static_cast<long double>(stride) +
                            static_cast<long double>(size);
    return end <= static_cast<long double>(length);
}

struct View {
    std::uint64_t length = 0;
    std::uint64_t stride = 0;  // 0: tightly packed
};

std::string views_problem(const json& root, std::optional<std::uint64_t> bin_chunk_bytes,
                          std::vector<View>& views) {
    std::vector<std::uint64_t> buffers;
    if (const auto it = root.find("buffers"); it != root.end() && it->is_array()) {
        for (std::size_t i = 0; i < it->size(); ++i) {
            const json& buffer = (*it)[i];
            const auto bytes = buffer.is_object() ? whole(buffer, "byteLength", 0) : std::nullopt;
            if (!bytes) return "its glTF buffer " + std::to_string(i) + " has no byte length";
            if (i == 0 && bin_chunk_bytes && !buffer.contains("uri") && *bytes > *bin_chunk_bytes)
                return "its glTF buffer 0 claims " + std::to_string(*bytes) +
                       " bytes, more than the binary chunk's " + std::to_string(*bin_chunk_bytes);
            buffers.push_back(*bytes);
        }
    }
    if (const auto it = root.find("bufferViews"); it != root.end() && it->is_array()) {
        for (std::size_t i = 0; i < it->size(); ++i) {
            const json& view = (*it)[i];
            const std::string name = "its glTF buffer view " + std::to_string(i);
            if (!view.is_object()) return name + " is not an object";
            const auto buffer = whole(view, "buffer", buffers.size());
            const auto offset = whole(view, "byteOffset", 0);
            const auto length = whole(view, "byteLength", 0);
            const auto stride = whole(view, "byteStride", 0);
            if (!buffer || *buffer >= buffers.size()) return name + " names no buffer of the file";
            if (!offset || !length || !stride) return name + " has a byte count that is no count";
            if (!fits(*offset, 1, 0, *length, buffers[*buffer]))
                return name + " takes bytes " + std::to_string(*offset) + " to " +
                       std::to_string(*offset + *length) + " of buffer " + std::to_string(*buffer) +
                       ", which holds " + std::to_string(buffers[*buffer]);
            views.push_back({*length, *stride});
        }
    }
    return "";
}

// Where `count` elements of `size` bytes lie in view `view` from `offset`, or
// what is wrong with them (`what` names them).
std::string span_problem(const std::string& what, const std::vector<View>& views,
                         std::optional<std::uint64_t> view, std::optional<std::uint64_t> offset,
                         std::uint64_t count, std::uint64_t size, bool strided) {
    if (!view || *view >= views.size()) return what + " names no buffer view of the file";
    if (!offset) return what + " has a byte offset that is no count";
    const View& v = views[*view];
    const std::uint64_t stride = strided && v.stride != 0 ? v.stride : size;
    if (fits(*offset, count, stride, size, v.length)) return "";
    return what + " would read " + std::to_string(count) + " elements of " + std::to_string(size) +
           " bytes from byte " + std::to_string(*offset) + " of buffer view " +
           std::to_string(*view) + ", which holds " + std::to_string(v.length);
}

std::string accessor_problem(const json& accessor, std::size_t index,
                             const std::vector<View>& views) {
    const std::string name = "its glTF accessor " + std::to_string(index);
    if (!accessor.is_object()) return name + " is not an object";
    const auto count = whole(accessor, "count", 0);
    const auto type = whole(accessor, "componentType", 0);
    if (!count || !type) return name + " has a count or component type that is no count";
    const std::uint64_t size = component_bytes(*type) * components(accessor.value("type", json()));
    if (size == 0) return name + " has an unknown component type or type";
    if (accessor.contains("bufferView")) {
        if (auto problem = span_problem(name, views, whole(accessor, "bufferView", 0),
                                        whole(accessor, "byteOffset", 0), *count, size, true);
            !problem.empty())
            return problem;
    }
    const auto sparse = accessor.find("sparse");
    if (sparse == accessor.end()) return "";
    if (!sparse->is_object()) return name + "'s sparse part is not an object";
    const auto sparse_count = whole(*sparse, "count", 0);
    const json& indices = sparse->value("indices", json::object());
    const json& values = sparse->value("values", json::object());
    if (!sparse_count || !indices.is_object() || !values.is_object())
        return name + "'s sparse part is malformed";
    const auto index_type = whole(indices, "componentType", 0);
    const std::uint64_t index_size = index_type ? component_bytes(*index_type) : 0;
    if (index_size == 0) return name + "'s sparse indices have an unknown component type";
    if (auto problem = span_problem(
            name + "'s sparse indices", views, whole(indices, "bufferView", views.size()),
            whole(indices, "byteOffset", 0), *sparse_count, index_size, false);
        !problem.empty())
        return problem;
    return span_problem(name + "'s sparse values", views, whole(values, "bufferView", views.size()),
                        whole(values, "byteOffset", 0), *sparse_count, size, false);
}

// nlohmann's own words for a parse error, without its exception's prefix or
// the bytes it last read (which need not be printable).
std::string parse_error_message(const json::parse_error& error) {
    std::string message = error.what();
    constexpr std::string_view kPrefix = "parse error at ";
    if (const std::size_t at = message.find(kPrefix); at != std::string::npos)
        message.erase(0, at + kPrefix.size());
    if (const std::size_t at = message.find("; last read:"); at != std::string::npos)
        message.erase(at);
    return message;
}

std::string skins_problem(const json& root) {
    const auto it = root.find("skins");
    if (it == root.end() || !it->is_array()) return "";
    for (std::size_t i = 0; i < it->size(); ++i)
        if (!(*it)[i].is_object() || !(*it)[i].contains("inverseBindMatrices"))
            return "its glTF skin " + std::to_string(i) +
                   " has no inverseBindMatrices (glTF allows that, but the model reader, Assimp "
                   "5.2, fails on it)";
    return "";
}

// The version a glTF file's asset gives, as written ("2.0", 1, ...), or ""
// when it gives none.
std::string asset_version(const json& root) {
    const auto asset = root.find("asset");
    if (asset == root.end() || !asset->is_object()) return "";
    const auto version = asset->find("version");
    if (version == asset->end()) return "";
    return version->is_string() ? version->get<std::string>() : version->dump();
}

std::string not_gltf2(const std::string& what) {
    return "it is " + what + ", which is not read: only glTF 2.0 is (convert the file to glTF 2.0)";
}

// The triangles a primitive of `mode` makes of `count` corners (glTF 2.0
// §3.7.2.1); 0 for points and lines.
std::uint64_t primitive_triangles(std::uint64_t mode, std::uint64_t count) {
    if (mode == 4) return count / 3;
    if (mode == 5 || mode == 6) return count > 2 ? count - 2 : 0;
    return 0;
}

std::uint64_t declared_triangles(const json& root) {
    const auto meshes = root.find("meshes");
    const auto accessors = root.find("accessors");
    if (meshes == root.end() || !meshes->is_array() || accessors == root.end() ||
        !accessors->is_array())
        return 0;
    auto accessor_count = [&](std::optional<std::uint64_t> index) -> std::uint64_t {
        if (!index || *index >= accessors->size()) return 0;
        return whole((*accessors)[*index], "count", 0).value_or(0);
    };
    std::uint64_t triangles = 0;
    for (const json& mesh : *meshes) {
        if (!mesh.is_object()) continue;
        const json& primitives = mesh.value("primitives", json::array());
        if (!primitives.is_array()) continue;
        for (const json& primitive : primitives) {
            if (!primitive.is_object()) continue;
            const std::uint64_t mode = whole(primitive, "mode", 4).value_or(0);
            std::uint64_t count = 0;
            if (primitive.contains("indices")) {
                count = accessor_count(whole(primitive, "indices", 0));
            } else {
                const json& attributes = primitive.value("attributes", json::object());
                if (attributes.is_object())
                    count = accessor_count(whole(attributes, "POSITION", accessors->size()));
            }
            triangles += primitive_triangles(mode, count);
        }
    }
    return triangles;
}

std::string gltf2_problem(const json& root, std::optional<std::uint64_t> bin_chunk_bytes) {
    std::vector<View> views;
    if (std::string problem = views_problem(root, bin_chunk_bytes, views); !problem.empty())
        return problem;
    if (const auto it = root.find("accessors"); it != root.end() && it->is_array())
        for (std::size_t i = 0; i < it->size(); ++i)
            if (std::string problem = accessor_problem((*it)[i], i, views); !problem.empty())
                return problem;
    return skins_problem(root);
}

}  // namespace

GltfCheck check_gltf(std::span<const std::uint8_t> bytes) {
    if (bytes.size() >= 8 && read_u32(bytes, 0) == kGlbMagic && read_u32(bytes, 4) != 2)
        return {not_gltf2("binary glTF version " + std::to_string(read_u32(bytes, 4)) + " (.glb)"),
                0, 0};
    const std::optional<GltfText> text = gltf_text(bytes);
    if (!text) return {};
    json root;
    try {
        root = json::parse(text->json);
    } catch (const json::parse_error& error) {
        return {"its glTF JSON does not parse: " + parse_error_message(error), 0, 0};
    }
    if (!root.is_object()) return {};
    const std::string version = asset_version(root);
    if (version.empty()) return {};
    if (version.rfind("2.", 0) != 0) return {not_gltf2("glTF " + version), 0, 0};
    const auto materials = root.find("materials");
    return {gltf2_problem(root, text->bin_chunk_bytes), declared_triangles(root),
            materials != root.end() && materials->is_array() ? materials->size() : 0};
}

}  // namespace jt
