#pragma once
// Adding, duplicating and deleting the blocks of a scene, and giving a
// primitive a material or transform block, as edits of its text (see
// scene_text.hpp). new_block.hpp makes the blocks to add.

#include "jtracer/error.hpp"
#include "jtracer/scene_text.hpp"

#include <string>
#include <vector>

namespace jt {

// Adds the primitive to the scene block in use (one is appended to the text
// if there is none), written as the serializer writes it, with the objects:
// right after the last primitive (set apart by a blank line when it is), or
// before the first light when there is no primitive. It becomes the scene's
// last primitive.
Expected<std::string> add_primitive(const SceneText& scene, const Primitive& primitive);
// Appends a point light to the scene block, after its last item, with the
// indentation of the blocks before it and a blank line before it when they
// are separated by blank lines: it becomes the scene's last light.
Expected<std::string> add_light(const SceneText& scene, const PointLight& light);

// A copy of the block's text (everything from its keyword to its closing
// brace, comments inside it included) right after it, so that the copy comes
// next in its list. A camera's copy is given a name no other camera has
// (unique_camera_name).
Expected<std::string> duplicate_block(const SceneText& scene, BlockRef block);

// Removes the block's text from its keyword to its closing brace, comments
// inside it included: its whole lines when it has them to itself (a comment
// after its closing brace on the same line goes too), and one blank line when
// two would be left side by side. Deleting a camera that render_settings
// names as active_camera removes that property, so the first camera is
// used. The only camera cannot be deleted.
Expected<std::string> delete_block(const SceneText& scene, BlockRef block);

// Writes a `material` block holding `material` into a primitive that has no
// material block (an error if it has one).
Expected<std::string> add_material_block(const SceneText& scene, std::size_t primitive,
                                         const Material& material);
// Writes a `transform` block holding `ops` into a primitive that has no
// transform block (an error if it has one).
Expected<std::string> add_transform_block(const SceneText& scene, std::size_t primitive,
                                          const std::vector<TransformOp>& ops = {});

}  // namespace jt
