#include "jtracer/pick.hpp"

#include "render/prepared_frame.hpp"
#include "render/prepared_scene.hpp"
#include "render/ray_queries.hpp"

#include <glm/geometric.hpp>

#include <cmath>

namespace jt {

PixelRect frame_rect(const PreparedFrame& frame) {
    return {0, 0, frame.options.width, frame.options.height};
}

std::optional<CameraRay> camera_ray(const PreparedFrame& frame, const ImagePoint& at) {
    const CameraFrame& camera = frame.camera;
    const Vec3 d = camera_direction(camera, at.x, at.y);
    // A camera that cannot form a frame sees nothing (render_tile: background).
    if (!all_finite(camera.position) || !all_finite(d)) return {};
    return CameraRay{camera.position, d};
}

std::optional<PickedPrimitive> pick_primitive(const PreparedFrame& frame, int x, int y) {
    if (x < 0 || y < 0 || x >= frame.options.width || y >= frame.options.height) return {};
    const std::optional<CameraRay> ray = camera_ray(frame, {x + 0.5, y + 0.5});
    if (!ray) return {};
    Hit hit;
    if (!closest_hit(*frame.scene->geometry, ray->origin, ray->direction, 0.0, hit)) return {};
    return PickedPrimitive{static_cast<int>(hit.source), hit.t};
}

std::optional<ImagePoint> project_to_image(const PreparedFrame& frame, const Vec3& point) {
    const CameraFrame& c = frame.camera;
    const Vec3 v = point - c.position;
    const double depth = glm::dot(v, c.forward);
    if (!(depth > 0.0) || !all_finite(v)) return {};
    // camera_direction backwards: the offsets along right and up at unit depth.
    const double sx = glm::dot(v, c.right) / depth;
    const double sy = glm::dot(v, c.up) / depth;
    const ImagePoint p{(sx / (c.tan_half_fov * c.aspect) + 1.0) * 0.5 * c.width,
                       (sy / c.tan_half_fov + 1.0) * 0.5 * c.height};
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return {};
    return p;
}

}  // namespace jt
