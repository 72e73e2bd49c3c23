#include "model/drag_geometry.hpp"

#include "jtracer/value_text.hpp"

#include <glm/geometric.hpp>

#include <cmath>

namespace jt::view {

namespace {

// rounded_to_scale's step is a power of ten three digits below its scale: a
// scale of ten pixels makes it the power of ten at or below a tenth of one.
constexpr double kPixelsPerScale = 10.0;

}  // namespace

std::optional<DragPlane> plane_facing_camera(const PreparedFrame& frame, const Vec3& point) {
    const PixelRect image = frame_rect(frame);
    const std::optional<CameraRay> centre = camera_ray(frame, {image.x1 * 0.5, image.y1 * 0.5});
    if (!centre || !all_finite(point)) return std::nullopt;
    return DragPlane{point, centre->direction};
}

std::optional<Vec3> meet_plane(const DragPlane& plane, const CameraRay& ray) {
    const double facing = glm::dot(ray.direction, plane.normal);
    const double t = glm::dot(plane.point - ray.origin, plane.normal) / facing;
    if (!(t > 0.0) || !std::isfinite(t)) return std::nullopt;
    const Vec3 hit = ray.origin + ray.direction * t;
    if (!all_finite(hit)) return std::nullopt;
    return hit;
}

namespace {

std::optional<Vec3> under(const PreparedFrame& frame, const DragPlane& plane,
                          const ImagePoint& at) {
    const std::optional<CameraRay> ray = camera_ray(frame, at);
    if (!ray) return std::nullopt;
    return meet_plane(plane, *ray);
}

}  // namespace

std::optional<Vec3> drag_delta(const PreparedFrame& frame, const DragPlane& plane,
                               const ImagePoint& from, const ImagePoint& to) {
    const std::optional<Vec3> a = under(frame, plane, from), b = under(frame, plane, to);
    if (!a || !b) return std::nullopt;
    return *b - *a;
}

std::optional<double> pixel_size_on(const PreparedFrame& frame, const DragPlane& plane,
                                    const ImagePoint& at) {
    const std::optional<Vec3> step = drag_delta(frame, plane, at, {at.x, at.y + 1.0});
    if (!step) return std::nullopt;
    const double size = glm::length(*step);
    if (!(size > 0.0) || !std::isfinite(size)) return std::nullopt;
    return size;
}

Vec3 along_largest_axis(const Vec3& delta) {
    int axis = 0;
    for (int i = 1; i < 3; ++i)
        if (std::abs(delta[i]) > std::abs(delta[axis])) axis = i;
    Vec3 out{0.0};
    out[axis] = delta[axis];
    return out;
}

Vec3 along(const Vec3& delta, const Vec3& axis) {
    return axis * glm::dot(delta, axis);
}

Vec3 moved_value(const Vec3& start, const Vec3& delta, double pixel_size) {
    const double scale = pixel_size * kPixelsPerScale;
    Vec3 out = start;
    for (int i = 0; i < 3; ++i)
        if (rounded_to_scale(delta[i], scale) != 0.0)
            out[i] = rounded_to_scale(start[i] + delta[i], scale);
    return out;
}

}  // namespace jt::view
