#pragma once
// A .jts text together with what it parsed to: the input of every edit that
// changes the structure of a scene by rewriting part of its text
// (block_edit.hpp, transform_edit.hpp, camera_edit.hpp).
//
//   jt::ParseResult parsed = jt::parse_scene(text);
//   jt::Expected<std::string> edited = jt::delete_block(
//       jt::SceneText{text, parsed.scene, parsed.source}, {jt::BlockKind::primitive, 2});
//   if (!edited) report(edited.error().message);
//
// Each edit returns the whole new text. Only the bytes of the block it changes
// differ (and, where it says so, the property that refers to it); every
// comment, blank line and value elsewhere stays as it was.

#include "jtracer/scene.hpp"
#include "jtracer/source_map.hpp"

#include <cstddef>
#include <string>
#include <string_view>

namespace jt {

// `text` parsed without errors to `scene`, with the spans in `source`.
struct SceneText {
    std::string_view text;
    const Scene& scene;
    const SceneSource& source;
};

// The blocks an edit can name: one of a scene's cameras, primitives or lights.
enum class BlockKind { camera, primitive, light };

struct BlockRef {
    BlockKind kind = BlockKind::primitive;
    std::size_t index = 0;  // into Scene::cameras, ::primitives or ::lights
    bool operator==(const BlockRef&) const = default;
};

// "camera 2", "sphere 3" (the primitive's kind, counted among all
// primitives), "point_light 1": a block as messages name it, counting from 1.
std::string block_name(const Scene& scene, BlockRef block);

}  // namespace jt
