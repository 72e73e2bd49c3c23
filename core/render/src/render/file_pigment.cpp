#include "render/file_pigment.hpp"

#include "render/pattern.hpp"

#include <glm/common.hpp>

namespace jt {

std::optional<Colour> file_pigment(const TriangleGeometry& g, TriangleId id, glm::dvec2 barycentric,
                                   glm::dvec2 uv) {
    if (id.instance == TriangleId::no_instance) return std::nullopt;
    const MeshInstance& instance = g.instances[id.instance];
    if (!instance.file_materials) return std::nullopt;
    const Model& m = *g.models[instance.model]->model;
    if (m.part_of.empty()) return std::nullopt;
    const ModelPart& part = m.parts[m.part_of[id.triangle]];
    bool coloured = false;
    Colour a(0.0), b(0.0), c(0.0);
    if (!m.colours.empty()) {
        const auto& corners = m.triangles[id.triangle];
        a = Colour(m.colours[corners[0]]);
        b = Colour(m.colours[corners[1]]);
        c = Colour(m.colours[corners[2]]);
        coloured = a.x != kNoVertexColour && b.x != kNoVertexColour && c.x != kNoVertexColour;
    }
    if (!part.has_material && !coloured) return std::nullopt;
    Colour pigment(1.0);
    if (part.texture) pigment = sample_bilinear(*part.texture, Uv{uv.x, uv.y});
    if (coloured) {
        const double w = 1.0 - barycentric.x - barycentric.y;
        pigment *= w * a + barycentric.x * b + barycentric.y * c;
    }
    if (part.has_material) pigment *= part.base;
    return pigment;
}

}  // namespace jt
