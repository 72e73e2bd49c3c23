#include "invariants.hpp"

#include "jtracer/bmp.hpp"
#include "jtracer/diagnostics.hpp"
#include "jtracer/model_file.hpp"
#include "jtracer/parser.hpp"
#include "jtracer/serializer.hpp"
#include "jtracer/source_map.hpp"
#include "jtracer/source_serializer.hpp"
#include "jtracer/texture.hpp"
#include "jtracer/validate.hpp"

#include <unistd.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <new>
#include <optional>
#include <vector>

namespace jt::fuzz {

namespace {

// Byte length of each '\n'-separated line, as the lexer counts columns.
std::vector<std::size_t> line_lengths(std::string_view text) {
    std::vector<std::size_t> lengths;
    std::size_t start = 0;
    for (;;) {
        std::size_t nl = text.find('\n', start);
        if (nl == std::string_view::npos) {
            lengths.push_back(text.size() - start);
            return lengths;
        }
        lengths.push_back(nl - start);
        start = nl + 1;
    }
}

std::string describe(const Diagnostic& d) {
    return std::to_string(d.pos.line) + ":" + std::to_string(d.pos.column) + " '" + d.message + "'";
}

// The only files an `include` of a fuzz input reads: texts of the fuzzer's
// own, so that no input reads the disk, yet includes, cycles, unclosed blocks
// and names across files are all within reach of the dictionary.
const std::map<std::string, std::string, std::less<>>& fuzz_files() {
    static const std::map<std::string, std::string, std::less<>> files{
        {"defs.jts", "define r = 2;\nmaterial m { pigment: <1, 0, 0>; }\n"},
        {"ball.jts", "sphere { radius: r; material: m; }\n"},
        {"camera.jts", "perspective_camera { position: <0, 0, -5>; }\n"},
        {"open.jts", "sphere {\n"},
        {"self.jts", "include \"self.jts\";\n"},
        {"sub/twice.jts", "include \"../ball.jts\"; include \"../ball.jts\";\n"},
        // Not text: its error is located in it, past the first line.
        {"latin.jts", "define q = 1;\n# caf\xe9\n"},
        // Read again at every frame, the rest taken from the frame before.
        {"moving.jts", "sphere { radius: 1 + clock; }\npoint_light { radius: clock; }\n"},
    };
    return files;
}

Expected<IncludedText> read_fuzz_file(const std::string& path, std::uintmax_t) {
    const std::string name = std::filesystem::path(path).lexically_normal().generic_string();
    const auto found = fuzz_files().find(name);
    if (found == fuzz_files().end())
        return Error{"cannot read '" + name + "': the fuzzer reads only files of its own"};
    return IncludedText{"/fuzz/" + name, found->second};
}

std::string check_located(const std::vector<Diagnostic>& diagnostics, std::string_view main_text,
                          const char* stage, std::span<const SourceFile> files = {}) {
    for (const Diagnostic& d : diagnostics) {
        if (d.message.empty()) return std::string(stage) + ": empty message at " + describe(d);
        if (d.pos.line == 0) continue;
        if (d.pos.file > files.size())
            return std::string(stage) + ": diagnostic in no file at " + describe(d);
        const std::string_view text = file_text(files, main_text, d.pos.file);
        const std::vector<std::size_t> lengths = line_lengths(text);
        if (d.pos.line < 0 || static_cast<std::size_t>(d.pos.line) > lengths.size() ||
            d.pos.column < 1 ||
            static_cast<std::size_t>(d.pos.column) > lengths[d.pos.line - 1] + 1)
            return std::string(stage) + ": diagnostic outside the text at " + describe(d);
        std::string formatted = format_diagnostic(d, "fuzz.jts", main_text, files);
        const std::string_view name = file_name(files, "fuzz.jts", d.pos.file);
        if (!formatted.starts_with(std::string(name) + ":"))
            return std::string(stage) + ": badly formatted diagnostic " + formatted;
    }
    return {};
}

// A frame sequence's next frame, which takes the primitives that read no
// `clock` from the frame before (parser.hpp's EarlierParse), reads the scene
// a parse from scratch at its clock reads.
std::string check_frame_to_frame(std::string_view text, ParseOptions options) {
    options.source_map = false;
    options.record_primitive_readings = true;
    options.clock = 0.25;
    ParseResult first = parse_scene(text, options);
    if (!first.ok()) return {};
    EarlierParse earlier{std::string(text), first.source.files, std::move(first.scene.primitives),
                         std::move(first.primitive_readings)};
    options.clock = 0.75;
    ParseResult scratch = parse_scene(text, options);
    options.earlier = &earlier;
    ParseResult next = parse_scene(text, options);
    if (scratch.ok() != next.ok())
        return "frame to frame: the next frame parses " + std::string(next.ok() ? "" : "not ") +
               "where a parse from scratch does " + std::string(scratch.ok() ? "" : "not");
    if (scratch.ok() && !(next.scene == scratch.scene))
        return "frame to frame: the next frame's scene differs from a parse from scratch";
    return {};
}

}  // namespace

std::string check_diagnostics_within(const std::vector<Diagnostic>& diagnostics,
                                     std::string_view text) {
    return check_located(diagnostics, text, "diagnostics");
}

std::string check_scene_text(std::string_view text) {
    ParseOptions options;
    options.read_include = read_fuzz_file;
    ParseResult parsed = parse_scene(text, options);
    const std::span<const SourceFile> files = parsed.source.files;
    if (std::string e = check_located(parsed.diagnostics, text, "parse", files); !e.empty())
        return e;
    // Runs of plain properties, read without tokens for their names, read as
    // the tokens read them: the same scene, records and messages.
    ParseOptions by_tokens = options;
    by_tokens.plain_properties = false;
    const ParseResult tokens = parse_scene(text, by_tokens);
    if (!(tokens.scene == parsed.scene) || !(tokens.source == parsed.source) ||
        tokens.diagnostics != parsed.diagnostics)
        return "parse: the plain properties' reading differs from the tokens'";
    if (!parsed.ok()) return {};
    std::vector<Diagnostic> checks = validate_scene(parsed.scene, parsed.source);
    if (std::string e = check_located(checks, text, "validate", files); !e.empty()) return e;
    // A parsed scene's values were checked by the parser: the checks that take
    // them as parsed find the same.
    if (validate_scene(parsed.scene, parsed.source, {.primitives_as_parsed = true}) != checks)
        return "validate: taking the primitives as parsed finds other diagnostics";

    const std::string canonical = serialize_scene(parsed.scene);
    ParseResult reparsed = parse_scene(canonical);
    if (!reparsed.ok()) {
        std::string first = reparsed.diagnostics.empty() ? "" : describe(reparsed.diagnostics[0]);
        return "round trip: the serialized scene does not parse: " + first + "\n" + canonical;
    }
    if (!(reparsed.scene == parsed.scene))
        return "round trip: the reparsed scene differs\n" + canonical;
    if (serialize_scene(reparsed.scene) != canonical)
        return "round trip: serializing twice gives different text\n" + canonical;

    // The same, keeping the text's names and expressions.
    const std::string kept = serialize_scene(parsed.scene, {text, parsed});
    // It may keep the text's includes: read them as the text's were.
    ParseResult kept_parsed = parse_scene(kept, options);
    if (!kept_parsed.ok()) {
        std::string first =
            kept_parsed.diagnostics.empty() ? "" : describe(kept_parsed.diagnostics[0]);
        return "source round trip: the serialized scene does not parse: " + first + "\n" + kept;
    }
    if (!(kept_parsed.scene == parsed.scene))
        return "source round trip: the reparsed scene differs\n" + kept;
    if (serialize_scene(kept_parsed.scene, {kept, kept_parsed}) != kept)
        return "source round trip: serializing twice gives different text\n" + kept;
    return check_frame_to_frame(text, options);
}

std::string check_bmp_bytes(std::span<const std::uint8_t> bytes) {
    const Expected<Image8> decoded = decode_bmp(bytes);
    if (!decoded) return {};
    const Image8& image = *decoded;
    if (image.width <= 0 || image.height <= 0 ||
        image.rgb.size() != static_cast<std::size_t>(image.width) * image.height * 3)
        return "decoded image has inconsistent size " + std::to_string(image.width) + "x" +
               std::to_string(image.height);
    const Expected<Image8> again = decode_bmp(encode_bmp(image));
    if (!again) return "re-encoded image does not decode: " + again.error().message;
    if (!(*again == image)) return "re-encoded image decodes to different pixels";
    return {};
}

std::string check_texture_bytes(std::span<const std::uint8_t> bytes) {
    const Expected<Texture> decoded = decode_texture(bytes);
    if (!decoded) return decoded.error().message.empty() ? "an error without a message" : "";
    const Texture& t = *decoded;
    const auto texels = static_cast<std::int64_t>(t.width) * t.height;
    const std::size_t values = t.rgb16.empty() ? t.rgb8.size() : t.rgb16.size();
    if (t.width <= 0 || t.height <= 0 || texels > kMaxTextureTexels ||
        values != static_cast<std::size_t>(texels) * 3 || (!t.rgb8.empty() && !t.rgb16.empty()))
        return "decoded texture has inconsistent size " + std::to_string(t.width) + "x" +
               std::to_string(t.height) + " with " + std::to_string(values) + " values";
    return {};
}

namespace {

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::string check_model(const Model& m) {
    const std::size_t vertices = m.positions.size();
    if (vertices > kMaxModelTriangles || m.triangles.size() > kMaxModelTriangles)
        return "a model over the size cap: " + std::to_string(vertices) + " vertices, " +
               std::to_string(m.triangles.size()) + " triangles";
    if (!m.normals.empty() && m.normals.size() != vertices)
        return "normals not parallel to positions";
    if (!m.uvs.empty() && m.uvs.size() != vertices) return "uvs not parallel to positions";
    for (const glm::vec3& p : m.positions)
        if (!finite(p)) return "a position that is not finite";
    for (const auto& t : m.triangles) {
        for (std::uint32_t i : t)
            if (i >= vertices)
                return "a triangle naming vertex " + std::to_string(i) + " of " +
                       std::to_string(vertices);
        const glm::dvec3 a(m.positions[t[0]]), b(m.positions[t[1]]), c(m.positions[t[2]]);
        if (glm::cross(b - a, c - a) == glm::dvec3(0.0)) return "a triangle of zero area";
    }
    // Read with its materials (docs/language.md §14.5).
    if (!m.colours.empty() && m.colours.size() != vertices)
        return "vertex colours not parallel to positions";
    for (const glm::vec3& c : m.colours)
        if (c.x != kNoVertexColour && !(c.x >= 0.0f && c.x <= 1.0f && c.y >= 0.0f && c.y <= 1.0f &&
                                        c.z >= 0.0f && c.z <= 1.0f))
            return "a vertex colour outside [0, 1]";
    if (!m.part_of.empty() && m.part_of.size() != m.triangles.size())
        return "parts not parallel to triangles";
    for (const std::uint32_t part : m.part_of)
        if (part >= m.parts.size()) return "a triangle in a part the model does not list";
    for (const ModelPart& part : m.parts)
        if (!std::isfinite(part.base.x) || !std::isfinite(part.base.y) ||
            !std::isfinite(part.base.z))
            return "a part's base colour that is not finite";
    return {};
}

}  // namespace

std::string check_model_bytes(std::span<const std::uint8_t> bytes) {
    if (bytes.empty()) return {};
    namespace fs = std::filesystem;
    // A folder of its own for every input: what the file refers to can only be
    // itself or nothing.
    static int inputs = 0;
    const fs::path folder =
        fs::temp_directory_path() /
        ("jtracer-model-check-" + std::to_string(::getpid()) + "-" + std::to_string(++inputs));
    fs::create_directories(folder);
    const fs::path file =
        folder / (std::string("model.") + model_extensions[bytes[0] % model_extensions.size()]);
    std::ofstream(file, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data() + 1),
               static_cast<std::streamsize>(bytes.size() - 1));
    // Read as a mesh reads it, then with its materials (materials: "file").
    std::string broken;
    for (const bool file_materials : {false, true}) {
        std::optional<Expected<Model>> attempt;
        try {
            attempt = read_model(file, folder, file_materials);
        } catch (const std::bad_alloc&) {
            // Out of memory for what the file claims: the programs report that
            // and exit 3 (tests/hardening checks them under ulimit -v).
        }
        if (!attempt) continue;
        const Expected<Model>& read = *attempt;
        if (!read)
            broken = read.error().message.empty() ? "an error without a message" : "";
        else
            broken = check_model(*read);
        if (!broken.empty()) break;
    }
    fs::remove_all(folder);
    return broken;
}

void abort_if_broken(const std::string& broken) {
    if (broken.empty()) return;
    std::fprintf(stderr, "invariant broken: %s\n", broken.c_str());
    std::abort();
}

}  // namespace jt::fuzz
