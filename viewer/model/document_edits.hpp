#pragma once
// The commands that rewrite the document's text rather than one value: the
// structure edits of the panels (add, duplicate, delete blocks; material and
// transform blocks; transform operations; cameras, through the core's
// block_edit.hpp, transform_edit.hpp and camera_edit.hpp) and the text typed
// in the text editor. Each is one undo step in the same history as the
// panels' value edits; Save scene writes the text they leave.

#include "jtracer/error.hpp"
#include "jtracer/new_block.hpp"
#include "jtracer/scene_text.hpp"
#include "model/app_state.hpp"
#include "model/editor_files.hpp"

#include <cstddef>
#include <functional>
#include <string>

namespace jt::view {

// Runs `edit` on the document's text (with the panels' edits written in) and
// takes the result in as one undo step; on failure nothing changes and the
// message says why. `done` is the message on success.
bool edit_text_structure(AppState& state,
                         const std::function<Expected<std::string>(const SceneText&)>& edit,
                         const std::string& done);
// The same without recording an undo step or a message, for an edit that
// keeps its own step (a drag that moves an object records one when let go);
// the error is the message to show.
Expected<void> rewrite_text(AppState& state,
                            const std::function<Expected<std::string>(const SceneText&)>& edit);

// Each add selects what it added (to be moved or changed next).
bool add_object(AppState& state, ShapeKind kind);  // in front of the view's camera
// A mesh of the model `file` (relative to the scene's folder, as a mesh's
// `file` is; an absolute path inside that folder is written relative to it)
// in front of the view's camera, scaled to a new sphere's size (new_mesh).
// A file that does not load, or holds no triangle, adds nothing and the
// message says why.
bool add_mesh(AppState& state, const std::string& file);
bool add_light(AppState& state);
bool duplicate_block(AppState& state, BlockRef block);
bool delete_block(AppState& state, BlockRef block);
// Why the commands that rewrite `block` as a whole (Duplicate, Delete, Add
// material or transform block, the transform operations, a camera's rename)
// are not offered: it is written in a file the scene includes, and they
// edit the scene file's text; its values are still edited in place. Empty
// when they are offered.
std::string why_not_rewrite_block(const SceneDocument& doc, BlockRef block);
bool add_material_block(AppState& state, std::size_t primitive);
bool add_transform_block(AppState& state, std::size_t primitive);
bool add_transform_op(AppState& state, std::size_t primitive, TransformKind kind);
bool move_transform_op(AppState& state, std::size_t primitive, std::size_t from, std::size_t to);
bool remove_transform_op(AppState& state, std::size_t primitive, std::size_t index);
// A new camera: the view as it is (the free camera's, or the selected one's), named uniquely.
bool add_camera(AppState& state);
bool rename_camera(AppState& state, std::size_t camera, const std::string& name);
bool set_aspect_from_image(AppState& state, std::size_t camera);

// Puts new_scene()'s text into a blank document (document_is_blank), as typing it would (one undo
// step, checked off the UI thread): then the panels can add to it. False, with
// the reason in state.message, when the document is not blank.
bool start_new_scene(AppState& state);

// The text editor's text changed to `text`: it becomes the document's draft,
// checked off the UI thread once typing pauses (kTypingPause). The first
// keystroke after a pause records one undo step.
void type_text(AppState& state, std::string text);
// Takes in the check of the draft, if one finished: a text without errors
// becomes the document (the render restarts from it); one with errors keeps
// the last good scene and image, and its diagnostics say where. True when a
// check was taken in.
bool take_checked_text(AppState& state);

}  // namespace jt::view
