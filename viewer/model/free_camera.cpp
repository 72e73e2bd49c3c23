#include "model/free_camera.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace jt::view {

namespace {

constexpr double pi = 3.14159265358979323846;

// Rodrigues' rotation of v about the unit axis k by `angle` radians.
Vec3 rotate(const Vec3& v, const Vec3& k, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    return v * c + glm::cross(k, v) * s + k * glm::dot(k, v) * (1.0 - c);
}

Vec3 safe_normalize(const Vec3& v, const Vec3& fallback) {
    const double len = glm::length(v);
    return len > 1e-12 && std::isfinite(len) ? v / len : fallback;
}

}  // namespace

FreeCamera free_camera_from(const Camera& camera) {
    FreeCamera free;
    free.position = camera.position;
    free.look_at = camera.look_at;
    free.up = safe_normalize(camera.up, Vec3(0, 1, 0));
    free.aspect = camera.aspect;
    free.fov = camera.fov;
    return free;
}

Camera camera_from(const FreeCamera& free, const std::string& name) {
    Camera camera;
    camera.name = name;
    camera.position = free.position;
    camera.look_at = free.look_at;
    camera.up = free.up;
    camera.aspect = free.aspect;
    camera.fov = free.fov;
    return camera;
}

void orbit(FreeCamera& camera, double dx, double dy, double view_height) {
    const double per_pixel = pi / std::max(view_height, 1.0);
    Vec3 offset = camera.position - camera.look_at;
    const double distance = glm::length(offset);
    if (!(distance > 0.0)) return;
    offset = rotate(offset, camera.up, -dx * per_pixel);
    // Tilt about the camera's right axis, stopping short of the poles so the
    // view direction never becomes parallel to `up` (the scene would be invalid).
    const Vec3 right = safe_normalize(glm::cross(-offset, camera.up), Vec3(1, 0, 0));
    const double elevation =
        std::acos(std::clamp(glm::dot(offset / distance, camera.up), -1.0, 1.0));
    const double limit = 1.0 * pi / 180.0;
    const double tilt = std::clamp(-dy * per_pixel, elevation - (pi - limit), elevation - limit);
    offset = rotate(offset, right, tilt);
    camera.position = camera.look_at + offset;
}

void pan(FreeCamera& camera, double dx, double dy, double view_height) {
    const Vec3 forward = camera.look_at - camera.position;
    const double distance = glm::length(forward);
    if (!(distance > 0.0)) return;
    const Vec3 f = forward / distance;
    const Vec3 r = safe_normalize(glm::cross(f, camera.up), Vec3(1, 0, 0));
    const Vec3 u = glm::cross(r, f);
    const double visible = 2.0 * distance * std::tan(camera.fov * pi / 360.0);
    const double per_pixel = visible / std::max(view_height, 1.0);
    const Vec3 shift = (-dx * r + dy * u) * per_pixel;
    camera.position += shift;
    camera.look_at += shift;
}

void dolly(FreeCamera& camera, double steps) {
    const Vec3 offset = camera.position - camera.look_at;
    const double distance = glm::length(offset);
    if (!(distance > 0.0)) return;
    const double next = std::max(distance * std::pow(0.9, steps), 1e-3);
    camera.position = camera.look_at + offset * (next / distance);
}

}  // namespace jt::view
