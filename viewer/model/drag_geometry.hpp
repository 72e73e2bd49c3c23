#pragma once
// The geometry of moving an object by dragging it in the image: the plane
// facing the camera it moves in, the world-space move a cursor position makes
// (the core's primary rays, so the point grabbed stays under the cursor), the
// Shift constraint to one axis, and the short numbers the move is written with.

#include "jtracer/pick.hpp"
#include "jtracer/scene.hpp"

#include <optional>

namespace jt::view {

// The plane { p : dot(p - point, normal) = 0 }, normal of unit length.
struct DragPlane {
    Vec3 point{0.0};
    Vec3 normal{0.0, 0.0, 1.0};
};

// The plane facing the camera of `frame` (its normal the camera's forward
// direction) through `point`; nothing when the camera cannot form a frame.
std::optional<DragPlane> plane_facing_camera(const PreparedFrame& frame, const Vec3& point);

// Where `ray` meets `plane` in front of its origin, or nothing (parallel, behind).
std::optional<Vec3> meet_plane(const DragPlane& plane, const CameraRay& ray);

// The move in `plane` that takes the point under image point `from` to the
// point under `to`: where the primary rays of `frame` through them meet it,
// the later less the earlier. Nothing when either ray misses the plane.
std::optional<Vec3> drag_delta(const PreparedFrame& frame, const DragPlane& plane,
                               const ImagePoint& from, const ImagePoint& to);

// The extent of one image pixel on `plane` about image point `at` (the
// distance between the points the rays through `at` and one pixel above
// meet it), or nothing when they miss it.
std::optional<double> pixel_size_on(const PreparedFrame& frame, const DragPlane& plane,
                                    const ImagePoint& at);

// Shift: `delta` along the one world axis (x, y or z) of its largest
// component, the other two zero; the first of equal ones.
Vec3 along_largest_axis(const Vec3& delta);

// `delta` along `axis` (unit length) alone: how a plane, which cannot move
// within itself, follows a drag.
Vec3 along(const Vec3& delta, const Vec3& axis);

// The value a drag writes for `start` moved by `delta`: each coordinate the
// move changes by less than half a step keeps `start`'s exact value; each
// other is start + delta rounded to the step, the power of ten at or below a
// tenth of `pixel_size` (0.001 for a pixel 0.017 across), so that the file
// gets 1.234 rather than 1.2340000000000002 or 1e-17 and the point grabbed
// stays within a tenth of a pixel of the cursor.
Vec3 moved_value(const Vec3& start, const Vec3& delta, double pixel_size);

}  // namespace jt::view
