#include "jtracer/source_serializer.hpp"

#include "jtracer/schema.hpp"
#include "jtracer/serializer.hpp"
#include "jtracer/source_files.hpp"
#include "language/kept_includes.hpp"
#include "language/scene_writer.hpp"

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace jt {

namespace {

using lang::PropertyText;
using lang::Writer;
using How = PropertyText::How;

// The last record of `name`: the one whose value the block holds (a later
// repeat wins).
const PropertySource* last_record(std::span<const PropertySource> records, std::string_view name) {
    for (auto it = records.rbegin(); it != records.rend(); ++it)
        if (it->name == name) return &*it;
    return nullptr;
}

// True when the property is an optional value that is unset: no text says that.
template <class Block>
bool is_unset(const PropertySpec<Block>& property, const Block& block) {
    return with_member(property, block, [](const auto& value) {
        if constexpr (requires { value.has_value(); })
            return !value.has_value();
        else
            return false;
    });
}

// An item of the layout as the include plan says: after the line of the
// include that starts there, if one does, and not at all when an include
// gives it.
template <class Write>
void place(Writer& w, const lang::Placement& placement, Write write) {
    if (!placement.include.empty()) w.line("include " + std::string(placement.include) + ";");
    if (!placement.covered) write();
}

// A part of the top level, followed by a blank line when it wrote anything.
template <class Write>
void section(Writer& w, Write write) {
    const std::size_t before = w.text.size();
    write();
    if (w.text.size() != before) w.blank();
}

// The parse `scene` is written against: its text, source spans and the
// scene as parsed, to which the source is parallel block by block.
class Original {
  public:
    explicit Original(const ParsedText& from) : text_(from.text), parsed_(from.parsed) {}

    const SceneSource& source() const { return parsed_.source; }
    const Scene& scene() const { return parsed_.scene; }

    // A span's text, from the file it lies in (the main text or an included one).
    std::string_view written(const TextSpan& span) const {
        return file_text(parsed_.source.files, text_, span.pos.file)
            .substr(span.offset, span.length);
    }

    // Whether a record's value may be written as the text wrote it. A file
    // name written in an included file is relative to that file's folder and
    // the scene holds it relative to the main file's: written in the result,
    // which has no include, it must be that value.
    static bool keeps_text(const PropertySource& record) {
        return record.name_span.pos.file == 0 || !names_a_file(record.name);
    }

    // A value the text wrote as a name or an expression, as written, while
    // `now` still holds what it gave; otherwise the canonical text.
    template <class Block>
    PropertyText kept(const PropertySpec<Block>& property, const Block& now, const Block& then,
                      std::span<const PropertySource> records) const {
        const PropertySource* record = last_record(records, property.name);
        if (!record || record->origin == ValueOrigin::literal || !keeps_text(*record) ||
            !same_value(property, now, then))
            return {};
        return {How::as_written, written(record->value_span)};
    }

    // A block of properties only, each kept as written where it can be.
    template <class Block>
    void write_block(Writer& w, const Block& now, const Block* then,
                     const BlockSource* block) const {
        if (!then || !block) {
            lang::write_block(w, now);
            return;
        }
        w.open(schema_of<Block>().keyword);
        lang::write_properties(w, now, [&](const PropertySpec<Block>& property) {
            return kept(property, now, *then, properties_of(source(), *block));
        });
        w.close();
    }

    void write_primitive(Writer& w, const Primitive& now, const Primitive* then,
                         const BlockSource* block) const;
    void write_definitions(Writer& w, std::span<const Define> defines,
                           std::span<const lang::Placement> placements) const;

  private:
    // The records of a primitive's child blocks of one keyword, in file order.
    std::vector<PropertySource> child_records(const BlockSource& block,
                                              std::string_view keyword) const {
        std::vector<PropertySource> records;
        for (const BlockSource& child : children_of(source(), block))
            if (child.keyword == keyword) {
                const auto own = properties_of(source(), child);
                records.insert(records.end(), own.begin(), own.end());
            }
        return records;
    }

    void write_material(Writer& w, const Material& now, const Material& then,
                        const BlockSource& block) const;

    // The value named material `definition` gives `property`, as value_text,
    // from a primitive that inherits it as parsed; none when no primitive
    // does, and then the value means nothing to the scene.
    std::optional<std::string> inherited_value(const PropertySpec<Material>& property,
                                               std::uint32_t definition) const {
        for (std::size_t i = 0; i < source().primitives.size(); ++i) {
            const BlockSource& block = source().primitives[i];
            if (block.named_material != definition) continue;
            const std::vector<PropertySource> own =
                child_records(block, schema_of<Material>().keyword);
            if (!last_record(own, property.name))
                return value_text(property, scene().primitives[i].material);
        }
        return std::nullopt;
    }

    std::string_view text_;
    const ParseResult& parsed_;
};

void Original::write_material(Writer& w, const Material& now, const Material& then,
                              const BlockSource& block) const {
    const std::vector<PropertySource> records = child_records(block, schema_of<Material>().keyword);
    const std::span<const PropertySource> own(records);
    // A named material applies first, then the primitive's own blocks. What
    // the primitive does not set itself is inherited, so its own block must
    // state every value that differs from the named material's: an optional
    // value unset over a named one that is set cannot be stated, and the
    // material is then written whole, without the name.
    bool named = block.named_material.has_value();
    for (const PropertySpec<Material>& property : schema_of<Material>().properties)
        if (is_unset(property, now) && !same_value(property, now, then)) named = false;
    if (!named) {
        w.open(schema_of<Material>().keyword);
        lang::write_properties(w, now, [&](const PropertySpec<Material>& property) {
            return kept(property, now, then, own);
        });
        w.close();
        return;
    }
    w.property(schema_of<Material>().keyword, source().definitions[*block.named_material].name);
    auto choose = [&](const PropertySpec<Material>& property) -> PropertyText {
        const bool same = same_value(property, now, then);
        if (const PropertySource* record = last_record(own, property.name)) {
            if (same && record->origin != ValueOrigin::literal && keeps_text(*record))
                return {How::as_written, written(record->value_span)};
            return {How::literal, {}};
        }
        return {same ? How::omitted : How::literal, {}};
    };
    if (!lang::writes_any(now, choose)) return;
    w.open(schema_of<Material>().keyword);
    lang::write_properties(w, now, choose);
    w.close();
}

void Original::write_primitive(Writer& w, const Primitive& now, const Primitive* then,
                               const BlockSource* block) const {
    if (!then || !block || now.shape.index() != then->shape.index()) {
        lang::write_primitive(w, now);
        return;
    }
    w.open(keyword_of(now.shape));
    visit_shape(
        [&](const auto& shape) {
            using Shape = std::decay_t<decltype(shape)>;
            const Shape& was = shape_as<Shape>(then->shape);
            lang::write_properties(w, shape, [&](const PropertySpec<Shape>& property) {
                return kept(property, shape, was, properties_of(source(), *block));
            });
        },
        now.shape);
    write_material(w, now.material, then->material, *block);
    if (!now.transforms.empty()) {
        const std::vector<PropertySource> records = child_records(*block, kTransformKeyword);
        lang::write_transform(w, now.transforms, [&](std::size_t i) {
            const bool kept = i < then->transforms.size() && i < records.size() &&
                              now.transforms[i] == then->transforms[i] &&
                              records[i].origin != ValueOrigin::literal &&
                              records[i].name == transform_op(now.transforms[i].kind).property.name;
            return kept ? written(records[i].value_span) : std::string_view();
        });
    }
    w.close();
}

void Original::write_definitions(Writer& w, std::span<const Define> defines,
                                 std::span<const lang::Placement> placements) const {
    // The --define values in effect: a later one of a name wins.
    auto command_line = [&](std::string_view name) -> const Define* {
        for (auto it = defines.rbegin(); it != defines.rend(); ++it)
            if (it->name == name) return &*it;
        return nullptr;
    };
    auto defined_in_text = [&](std::string_view name) {
        for (const DefinitionSource& definition : source().definitions)
            if (definition.name == name && !definition.material_properties) return true;
        return false;
    };
    auto define = [&](std::string_view name, std::string_view value) {
        w.line("define " + std::string(name) + " = " + std::string(value) + ";");
    };
    for (std::size_t i = 0; i < defines.size(); ++i) {
        const Define& d = defines[i];
        if (command_line(d.name) != &d || defined_in_text(d.name)) continue;
        define(d.name, d.value);
    }
    for (std::uint32_t index = 0; index < source().definitions.size(); ++index) {
        const DefinitionSource& definition = source().definitions[index];
        place(w, placements[index], [&] {
            if (!definition.material_properties) {
                const Define* set = command_line(definition.name);
                define(definition.name,
                       set ? std::string_view(set->value) : written(definition.value_span));
                return;
            }
            const std::span<const PropertySource> records =
                std::span(source().properties)
                    .subspan(definition.material_properties->first,
                             definition.material_properties->count);
            w.open(std::string(schema_of<Material>().keyword) + " " + definition.name);
            for (const PropertySpec<Material>& property : schema_of<Material>().properties) {
                const PropertySource* record = last_record(records, property.name);
                if (!record) continue;
                const std::optional<std::string> value =
                    keeps_text(*record) ? std::nullopt : inherited_value(property, index);
                w.property(property.name, value ? *value : written(record->value_span));
            }
            w.close();
        });
    }
}

// Whether the source is parallel to the scene parsed with it: not so when it
// was parsed without the source map.
bool has_source(const ParseResult& parsed) {
    return parsed.source.cameras.size() == parsed.scene.cameras.size() &&
           parsed.source.primitives.size() == parsed.scene.primitives.size() &&
           parsed.source.lights.size() == parsed.scene.lights.size();
}

}  // namespace

std::string serialize_scene(const Scene& scene, const ParsedText& from) {
    if (!from.parsed.ok() || !has_source(from.parsed)) return serialize_scene(scene);
    const Original original(from);
    const Scene& then = original.scene();
    const SceneSource& source = original.source();
    const lang::IncludePlan plan = lang::plan_includes(scene, from.parsed, from.text, from.defines);
    auto at = [](const auto& items, std::size_t i) {
        return i < items.size() ? &items[i] : nullptr;
    };
    // lang::write_blocks's layout, where a kept include stands in place of
    // what it gives (kept_includes.hpp).
    Writer w;
    w.text = lang::kWrittenBy;
    section(w, [&] { original.write_definitions(w, from.defines, plan.definitions); });
    section(w, [&] {
        place(w, plan.settings, [&] {
            original.write_block(w, scene.settings, &then.settings,
                                 source.render_settings ? &*source.render_settings : nullptr);
        });
    });
    section(w, [&] {
        place(w, plan.cameras_block, [&] {
            w.open(kCamerasKeyword);
            for (std::size_t i = 0; i < scene.cameras.size(); ++i)
                place(w, plan.cameras[i], [&] {
                    original.write_block(w, scene.cameras[i], at(then.cameras, i),
                                         at(source.cameras, i));
                });
            w.close();
        });
    });
    place(w, plan.scene_block, [&] {
        w.open(kSceneKeyword);
        for (std::size_t i = 0; i < scene.primitives.size(); ++i)
            place(w, plan.primitives[i], [&] {
                original.write_primitive(w, scene.primitives[i], at(then.primitives, i),
                                         at(source.primitives, i));
            });
        for (std::size_t i = 0; i < scene.lights.size(); ++i)
            place(w, plan.lights[i], [&] {
                original.write_block(w, scene.lights[i], at(then.lights, i), at(source.lights, i));
            });
        w.close();
    });
    // An include that starts in an earlier part and gives the scene block as
    // well leaves that part's blank line last: drop it.
    if (w.text.ends_with("\n\n")) w.text.pop_back();
    return std::move(w.text);
}

}  // namespace jt
