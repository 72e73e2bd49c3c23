#pragma once
// Moving the selected object or light by dragging it in the image (Alt+drag).
//
// The drag moves in the plane facing the camera through the point grabbed:
// the point of the selected object under the cursor at the press (the core's
// pick, the renderer's first hit), or the object's centre when the press is
// off it. Each cursor position casts the primary ray through it with the
// camera of the image the drag started on; where it meets that plane, less
// where the press's ray met it, is the move (drag_geometry.hpp), so the point
// grabbed stays under the cursor. With Shift the move keeps only its largest
// world axis (x, y or z). A plane, infinite, moves along its own normal only.
//
// An object moves by the last operation of its transform, a translate: the
// operations apply in the order written (docs/language.md §5.3), so the last
// is applied in world space and adding the move to it moves the object by
// exactly that in the world. When the last operation is not a translate, the
// drag's first move adds one (a transform block too when there is none,
// through the core's transform_edit.hpp). A light moves its `position`.
//
// The document changes as the cursor moves, at most every kDragWriteInterval
// (the latest position wins), so the render restarts and follows; the whole
// drag is one undo step, Esc (or Ctrl+Z) during it gives the document back as
// it was, and a drag let go where it started changes nothing.

#include "model/app_state.hpp"

#include <chrono>

namespace jt::view {

inline constexpr std::chrono::milliseconds kDragWriteInterval{40};

// Starts moving the selection from image point `at` (pixels from the bottom
// left); with nothing selected, what a click at `at` would select (a light's
// marker within `marker_radius` pixels first) is selected and moved. False,
// with the reason in state.message, when there is nothing it can move.
bool start_object_drag(AppState& state, const ImagePoint& at, double marker_radius);

// The drag follows the cursor at image point `at`, constrained to one axis
// with `one_axis` (Shift): the document gets the new value when it changed
// and kDragWriteInterval has passed since the last write. Called every frame
// of the drag, so that the last position is written once the interval passes.
void drag_object_to(AppState& state, const ImagePoint& at, bool one_axis,
                    std::chrono::steady_clock::time_point now = std::chrono::steady_clock::now());

// The drag let go at `at`: its final value is written and recorded as one
// undo step; nothing changes (no undo step) when it ends where it started.
void finish_object_drag(AppState& state, const ImagePoint& at, bool one_axis);

// Esc: the document is given back as it was before the drag.
void cancel_object_drag(AppState& state);

// Where an object is, in world space: a sphere's centre, a cylinder's axis
// midpoint, a triangle's centroid, a mesh's bounding box centre, a plane's
// point nearest the origin of its object space, each through its transform.
// Nothing when its transform leaves it out of the render.
std::optional<Vec3> object_centre(const Scene& scene, const Primitive& primitive);

}  // namespace jt::view
