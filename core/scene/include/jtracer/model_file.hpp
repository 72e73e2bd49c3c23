#pragma once
// Triangle models read from files for `mesh` (docs/language.md §13.5): OBJ,
// PLY, STL, glTF 2.0 and anything else Assimp reads, reduced to what the
// renderer uses: corner positions, the file's vertex normals and first set of
// texture coordinates, and triangles fanned from each polygon's first vertex.
//
//   Expected<Model> model = read_model("scenes/models/bunny.ply", "scenes");
//   if (!model) report(model.error().message);
//
// read_model is the one entry point that touches the file: a pure function of
// the files it names. shared_model (model_cache.hpp) loads each file once.

#include "jtracer/error.hpp"
#include "jtracer/texture.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace jt {

// What a file holds that its model leaves out, for the warning at the mesh's
// `file` string (model_warnings). Zero-area triangles are not counted: the
// language skips them silently (docs/language.md §13.5).
struct ModelLeftOut {
    std::size_t points = 0, lines = 0;  // faces of one and of two corners
    std::size_t out_of_range = 0;       // triangles naming a corner the file does not have
    std::size_t not_finite = 0;         // triangles with a corner at infinity or NaN
    std::string refused_file;           // why a file it refers to was not opened, or ""
    // What the model reader printed while it read the file (Assimp's OpenGEX
    // reader writes to stderr), each line once with how often it came.
    std::vector<std::pair<std::string, std::size_t>> reader_said;
    // With materials "file", what a format whose colours are not read (not
    // OBJ, glTF or PLY) holds all the same: "textures", ..., or "".
    std::string colours_not_read;
};

// One part of a model read with its materials (docs/language.md §14.5): the
// faces of one OBJ material (`usemtl`) or of one glTF material, or the faces
// with none (before any `usemtl`, after an unknown name, a glTF primitive
// without a material, every face of a format without materials).
struct ModelPart {
    std::string name;           // the material's name; "" for the faces with none
    bool has_material = false;  // then `base` applies (1 when the file gives no colour)
    Colour base{1.0};           // OBJ Kd, glTF baseColorFactor's r, g, b
    // How the file names its texture ("" for none; "embedded image 2" for one
    // inside the file) and the picture, decoded as image_map's are.
    std::string texture_name;
    std::shared_ptr<const Texture> texture;
    bool vertex_colours = false;  // some triangle of it has a colour at all three corners
    bool operator==(const ModelPart&) const = default;
};

// A corner's colour when the file gives it none (`Model::colours`).
inline constexpr float kNoVertexColour = -1.0f;

// A model's object space is the file's coordinates after its own node
// transforms (glTF). Vertex positions are single precision, as every model
// format stores them; the renderer refines hits on them in double. Every one
// is finite: a corner the file gives as infinite or NaN is zero, and no
// triangle names it.
struct Model {
    std::vector<glm::vec3> positions;
    // Parallel to positions, or empty when the file has none; a zero vector is
    // a corner without a normal. STL's facet normals are not vertex normals.
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs;  // parallel to positions, or empty
    // Counter-clockwise seen from the front; none of zero area.
    std::vector<std::array<std::uint32_t, 3>> triangles;
    // Read only with the file's materials (read_model's `file_materials`),
    // else all three are empty. Colours are parallel to positions (or empty
    // when the file has none), clipped to [0, 1]; a corner without one has
    // kNoVertexColour in x. part_of is parallel to triangles, an index into
    // parts; parts lists each material used once, in the order first used.
    std::vector<glm::vec3> colours;
    std::vector<ModelPart> parts;
    std::vector<std::uint32_t> part_of;
    ModelLeftOut left_out;
};

// Files larger than this are refused before any is read (the model file and
// every file it refers to, each).
inline constexpr std::uintmax_t kMaxModelFileBytes = std::uintmax_t{1} << 29;  // 512 MiB
// Models with more triangles or vertices than this are refused.
inline constexpr std::size_t kMaxModelTriangles = std::size_t{1} << 26;

// Reads every triangle of `file`. Files it refers to (glTF buffers, OBJ
// material libraries) are opened only inside `folder` (the scene's folder)
// or, for a model outside it, inside the model's own folder; one outside it
// is never opened: an error when the model cannot be read without it (a glTF
// buffer), else it is left out (an OBJ's material library) and
// left_out.refused_file says so. A model with no triangle of non-zero area is
// not an error: its triangle list is empty. Running out of memory raises
// std::bad_alloc, as everywhere (error.hpp).
//
// With `file_materials` (a mesh's `materials: "file"`), it also reads each
// part's colour and texture and the vertex colours; then a material library
// or texture that cannot be read is an error, and textures are confined as
// buffers are. Without, the file's materials are never looked at.
Expected<Model> read_model(const std::filesystem::path& file, const std::filesystem::path& folder,
                           bool file_materials = false);

// The warnings a mesh of `model` gets, each to follow the file's name: what
// the file held that is left out, and when no triangle is left, that the mesh
// is left out and why ("holds only points (8): the mesh is left out").
std::vector<std::string> model_warnings(const Model& model);

// The box around the corners the model's triangles name, in its own space;
// empty (lower > upper) when it has no triangle.
struct ModelBox {
    glm::dvec3 lower, upper;
    bool empty() const { return lower.x > upper.x; }
};
ModelBox model_box(const Model& model);

}  // namespace jt
