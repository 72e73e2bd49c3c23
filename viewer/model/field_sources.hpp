#pragma once
// Where the value a panel field shows comes from in the text (docs/language.md
// §15.3): written as a literal (the field edits it), as a name or an
// expression (computed: the field is read-only, edited in the text editor),
// inherited from a named material (editing writes the object's own
// `material { }` block), or not written at all. Asked for every field on
// every frame: the lookups walk the document's source map and allocate
// nothing; the words of a tooltip are made only when it shows.

#include "jtracer/source_map.hpp"
#include "model/scene_document.hpp"

#include <cstddef>
#include <span>
#include <string>
#include <string_view>

namespace jt::view {

struct EditedBlock;

enum class FieldOrigin { unwritten, literal, name, expression, inherited };

struct FieldSource {
    FieldOrigin origin = FieldOrigin::unwritten;
    const PropertySource* property = nullptr;    // the statement in force, when written
    const DefinitionSource* material = nullptr;  // the named material it is inherited from
};

// A value the panels show but do not edit.
inline bool read_only(const FieldSource& source) {
    return source.origin == FieldOrigin::name || source.origin == FieldOrigin::expression;
}

// The text's block of a panel's block; null when the text has none (render
// settings never written, a camera added in the panel and not yet saved).
const BlockSource* block_source(const SceneDocument& doc, const EditedBlock& block);

// A property of the block itself (a shape's, a camera's, a light's, the
// render settings'): the last statement of it is the one in force.
FieldSource field_source(const SceneDocument& doc, const BlockSource* block,
                         std::string_view property);
// A property of a primitive's material: its own `material { }` blocks, then
// the material it names (`material: NAME;`).
FieldSource material_field_source(const SceneDocument& doc, const BlockSource* primitive,
                                  std::string_view property);
// The named material a primitive uses (`material: NAME;`), or null.
const DefinitionSource* named_material(const SceneDocument& doc, const BlockSource* primitive);
// The `index`th operation of a primitive's transform blocks.
FieldSource transform_field_source(const SceneDocument& doc, const BlockSource* primitive,
                                   std::size_t index);

// The included file a block is written in (docs/language.md §15.6), and how
// many times the scene reads it: each reading makes objects of its own, and
// an edit of a value written there changes all of them. No allocation:
// asked every frame.
struct SharedText {
    std::string_view name;  // the file's, short (short_file_name)
    int readings = 0;       // 0 when the block is in the scene file
};
SharedText shared_text(const SceneDocument& doc, const BlockSource* block);

// "in parts/ball.jts", or "in parts/ball.jts (included 3 times): an edit
// changes every object read from it", written into `out` (cut to fit);
// empty when the block is in the scene file.
std::string_view shared_text_note(const SharedText& shared, std::span<char> out);

// "FILE:LINE" of a place in the document's text: the one place that names the
// file a span is in.
std::string text_place(const SceneDocument& doc, const TextSpan& span);

// The value's own text as written (`r * 2`), empty when not written.
std::string_view written_text(const SceneDocument& doc, const FieldSource& source);

// What the field's tooltip says about where its value comes from: "from r,
// defined at scene.jts:3; edit it in the text editor (T)", "computed from the
// expression `r * 2` ...", "inherited from material shiny ..."; empty for a
// literal or an unwritten value.
std::string describe_source(const SceneDocument& doc, const FieldSource& source);
// What a read-only value is, for a message: "the name r, defined at
// scene.jts:3", "the name r, set by --define r=2", "computed from the
// expression `r * 2`"; empty for a literal or an unwritten value.
std::string computed_from(const SceneDocument& doc, const FieldSource& source);

}  // namespace jt::view
