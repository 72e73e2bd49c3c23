#include "jtracer/model_file.hpp"

#include <glm/common.hpp>

#include <limits>

namespace jt {

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
