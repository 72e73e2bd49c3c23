#include "jtracer/model_file.hpp"

#include "io/model_reader.hpp"

#include <glm/common.hpp>

#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace jt {

namespace {

// A model's textures as stored, whatever a JPEG's EXIF orientation says
// (TextureLayout): the module never chooses.
Expected<std::shared_ptr<const Texture>> model_texture_file(const std::filesystem::path& path) {
    return load_texture(path, TextureLayout::as_stored);
}

Expected<Texture> model_texture_bytes(std::span<const std::uint8_t> bytes) {
    return decode_texture(bytes, TextureLayout::as_stored);
}

}  // namespace

Expected<Model> read_model(const std::filesystem::path& file, const std::filesystem::path& folder,
                           bool file_materials) {
    const Expected<const ModelReader*> reader = model_reader();
    if (!reader) return reader.error();
    static constexpr ModelReaderHost host{model_texture_file, model_texture_bytes};
    return (*reader)->read(file, folder, file_materials, host);
}

namespace {

// "1 point", "2 points"; "1 names", "2 name".
std::string count_of(std::size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

}  // namespace

std::vector<std::string> model_warnings(const Model& model) {
    std::vector<std::string> warnings;
    const ModelLeftOut& out = model.left_out;
    if (!out.refused_file.empty()) warnings.push_back(out.refused_file + ": that file is left out");
    if (!out.colours_not_read.empty())
        warnings.push_back("holds " + out.colours_not_read +
                           " that materials: \"file\" does not read (it reads OBJ, glTF and "
                           "PLY files): every triangle takes the mesh's material");
    for (const auto& [line, times] : out.reader_said) {
        // Appended, not chained from a literal: GCC 12 warns falsely (-Wrestrict).
        std::string said("made the model reader (Assimp) print '");
        said.append(line).append("'");
        if (times > 1) said.append(" ").append(std::to_string(times)).append(" times");
        warnings.push_back(std::move(said));
    }
    // Why triangles were dropped: "2 name a corner ..., 1 has a corner ...".
    std::string why;
    if (out.out_of_range > 0)
        why = count_of(out.out_of_range, "names", "name") +
              " a corner the file does not have (an index out of range)";
    if (out.not_finite > 0) {
        if (!why.empty()) why += ", ";
        why += count_of(out.not_finite, "has", "have") + " a corner at infinity or NaN";
    }
    const std::size_t broken = out.out_of_range + out.not_finite;
    if (!model.triangles.empty()) {
        if (broken > 0)
            warnings.push_back("has " + std::to_string(broken) + " of its " +
                               std::to_string(broken + model.triangles.size()) +
                               " triangles left out: " + why);
        return warnings;
    }
    if (broken > 0) {
        warnings.push_back("holds no usable triangle (" + why + "): the mesh is left out");
    } else if (out.points > 0 || out.lines > 0) {
        std::string held;
        if (out.points > 0) held = count_of(out.points, "point", "points");
        if (out.points > 0 && out.lines > 0) held += " and ";
        if (out.lines > 0) held += count_of(out.lines, "line", "lines");
        warnings.push_back("holds only " + held + ", no triangle: the mesh is left out");
    } else {
        warnings.push_back("holds no triangle of non-zero area: the mesh is left out");
    }
    return warnings;
}

ModelBox model_box(const Model& model) {
    ModelBox box{glm::dvec3(std::numeric_limits<double>::infinity()),
                 glm::dvec3(-std::numeric_limits<double>::infinity())};
    for (const auto& triangle : model.triangles)
        for (const std::uint32_t corner : triangle) {
            box.lower = glm::min(box.lower, glm::dvec3(model.positions[corner]));
            box.upper = glm::max(box.upper, glm::dvec3(model.positions[corner]));
        }
    return box;
}

}  // namespace jt
