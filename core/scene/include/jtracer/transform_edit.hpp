#pragma once
// Adding, moving and removing the operations of a primitive's transform, as
// edits of the text (see scene_text.hpp). A primitive's operations are those
// of all its transform blocks, in file order; `index` counts them so, as
// Primitive::transforms does.

#include "jtracer/error.hpp"
#include "jtracer/scene_text.hpp"

#include <cstddef>
#include <string>

namespace jt {

// Inserts `op` so that it becomes operation `index` (0 .. the number of
// operations): before the operation now there, or after the last one. A
// primitive with no transform block is given one.
Expected<std::string> add_transform_op(const SceneText& scene, std::size_t primitive,
                                       std::size_t index, const TransformOp& op);

// Moves operation `from` to position `to`: the statements between them move
// up or down one place, each slot of the text keeping its layout.
Expected<std::string> move_transform_op(const SceneText& scene, std::size_t primitive,
                                        std::size_t from, std::size_t to);

// Removes operation `index`'s statement (its whole line when it has one); an
// emptied transform block stays.
Expected<std::string> remove_transform_op(const SceneText& scene, std::size_t primitive,
                                          std::size_t index);

}  // namespace jt
