#pragma once
// Where each part of a parsed Scene came from in its .jts text.
//
// Kept beside the Scene rather than inside it, so that the Scene stays a pure
// value. Used for located validation messages and by the viewer to write an
// edited value back into the file at its exact span, leaving every other byte
// (comments, order, formatting) as it was.
//
// The layout is flat: every property record of the scene lives in one array,
// every material/transform block record in another, and a block refers to its
// own as a range of indices. A million spheres cost two arrays, not millions of
// small ones. Walk a block with the free functions below:
//
//   for (const PropertySource& p : properties_of(source, block)) ...
//   for (const BlockSource& child : children_of(source, block)) ...

#include "jtracer/diagnostics.hpp"
#include "jtracer/source_files.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace jt {

// Offsets are 32-bit: parse_scene refuses texts of 4 GiB or more. The offset
// is into the text of file `pos.file` (jtracer/source_files.hpp): a block,
// its properties and its children are all in one file.
struct TextSpan {
    std::uint32_t offset = 0;  // byte offset into the text
    std::uint32_t length = 0;
    SourcePos pos;  // line:column of `offset`
    bool operator==(const TextSpan&) const = default;
};

// `count` consecutive records from `first`, in one of SceneSource's arrays.
struct IndexRange {
    std::uint32_t first = 0;
    std::uint32_t count = 0;
    bool operator==(const IndexRange&) const = default;
};

// How a value is written (docs/language.md §15): a literal (`2`, `-1.5`,
// `<1, -2, 3>`, `"out.bmp"`) may be rewritten in place; a name (`r`) or an
// expression (`r * 2`, `<0, clock, 0>`) may not, since the value comes from
// elsewhere or is computed.
enum class ValueOrigin : std::uint8_t { literal, name, expression };

struct PropertySource {
    std::string_view name;  // the property's name as read, in static storage (never the text's)
    TextSpan name_span;
    TextSpan value_span;  // the value's own text, e.g. "<1, 0.5, 0>" or "2.0"
    ValueOrigin origin = ValueOrigin::literal;
    bool operator==(const PropertySource&) const = default;
};

// A `define NAME = VALUE;` or a named material `material NAME { ... }` at the
// top level, in file order. A named material's properties are its block's.
struct DefinitionSource {
    std::string name;
    TextSpan name_span;
    TextSpan value_span;  // a define's value; empty for a material
    ValueOrigin origin = ValueOrigin::literal;
    std::optional<IndexRange> material_properties;  // into SceneSource::properties
    bool operator==(const DefinitionSource&) const = default;
};

struct BlockSource {
    std::string_view keyword;  // "sphere", "material", ... in static storage
    TextSpan keyword_span;
    std::uint32_t open_brace = 0;   // offset of '{'
    std::uint32_t close_brace = 0;  // offset of '}'
    IndexRange properties;          // into SceneSource::properties, in file order, repeats included
    IndexRange children;            // into SceneSource::children: material and transform blocks
    // A primitive's `material: NAME;`: the named material's index in
    // SceneSource::definitions, whose properties the primitive inherits.
    std::optional<std::uint32_t> named_material;
    bool operator==(const BlockSource&) const = default;
};

struct SceneSource {
    std::optional<BlockSource> render_settings;  // the block in use (the last one)
    std::optional<BlockSource> scene;            // the block in use (the last one)
    std::vector<BlockSource> cameras;            // parallel to Scene::cameras
    std::vector<BlockSource> primitives;         // parallel to Scene::primitives
    std::vector<BlockSource> lights;             // parallel to Scene::lights
    std::vector<BlockSource> children;           // every primitive's nested blocks
    std::vector<PropertySource> properties;      // every block's properties
    std::vector<DefinitionSource> definitions;   // top-level defines and named materials
    // Every reading of an included file, in reading order (SourcePos::file
    // k > 0 is files[k - 1]); empty for a scene without `include`. Kept even
    // when parsed without a source map: diagnostics quote these texts.
    std::vector<SourceFile> files;
    // The paths of included files that could not be read, for a watcher to
    // notice when they appear.
    std::vector<std::string> unread_includes;
    bool operator==(const SceneSource&) const = default;
};

// A block's properties, in file order (repeats included).
inline std::span<const PropertySource> properties_of(const SceneSource& source,
                                                     const BlockSource& block) {
    return std::span(source.properties).subspan(block.properties.first, block.properties.count);
}

// A primitive's material and transform blocks, in file order.
inline std::span<const BlockSource> children_of(const SceneSource& source,
                                                const BlockSource& block) {
    return std::span(source.children).subspan(block.children.first, block.children.count);
}

}  // namespace jt
