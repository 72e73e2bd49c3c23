#pragma once
// The parts of a model read with its materials (docs/language.md §14.5): which
// part each face of each Assimp mesh belongs to, and each part's base colour
// and texture.
//
// OBJ: Assimp's meshes do not say which faces came before the first `usemtl`
// (it gives them a material of the library), and it invents a material for an
// unknown name; so the OBJ's own lines are scanned for the material of every
// face, and Kd and map_Kd are read from the libraries it opened, where it is
// known whether Kd was written at all. glTF: a primitive is a part with its
// material; one without a material is numbered after the file's materials.
// Other formats have no materials: every face is in the part without one.

#include "io/model_reader.hpp"
#include "jtracer/error.hpp"
#include "jtracer/model_file.hpp"
#include "model_reader/confined_io_system.hpp"

#include <assimp/scene.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace jt {

struct MaterialPlan {
    std::vector<ModelPart> parts;
    // For each Assimp mesh, the part of each of its faces (every face of a
    // glTF primitive or of a format without materials: one part).
    std::vector<std::vector<std::uint32_t>> face_parts;
    // Whether the format's vertex colours count: PLY's and OBJ's only, as the
    // language lists them.
    bool vertex_colours = false;
    // For a format whose colours are not read: what it holds that is left
    // unread ("textures and vertex colours"), or "".
    std::string unread;

    std::uint32_t part(unsigned mesh, unsigned face) const {
        const std::vector<std::uint32_t>& faces = face_parts[mesh];
        return faces.size() == 1 ? faces[0] : faces[face];
    }
};

// `gltf_materials`: how many materials a glTF file declares (else unused).
// Fails, in words to follow the model's name, when a material library the
// model names cannot be read or a texture cannot be decoded or lies outside
// the folder the model may read from. Textures are decoded by `host`'s.
Expected<MaterialPlan> plan_materials(const aiScene& scene, const std::filesystem::path& file,
                                      const ConfinedIOSystem& io, std::uint64_t gltf_materials,
                                      const ModelReaderHost& host);

}  // namespace jt
