#pragma once
// Scene + the text it was parsed from -> canonical .jts text that keeps the
// text's names and includes (docs/language.md §15.2, §15.3, §15.5).
//
// serialize_scene(scene) writes every value as a literal: right for a scene
// made in code, but a scene read from a file that says `define r = 2;` and
// `radius: r * 2;` would lose what its author wrote. This one writes the same
// canonical layout, with the text's definitions first and each value a name
// or an expression wrote kept as written, so that the file keeps meaning what
// it meant when one of its values changes.
//
//   ParseResult parsed = parse_scene(text, options);    // with the source map
//   Scene edited = parsed.scene; ...                      // any changes
//   std::string out = serialize_scene(edited, {text, parsed});
//   assert(parse_scene(out, options).scene == edited);    // the same main_file

#include "jtracer/parser.hpp"
#include "jtracer/scene.hpp"

#include <span>
#include <string>
#include <string_view>

namespace jt {

// A text with what parsing it gave.
struct ParsedText {
    std::string_view text;
    // parse_scene(text, options), with the source map (options.source_map).
    const ParseResult& parsed;
    // options.defines: the --define values the text was read with.
    std::span<const Define> defines = {};
};

// Canonical text for `scene` (serialize_scene's layout and order) that keeps
// what `from` wrote with names:
// - every `define` and named material `material NAME { ... }` of the text, in
//   its order, before render_settings; a define's value and a named
//   material's properties are written as the text wrote them;
// - a primitive's `material: NAME;`, with its own `material { }` block holding
//   only what it sets itself or what differs from the named material;
// - a property or transform operation the text wrote as a name or an
//   expression, written as the text wrote it while `scene` holds the value it
//   had when parsed (`from.parsed.scene`, block by block in order); a value
//   changed since is written as a literal, as is every other value.
// An `include` of the text whose files gave blocks, defines and named
// materials that `scene` still holds as read (each block equal to the one
// parsed at its index), and that stand as one unbroken run of the layout
// where the include may stand, is written as the text wrote it, once, in
// place of all it gave: the result then reads back as `scene` only when
// parsed with the same ParseOptions::main_file folder and the same files.
// Any other include is written out in place, from each file's own text, as
// a text without it would be; a file name such a file wrote is written as
// the value the scene holds, since it was relative to that file's folder.
// No included file is ever written: one that gave something that changed
// may be shared, or read more than once, so the change goes into the
// result instead. An include that gave the scene nothing (an empty file, or
// blocks a later one replaced) is dropped.
// A --define value stands in place of the text's own definition of that name
// (before everything when the text has none), so that the result reads back
// as `scene` with no --define; `clock` must be what it was.
//
// A text that did not parse without errors, or was parsed without the source
// map, has no names that can be trusted: the result is then serialize_scene(scene).
std::string serialize_scene(const Scene& scene, const ParsedText& from);

}  // namespace jt
