#pragma once
// Primary rays of a perspective camera (docs/language.md §7).

#include "jtracer/scene.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

namespace jt {

struct CameraFrame {
    Vec3 position{0.0};
    Vec3 forward{0.0, 0.0, -1.0};
    Vec3 right{1.0, 0.0, 0.0};
    Vec3 up{0.0, 1.0, 0.0};
    double tan_half_fov = 1.0;
    double aspect = 1.0;
    int width = 1;
    int height = 1;
};

inline CameraFrame camera_frame(const Camera& camera, int width, int height) {
    CameraFrame c;
    c.position = camera.position;
    c.forward = glm::normalize(camera.look_at - camera.position);
    c.right = glm::normalize(glm::cross(c.forward, camera.up));
    c.up = glm::cross(c.right, c.forward);
    c.tan_half_fov = std::tan(camera.fov * 0.5 * std::numbers::pi / 180.0);
    c.aspect = camera.aspect;
    c.width = width;
    c.height = height;
    return c;
}

// The unit direction through image point (x, y), in pixels from the bottom left
// corner: the centre of pixel (i, j) is (i + 0.5, j + 0.5).
inline Vec3 camera_direction(const CameraFrame& c, double x, double y) {
    double sx = (2.0 * x / c.width - 1.0) * c.tan_half_fov * c.aspect;
    double sy = (2.0 * y / c.height - 1.0) * c.tan_half_fov;
    return glm::normalize(c.forward + sx * c.right + sy * c.up);
}

}  // namespace jt
