#pragma once
// Edit fields for a block's properties, read from the schema (jtracer/schema.hpp):
// one field per number, vector and colour property, labelled with its name in
// the file and held to the language's range, in the schema's order (an
// optional colour or number with a checkbox that sets or clears it, a string
// of a few allowed words as a combo). A property added to the schema gets its
// field here without a line of panel code. Other strings (names, the
// filename, image maps) have no field here: the panels give the ones they
// edit their own.

#include "app/panels/widgets.hpp"
#include "jtracer/schema.hpp"
#include "model/field_sources.hpp"

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>

namespace jt::view {

// The widget bounds for a range: an open bound moves inside by a small step
// (radius > 0 stops at 0.0001).
struct FieldBounds {
    double min = 0.0;
    double max = 0.0;
};
FieldBounds field_bounds(const ValueRange& range);

// Drag speed per pixel: a 200th of a bounded range, half a degree for angles,
// else 1% of the value's size (at least 0.01).
float field_speed(const ValueRange& range, std::string_view unit, double size);

// What an unset optional number stands for: the value a tick writes (the one
// it takes unset, when it has one) and the words the greyed field shows.
// The note lives in the struct, not on the heap: the field is drawn every
// frame, and an idle frame allocates nothing.
struct UnsetNumber {
    double when_set = 0.0;
    std::array<char, 96> note{};
};
UnsetNumber unset_note(double when_set, const char* note);
// A camera's focus_distance is |look_at - position| (docs/language.md §14.2);
// a mesh's smooth_angle is off (§14.4).
UnsetNumber unset_number(std::string_view property, const Camera& camera);
UnsetNumber unset_number(std::string_view property, const Mesh& mesh);
template <class Block>
UnsetNumber unset_number(std::string_view, const Block&) {
    return unset_note(0.0, "not set");
}

template <class Block>
bool edit_property_field(const PropertySpec<Block>& property, Block& block);

// Under a block's header, when its text is in an included file: a line
// naming the file and, when the scene includes it more than once, saying
// that an edit changes every object read from it (field_sources.hpp:
// shared_text). Recorded as "included text".
void shared_text_line(const SceneDocument& doc, const BlockSource* block);

// Marks a field by where its value comes from (field_sources.hpp), around
// the widget: a name or an expression greys it out (it cannot change) and
// shows the text it is computed from under it; an inherited value tints it.
// Hovering tells where the value comes from. Nothing is allocated unless the
// tooltip shows.
class FieldMark {
  public:
    FieldMark(const SceneDocument* doc, const FieldSource& source);
    ~FieldMark();
    FieldMark(const FieldMark&) = delete;
    FieldMark& operator=(const FieldMark&) = delete;
    bool read_only() const { return read_only_; }

  private:
    const SceneDocument* doc_;
    FieldSource source_;
    bool read_only_ = false;
    int colours_ = 0;
};

// The field for one property of `block`; true when the user changed it.
// With `doc`, the field is marked by `source`, where its value comes from.
template <class Block>
bool edit_property(const PropertySpec<Block>& property, Block& block,
                   const SceneDocument* doc = nullptr, const FieldSource& source = {}) {
    const FieldMark mark(doc, source);
    const bool changed = edit_property_field(property, block);
    // Disabled, the widget cannot change; a computed value is never written here.
    return changed && !mark.read_only();
}

template <class Block>
bool edit_property_field(const PropertySpec<Block>& property, Block& block) {
    // Names in the tables are string literals, so data() ends in a NUL.
    const char* label = property.name.data();
    return with_member(property, block, [&](auto& value) {
        using T = std::decay_t<decltype(value)>;
        const FieldBounds bounds = field_bounds(property.range);
        const auto why = [&property] {
            return range_rule(property.range, property.kind, property.unit);
        };
        if constexpr (std::is_same_v<T, int>) {
            return edit_int(label, value, static_cast<int>(bounds.min),
                            static_cast<int>(bounds.max), why);
        } else if constexpr (std::is_same_v<T, double>) {
            return edit_number(label, value, field_speed(property.range, property.unit, value),
                               bounds.min, bounds.max, why);
        } else if constexpr (std::is_same_v<T, std::optional<double>>) {
            const UnsetNumber unset = unset_number(property.name, block);
            return edit_optional_number(
                label, value, unset.when_set, unset.note.data(),
                field_speed(property.range, property.unit, value ? *value : unset.when_set),
                bounds.min, bounds.max, why);
        } else if constexpr (std::is_same_v<T, std::string>) {
            if (property.range.choices.empty()) return false;
            return edit_choice(label, value, property.range.choices);
        } else if constexpr (std::is_same_v<T, std::optional<Vec3>>) {
            return edit_optional_colour(label, value, Colour(0.1));
        } else if constexpr (std::is_same_v<T, Vec3>) {
            if (property.kind == ValueKind::colour) return edit_colour(label, value);
            const double size = std::max({std::abs(value.x), std::abs(value.y), std::abs(value.z)});
            return edit_vector(label, value, field_speed(property.range, property.unit, size),
                               bounds.min, bounds.max, why);
        } else {
            return false;
        }
    });
}

// Every property of the block that has a field; true when any changed.
template <class Block>
bool edit_properties(Block& block) {
    bool changed = false;
    for (const PropertySpec<Block>& property : schema_of<Block>().properties)
        changed = edit_property(property, block) || changed;
    return changed;
}

// The same, each field marked by where its value comes from:
// `source_of(name)` gives its FieldSource in `doc`.
template <class Block, class SourceOf>
bool edit_properties(Block& block, const SceneDocument& doc, const SourceOf& source_of) {
    bool changed = false;
    for (const PropertySpec<Block>& property : schema_of<Block>().properties)
        changed = edit_property(property, block, &doc, source_of(property.name)) || changed;
    return changed;
}

}  // namespace jt::view
