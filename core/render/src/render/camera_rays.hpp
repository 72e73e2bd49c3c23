#pragma once
// Primary rays of a perspective camera (docs/language.md §7).

#include "jtracer/scene.hpp"
#include "render/pixel_hash.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>
#include <optional>

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
    // The lens (docs/language.md §14.2): its radius, 0 for a pinhole, and the
    // distance along `forward` of the plane in focus.
    double aperture = 0.0;
    double focus_distance = 1.0;
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
    c.aperture = camera.aperture;
    c.focus_distance =
        camera.focus_distance.value_or(glm::length(camera.look_at - camera.position));
    return c;
}

// The unit direction through image point (x, y), in pixels from the bottom left
// corner: the centre of pixel (i, j) is (i + 0.5, j + 0.5).
inline Vec3 camera_direction(const CameraFrame& c, double x, double y) {
    double sx = (2.0 * x / c.width - 1.0) * c.tan_half_fov * c.aspect;
    double sy = (2.0 * y / c.height - 1.0) * c.tan_half_fov;
    return glm::normalize(c.forward + sx * c.right + sy * c.up);
}

struct LensRay {
    Vec3 origin{0.0};
    Vec3 direction{0.0, 0.0, -1.0};  // unit
};

// Sample k of `samples` of pixel (i, j) through a lens (docs/language.md
// §14.2), where `d` is camera_direction's pinhole direction for that sample:
// from a point of the lens toward where d meets the plane in focus. None when
// the sample sits at the lens centre (a pinhole camera, or k = 0): the ray is
// then exactly the pinhole's, from the camera's position along d.
inline std::optional<LensRay> lens_ray(const CameraFrame& c, const Vec3& d, int samples,
                                       std::uint32_t i, std::uint32_t j, std::uint32_t k) {
    const double rho = c.aperture * std::sqrt(static_cast<double>(k) / samples);
    if (!(rho != 0.0)) return std::nullopt;
    const Vec3 focus = c.position + d * (c.focus_distance / glm::dot(d, c.forward));
    // One turn of the spiral per pixel; 2048 keeps it apart from the light
    // disks' turns, which use the sample index (at most 1023) in its place.
    const double theta = k * kGoldenAngle + pixel_angle(i, j, 2048);
    LensRay ray;
    ray.origin = c.position + rho * (std::cos(theta) * c.right + std::sin(theta) * c.up);
    ray.direction = glm::normalize(focus - ray.origin);
    return ray;
}

}  // namespace jt
