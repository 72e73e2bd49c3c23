#include "language/properties.hpp"

#include "jtracer/value_text.hpp"
#include "language/quote.hpp"
#include "language/suggest.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace jt::lang {

namespace {

// A literal number as spelled, a computed one as value_text writes it.
std::string written_number(const Value& v) {
    return v.text.empty() ? value_text(v.number) : std::string(v.text.substr(0, 40));
}

std::string got(const Value& v) {
    switch (v.form) {
        case Value::Form::number:
            return "the number " + written_number(v);
        case Value::Form::vector:
            return "the vector " + vector_text(v.vector);
        case Value::Form::string:
            return "the string \"" + std::string(v.text.substr(0, 40)) +
                   (v.text.size() > 40 ? "...\"" : "\"");
        default:
            return "nothing";
    }
}

// The value as the file wrote it, for messages.
std::string written(const Value& v) {
    if (v.form == Value::Form::vector) return vector_text(v.vector);
    if (v.form == Value::Form::number) return written_number(v);
    return std::string(v.text.substr(0, 40));
}

// The value as it would be written again: strings in quotes.
std::string as_written(const Value& v) {
    return v.form == Value::Form::string ? string_text(v.text.substr(0, 40)) : written(v);
}

}  // namespace

void PropertyReader::kind_error(const Property& p, ValueKind expected) {
    std::string message = quote(p.name) + " takes " + std::string(kind_description(expected)) +
                          ", got " + got(p.value);
    sink_.error(p.value.span.pos, std::move(message));
}

template <class Block>
bool PropertyReader::read(const PropertySpec<Block>& spec, const Property& p, Block& target) {
    const Value& v = p.value;
    return with_member(spec, target, [&](auto& out) {
        using T = std::decay_t<decltype(out)>;
        if constexpr (std::is_same_v<T, std::string>) {
            if (v.form != Value::Form::string) {
                kind_error(p, spec.kind);
                return false;
            }
            if (check_range(spec.range, v.text) == RangeVerdict::outside) {
                // In quotes, so that a word that is nearly a choice ("Smooth",
                // "file ", "") shows exactly what differs.
                sink_.error(v.span.pos,
                            out_of_range_message(
                                spec, spec.range.choices.empty() ? written(v) : as_written(v)));
                return false;
            }
            out = std::string(v.text);
            return true;
        } else {
            constexpr bool is_vector =
                std::is_same_v<T, Vec3> || std::is_same_v<T, std::optional<Vec3>>;
            if (v.form != (is_vector ? Value::Form::vector : Value::Form::number)) {
                kind_error(p, spec.kind);
                return false;
            }
            std::conditional_t<is_vector, Vec3, double> value;
            if constexpr (is_vector) {
                value = v.vector;
                // check_range's own first test, here without the call: most
                // vectors are strictly inside their range (so finite too).
                const ValueRange& range = spec.range;
                auto between = [&](double x) { return range.low < x && x < range.high; };
                if (!range.nonzero && between(value.x) && between(value.y) && between(value.z)) {
                    out = value;
                    return true;
                }
            } else {
                // Whole numbers truncate toward zero before the range applies
                // (docs/language.md §3.2).
                value = spec.kind == ValueKind::whole ? std::trunc(v.number) : v.number;
            }
            const auto checked = check_range(spec.range, value);
            if (checked.verdict == RangeVerdict::outside) {
                sink_.error(v.span.pos, out_of_range_message(spec, written(v)));
                return false;
            }
            if (checked.verdict == RangeVerdict::clamped && sink_.accepts_warnings()) {
                sink_.warning(v.span.pos,
                              past_clamp_message(spec, written(v), value_text(checked.value)));
            }
            if constexpr (is_vector)
                out = checked.value;
            else
                out = static_cast<T>(checked.value);
            return true;
        }
    });
}

namespace {

template <class Block>
std::optional<bool> has_property_in(std::string_view keyword, std::string_view name) {
    if (schema_of<Block>().keyword != keyword) return std::nullopt;
    return find_property<Block>(name) != nullptr;
}

template <std::size_t... I>
std::optional<bool> has_shape_property(std::string_view keyword, std::string_view name,
                                       std::index_sequence<I...>) {
    std::optional<bool> found;
    ((found = found ? found : has_property_in<ShapeAlternative<I>>(keyword, name)), ...);
    return found;
}

}  // namespace

