#include "model/field_sources.hpp"

#include "jtracer/schema.hpp"
#include "model/app_state.hpp"

#include <algorithm>
#include <cstdio>

namespace jt::view {

namespace {

// The last of `properties` named `property`: the statement in force.
const PropertySource* last_named(std::span<const PropertySource> properties,
                                 std::string_view property) {
    const PropertySource* last = nullptr;
    for (const PropertySource& p : properties)
        if (p.name == property) last = &p;
    return last;
}

FieldSource written(const PropertySource* p) {
    if (!p) return {};
    switch (p->origin) {
        case ValueOrigin::literal:
            return {FieldOrigin::literal, p, nullptr};
        case ValueOrigin::name:
            return {FieldOrigin::name, p, nullptr};
        case ValueOrigin::expression:
            return {FieldOrigin::expression, p, nullptr};
    }
    return {};
}

// The span's text, in the main text or in the included file it is in.
std::string_view span_text(const SceneDocument& doc, const TextSpan& span) {
    const std::string_view text = file_text(doc.source.files, doc.text, span.pos.file);
    if (span.offset > text.size()) return {};
    return text.substr(span.offset, span.length);
}

// The definition of `name` in the text, or null (set by --define alone).
const DefinitionSource* definition_of(const SceneDocument& doc, std::string_view name) {
    for (const DefinitionSource& d : doc.source.definitions)
        if (d.name == name) return &d;
    return nullptr;
}

// The --define that sets `name` (the last one of it wins), or null.
const Define* define_of(const SceneDocument& doc, std::string_view name) {
    const Define* found = nullptr;
    for (const Define& d : doc.options.defines)
        if (d.name == name) found = &d;
    return found;
}

// A long expression is cut for a tooltip.
std::string shortened(std::string_view text) {
    constexpr std::size_t most = 80;
    if (text.size() <= most) return std::string(text);
    return std::string(text.substr(0, most)) + "...";
}

}  // namespace

const BlockSource* block_source(const SceneDocument& doc, const EditedBlock& block) {
    const SceneSource& s = doc.source;
    switch (block.kind) {
        case EditedBlock::Kind::settings:
            return s.render_settings ? &*s.render_settings : nullptr;
        case EditedBlock::Kind::camera:
            return block.index < s.cameras.size() ? &s.cameras[block.index] : nullptr;
        case EditedBlock::Kind::primitive:
            return block.index < s.primitives.size() ? &s.primitives[block.index] : nullptr;
        case EditedBlock::Kind::light:
            return block.index < s.lights.size() ? &s.lights[block.index] : nullptr;
    }
    return nullptr;
}

FieldSource field_source(const SceneDocument& doc, const BlockSource* block,
                         std::string_view property) {
    if (!block) return {};
    return written(last_named(properties_of(doc.source, *block), property));
}

const DefinitionSource* named_material(const SceneDocument& doc, const BlockSource* primitive) {
    if (!primitive || !primitive->named_material ||
        *primitive->named_material >= doc.source.definitions.size())
        return nullptr;
    return &doc.source.definitions[*primitive->named_material];
}

FieldSource material_field_source(const SceneDocument& doc, const BlockSource* primitive,
                                  std::string_view property) {
    if (!primitive) return {};
    const PropertySource* own = nullptr;
    for (const BlockSource& child : children_of(doc.source, *primitive))
        if (child.keyword == schema_of<Material>().keyword)
            if (const PropertySource* p = last_named(properties_of(doc.source, child), property))
                own = p;
    if (own) return written(own);
    const DefinitionSource* named = named_material(doc, primitive);
    if (!named || !named->material_properties) return {};
    const DefinitionSource& material = *named;
    const IndexRange range = *material.material_properties;
    const auto properties = std::span(doc.source.properties).subspan(range.first, range.count);
    if (const PropertySource* p = last_named(properties, property))
        return {FieldOrigin::inherited, p, &material};
    return {};
}

FieldSource transform_field_source(const SceneDocument& doc, const BlockSource* primitive,
                                   std::size_t index) {
    if (!primitive) return {};
    std::size_t at = 0;
    for (const BlockSource& child : children_of(doc.source, *primitive)) {
        if (child.keyword != kTransformKeyword) continue;
        for (const PropertySource& p : properties_of(doc.source, child))
            if (at++ == index) return written(&p);
    }
    return {};
}

SharedText shared_text(const SceneDocument& doc, const BlockSource* block) {
    if (!block) return {};
    const std::uint32_t file = block->keyword_span.pos.file;
    if (file == 0 || file > doc.source.files.size()) return {};
    const SourceFile& read = doc.source.files[file - 1];
    int readings = 0;
    for (const SourceFile& f : doc.source.files) readings += f.canonical == read.canonical;
    return {short_file_name(doc, read.name), readings};
}

std::string_view shared_text_note(const SharedText& shared, std::span<char> out) {
    if (shared.readings < 1 || out.empty()) return {};
    const int name_size = static_cast<int>(shared.name.size());
    const int n =
        shared.readings == 1
            ? std::snprintf(out.data(), out.size(), "in %.*s", name_size, shared.name.data())
            : std::snprintf(out.data(), out.size(),
                            "in %.*s (included %d times): an edit changes every object read "
                            "from it",
                            name_size, shared.name.data(), shared.readings);
    if (n < 0) return {};
    return {out.data(), std::min(static_cast<std::size_t>(n), out.size() - 1)};
}

std::string text_place(const SceneDocument& doc, const TextSpan& span) {
    // The main file by its name alone; an included one as diagnostics name it.
    const std::string main = doc.path.filename().string();
    return std::string(file_name(doc.source.files, main, span.pos.file)) + ":" +
           std::to_string(span.pos.line);
}

std::string_view written_text(const SceneDocument& doc, const FieldSource& source) {
    return source.property ? span_text(doc, source.property->value_span) : std::string_view();
}

namespace {

// Where the name `name` gets its value, as a phrase after it: ", set by
// --define r=2", ", defined at scene.jts:3"; empty when neither is known.
std::string name_origin(const SceneDocument& doc, std::string_view name) {
    if (const Define* define = define_of(doc, name))
        return ", set by --define " + define->name + "=" + shortened(define->value);
    if (const DefinitionSource* d = definition_of(doc, name))
        return ", defined at " + text_place(doc, d->name_span);
    return {};
}

}  // namespace

std::string computed_from(const SceneDocument& doc, const FieldSource& source) {
    const std::string_view text = written_text(doc, source);
    if (source.origin == FieldOrigin::expression)
        return "computed from the expression `" + shortened(text) + "`";
    if (source.origin != FieldOrigin::name) return {};
    return "the name " + shortened(text) + name_origin(doc, text);
}

std::string describe_source(const SceneDocument& doc, const FieldSource& source) {
    const std::string_view text = written_text(doc, source);
    switch (source.origin) {
        case FieldOrigin::unwritten:
        case FieldOrigin::literal:
            return {};
        case FieldOrigin::name: {
            const std::string out = "From " + std::string(text) + name_origin(doc, text);
            if (define_of(doc, text))
                return out +
                       " on the command line. The value is computed: it cannot be edited "
                       "here.";
            return out +
                   ". The value is computed: edit it in the text editor (T), where the "
                   "name is defined.";
        }
        case FieldOrigin::expression:
            return "Computed from the expression `" + shortened(text) +
                   "`. Edit it in the text editor (T); saving keeps the expression.";
        case FieldOrigin::inherited: {
            const std::string name = source.material ? source.material->name : std::string("?");
            std::string out = "Inherited from material " + name;
            if (source.material)
                out += ", defined at " + text_place(doc, source.material->name_span);
            out += ", where it is written " + shortened(text) +
                   ". Editing it here writes it into this object's own material { } block; "
                   "material " +
                   name + " and the other objects that use it stay as they are.";
            return out;
        }
    }
    return {};
}

}  // namespace jt::view
