#pragma once
// Adding, renaming and changing cameras, as edits of the text (see
// scene_text.hpp; duplicating and deleting one is block_edit.hpp's).

#include "jtracer/error.hpp"
#include "jtracer/scene_text.hpp"

#include <cstddef>
#include <string>
#include <string_view>

namespace jt {

// `base` if no camera has that name, else "base 2", "base 3", ... (a number
// already ending `base` is counted on from).
std::string unique_camera_name(const Scene& scene, std::string_view base);

// Appends `camera` to the last cameras block (one is appended if there is
// none). Its name must be non-empty and not another camera's.
Expected<std::string> add_camera(const SceneText& scene, const Camera& camera);

// Renames the camera; an active_camera naming it follows. The name must be
// non-empty, writable in a .jts string and not another camera's.
Expected<std::string> rename_camera(const SceneText& scene, std::size_t camera,
                                    std::string_view name);

// Writes every property of `camera` that differs from the scene's camera
// (inserting those the block does not write yet); a new name is checked as
// rename_camera checks it, and values against the schema's ranges.
Expected<std::string> set_camera(const SceneText& scene, std::size_t camera, const Camera& edited);

// Sets the camera's aspect to render_settings' width / height (an error while
// either is 0).
Expected<std::string> set_aspect_from_image(const SceneText& scene, std::size_t camera);

}  // namespace jt