bool block_has_property(std::string_view keyword, std::string_view name) {
    for (std::optional<bool> found :
         {has_property_in<RenderSettings>(keyword, name), has_property_in<Camera>(keyword, name),
          has_property_in<PointLight>(keyword, name), has_property_in<Material>(keyword, name),
          has_shape_property(keyword, name,
                             std::make_index_sequence<std::variant_size_v<Shape>>{})})
        if (found) return *found;
    if (keyword == kTransformKeyword) {
        for (const TransformOpSpec& op : transform_ops())
            if (same_name(name, op.property.name)) return true;
        return false;
    }
    return keyword != kCamerasKeyword && keyword != kSceneKeyword;
}

void PropertyReader::unknown_property(const Property& p, std::string_view keyword,
                                      std::span<const std::string_view> names) {
    if (keyword == schema_of<Material>().keyword && p.name == keyword) {
        sink_.error(p.name_span.pos,
                    "a material cannot use another material: 'material: NAME;' stands directly "
                    "in a sphere, plane, cylinder, triangle or mesh");
        return;
    }
    if (keyword == schema_of<PointLight>().keyword &&
        std::ranges::any_of(primitive_blocks(),
                            [&](std::string_view b) { return same_name(b, p.name); })) {
        sink_.error(p.name_span.pos, takes_no_message(keyword, p.name));
        return;
    }
    std::string message = unknown_name_message("property", p.name, "in " + quote(keyword), names);
    // POV-Ray moves an object with a bare `translate`; here it stands in a block.
    for (const TransformOpSpec& op : transform_ops())
        if (keyword != kTransformKeyword && same_name(p.name, op.property.name))
            message +=
                "; write it in a transform block: transform { " + std::string(p.name) + ": ...; }";
    sink_.error(p.name_span.pos, message);
}

template <class Block>
void PropertyReader::apply_block(Block& target, OpenBlock& block, const Property& p) {
    const BlockSchema<Block>& schema = schema_of<Block>();
    const PropertySpec<Block>* spec = find_property<Block>(p.name);
    if (!spec) {
        std::vector<std::string_view> names;
        for (const PropertySpec<Block>& known : schema.properties) names.push_back(known.name);
        names.insert(names.end(), schema.children.begin(), schema.children.end());
        unknown_property(p, schema.keyword, names);
        return;
    }
    if (!read(*spec, p, target)) return;
    // Only a name with an alias can have been found by another name.
    if (!spec->alias.empty() && p.name != spec->name) {
        sink_.warning(p.name_span.pos, quote(p.name) + " inside a " + std::string(schema.noun) +
                                           " is read as " + quote(spec->name) + "; write " +
                                           std::string(spec->name) + ": " + as_written(p.value) +
                                           "; instead");
    }
    record(block, p, spec->name, true);
}

void PropertyReader::record(OpenBlock& block, const Property& p, std::string_view as_name,
                            bool warn_repeat) {
    if (warn_repeat) {
        int first_line = block.first_lines.find(as_name);
        if (first_line == 0) {
            block.first_lines.add(as_name, p.name_span.pos.line);
        } else if (sink_.accepts_warnings()) {
            sink_.warning(p.name_span.pos, quote(as_name) + " is set again in this " +
                                               quote(block.source.keyword) +
                                               "; the later value wins (first set at line " +
                                               std::to_string(first_line) + ")");
        }
    }
    block.properties.push_back({as_name, p.name_span, p.value.span, p.value.origin});
}

void PropertyReader::apply(RenderSettings& settings, OpenBlock& block, const Property& p) {
    apply_block(settings, block, p);
}
void PropertyReader::apply(Camera& camera, OpenBlock& block, const Property& p) {
    apply_block(camera, block, p);
}
void PropertyReader::apply(Shape& shape, OpenBlock& block, const Property& p) {
    visit_shape([&](auto& s) { apply_block(s, block, p); }, shape);
}
void PropertyReader::apply(Material& material, OpenBlock& block, const Property& p) {
    apply_block(material, block, p);
}
void PropertyReader::apply(PointLight& light, OpenBlock& block, const Property& p) {
    apply_block(light, block, p);
}

void PropertyReader::apply(std::vector<TransformOp>& transforms, OpenBlock& block,
                           const Property& p) {
    for (const TransformOpSpec& op_spec : transform_ops()) {
        if (!same_name(p.name, op_spec.property.name)) continue;
        TransformOp op;
        op.kind = op_spec.kind;
        if (!read(op_spec.property, p, op)) return;
        transforms.push_back(op);
        // Every transform property is an operation: repeats apply, with no warning.
        record(block, p, op_spec.property.name, false);
        return;
    }
    std::vector<std::string_view> names;
    for (const TransformOpSpec& op_spec : transform_ops()) names.push_back(op_spec.property.name);
    unknown_property(p, kTransformKeyword, names);
}

}  // namespace jt::lang
