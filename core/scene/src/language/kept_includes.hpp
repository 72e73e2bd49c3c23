#pragma once
// Which `include` statements of a main text the serializer that keeps a
// text's names (source_serializer.hpp) writes back as written, and where
// (docs/language.md §15.5).
//
// Every block, define and named material of the scene is one item of the
// canonical layout, in its order: the definitions, render_settings, the
// cameras block and its cameras, the scene block and its primitives, then
// its lights. An include of the main text owns the items that its reading
// (and the files it includes in turn) gave. It is kept, written once in
// place of its items, when they are all still as read, stand as one
// unbroken run of the layout, and stand where the include itself may stand;
// otherwise its items are written one by one, as for a text without it.
// Reading a kept include again also gives what its files hold that the
// scene no longer shows (a render_settings block a later one replaced): it
// is kept only where that is replaced again.

#include "jtracer/parser.hpp"
#include "jtracer/scene.hpp"

#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

namespace jt::lang {

// What the serializer writes at one item of the layout.
struct Placement {
    // A kept include gives the item: it is not written.
    bool covered = false;
    // The include's string as the main text wrote it, quotes included, at
    // the first item it gives (`include <this>;` is written there); empty
    // elsewhere.
    std::string_view include;
};

// One Placement an item, parallel to what the serializer writes.
struct IncludePlan {
    std::vector<Placement> definitions;  // parallel to SceneSource::definitions
    Placement settings;
    Placement cameras_block;            // `cameras { }` itself: covered with all its cameras
    std::vector<Placement> cameras;     // parallel to Scene::cameras
    Placement scene_block;              // `scene { }` itself
    std::vector<Placement> primitives;  // parallel to Scene::primitives
    std::vector<Placement> lights;      // parallel to Scene::lights
};

// The plan for writing `scene` against `parsed`, the parse (with the source
// map, without errors) of `main_text` with the --define values `defines`.
// An include is kept only when what it gave is unchanged: each block equal
// (operator==) to the one parsed at its place, and no define of it set by a
// --define. An include that gave the scene nothing is not written.
IncludePlan plan_includes(const Scene& scene, const ParseResult& parsed, std::string_view main_text,
                          std::span<const Define> defines);

}  // namespace jt::lang
