#pragma once
// Which camera the view shows: the scene's cameras, the free camera moved
// with the mouse, and copying it into the scene.

#include "model/app_state.hpp"

#include <string>

namespace jt::view {

// The index of the scene camera the view shows (or the free camera started
// from): always one of the scene's cameras, -1 when it has none. Every command
// that replaces the scene keeps view.camera_index valid; readers still go
// through this so that no stale index can reach past the cameras.
int selected_camera(const ViewState& view, const Scene& scene);
// After the scene was replaced by another (undo, redo, reload, an edit of the
// text), the selected camera index may name no camera or another one: keeps
// the same camera by name when it is still there, else the scene's active one.
void keep_camera_selection(ViewState& view, const Scene& scene, const Scene& before);
// The same, from the cameras `before` had: all an edit needs to keep of a
// large scene.
void keep_camera_selection(ViewState& view, const Scene& scene,
                           const std::vector<Camera>& cameras_before);
void select_camera(AppState& state, int index);
void next_camera(AppState& state);
// Starts moving freely from the selected scene camera (or keeps moving).
void use_free_camera(ViewState& view, const Scene& scene);
void reset_free_camera(ViewState& view, const Scene& scene);
// Appends the free camera to the scene as a new camera named `name` and
// selects it; refused when a camera already has that name.
bool copy_free_camera_to_scene(AppState& state, const std::string& name);

// Ctrl+click on the image (docs/language.md §14.6): the scene camera the view
// shows gets focus_distance = dot(hit - position, f), hit being where the
// pixel-centre pinhole ray through pixel (x, y) of the shown image (Image8's:
// y from the bottom) first meets a surface and f the camera's view direction.
// One undo step. Over the background, with the free camera, or while the
// image shows no frame, nothing changes and the message says why.
bool focus_camera_at(AppState& state, int x, int y);

}  // namespace jt::view
