#pragma once
// Finding the blocks a structure edit names in a SceneText, with the errors
// for names that are not there.

#include "edit/text_edits.hpp"
#include "jtracer/error.hpp"
#include "jtracer/scene_text.hpp"

#include <string_view>
#include <vector>

namespace jt::edit {

// The block's record in the source map; an error when the scene has no such
// block or the source map does not match the scene.
Expected<const BlockSource*> find_block(const SceneText& scene, BlockRef block);

// A primitive's nested blocks with that keyword ("material", "transform"), in file order.
std::vector<const BlockSource*> children_named(const SceneSource& source, const BlockSource& block,
                                               std::string_view keyword);

// The text with `edits` applied.
std::string edited_text(const SceneText& scene, std::vector<TextEdit> edits);

}  // namespace jt::edit
