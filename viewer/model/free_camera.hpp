#pragma once
// The viewer's own camera: starts from a scene camera and moves with the mouse.
// Left-drag orbits around the look-at point, right/middle-drag pans, the wheel
// dollies toward the look-at point.

#include "jtracer/scene.hpp"

namespace jt::view {

struct FreeCamera {
    Vec3 position{0.0, 0.0, 1.0};
    Vec3 look_at{0.0};
    Vec3 up{0.0, 1.0, 0.0};  // the orbit axis: the scene camera's up
    double aspect = 1.0;
    double fov = 45.0;
    bool operator==(const FreeCamera&) const = default;
};

FreeCamera free_camera_from(const Camera& camera);
Camera camera_from(const FreeCamera& free, const std::string& name);

// Mouse motion in pixels of the image view; `view_height` scales it so one
// drag across the view is about half a turn (orbit) or the visible height (pan).
void orbit(FreeCamera& camera, double dx, double dy, double view_height);
void pan(FreeCamera& camera, double dx, double dy, double view_height);
// Positive steps move closer; each step covers a tenth of the distance left.
void dolly(FreeCamera& camera, double steps);

}  // namespace jt::view
