#include "jtracer/block_edit.hpp"

#include "edit/block_layout.hpp"
#include "edit/scene_blocks.hpp"
#include "jtracer/camera_edit.hpp"
#include "jtracer/schema.hpp"
#include "jtracer/serializer.hpp"
#include "jtracer/value_text.hpp"

#include <algorithm>
#include <optional>

namespace jt {

namespace {

using edit::Range;
using edit::TextEdit;

// Whether `block` is written in the scene file's text, the one `s.text` is:
// an included file's block has offsets into its own file's.
bool in_text(const BlockSource& block) {
    return block.keyword_span.pos.file == 0;
}

// Appends a block (as `lines`) to the scene block in use, after its last item.
Expected<std::string> add_item(const SceneText& s, const std::vector<std::string>& lines) {
    if (s.source.scene && !in_text(*s.source.scene))
        return Error{"the scene block is written in a file the scene includes: add it there"};
    if (!s.source.scene) {
        std::string out(s.text);
        if (!out.empty() && out.back() != '\n') out += '\n';
        if (!out.empty()) out += '\n';
        return out + "scene {\n" + edit::indented_lines(lines, "    ") + "}\n";
    }
    std::optional<std::size_t> first;
    const BlockSource* last = nullptr;
    for (const std::vector<BlockSource>* items : {&s.source.primitives, &s.source.lights})
        for (const BlockSource& item : *items) {
            if (!in_text(item)) continue;
            const std::size_t at = item.keyword_span.offset;
            first = first ? std::min(*first, at) : at;
            if (!last || at > last->keyword_span.offset) last = &item;
        }
    const bool blank = last && edit::set_apart_by_blank_lines(s.text, edit::block_range(*last));
    return edit::edited_text(s, {edit::insertion_before_close(s.text, s.source.scene->close_brace,
                                                              first, lines, blank)});
}

// The camera block's text with its name set to `name`.
std::string renamed_copy(const SceneText& s, const BlockSource& block, const std::string& name) {
    const Range range = edit::block_range(block);
    const std::string_view copy = s.text.substr(range.begin, range.end - range.begin);
    const PropertySource* last = nullptr;
    for (const PropertySource& p : properties_of(s.source, block))
        if (p.name == "name") last = &p;
    const std::string value = string_text(name);
    if (last)
        return edit::apply_text_edits(
            copy, {{last->value_span.offset - range.begin, last->value_span.length, value}});
    std::optional<std::size_t> first = edit::first_item(s.source, block);
    if (first) *first -= range.begin;
    return edit::apply_text_edits(
        copy, {edit::insertion_before_close(copy, block.close_brace - range.begin, first,
                                            {"name: " + value + ";"})});
}

bool has_writable_strings(const Primitive& primitive) {
    return is_writable_string(primitive.material.finish->image_map);
}

}  // namespace

Expected<std::string> add_primitive(const SceneText& scene, const Primitive& primitive) {
    if (!has_writable_strings(primitive))
        return Error{"the image_map \"" + primitive.material.finish->image_map +
                     "\" cannot be written in a .jts string"};
    const std::vector<std::string> lines = block_lines(primitive);
    // With the objects: after the last one, else before the first light; at
    // the scene block's end when that one is read from an included file.
    const SceneSource& source = scene.source;
    if (source.scene && !source.primitives.empty() && in_text(source.primitives.back())) {
        const Range last = edit::block_range(source.primitives.back());
        return edit::edited_text(
            scene, {edit::insertion_after(scene.text, last, lines,
                                          edit::set_apart_by_blank_lines(scene.text, last))});
    }
    if (source.scene && source.primitives.empty() && !source.lights.empty() &&
        in_text(source.lights.front()))
        return edit::edited_text(
            scene,
            {edit::insertion_before(scene.text, edit::block_range(source.lights.front()), lines)});
    return add_item(scene, lines);
}

Expected<std::string> add_light(const SceneText& scene, const PointLight& light) {
    return add_item(scene, block_lines(light));
}

Expected<std::string> duplicate_block(const SceneText& scene, BlockRef ref) {
    Expected<const BlockSource*> found = edit::find_block(scene, ref);
    if (!found) return found.error();
    const BlockSource& block = **found;
    const Range range = edit::block_range(block);
    std::string copy(scene.text.substr(range.begin, range.end - range.begin));
    if (ref.kind == BlockKind::camera) {
        const std::string& name = scene.scene.cameras[ref.index].name;
        copy = renamed_copy(scene, block,
                            unique_camera_name(scene.scene, name.empty() ? "camera" : name));
    }
    TextEdit inserted;
    if (edit::has_own_lines(scene.text, range)) {
        const bool blank = edit::set_apart_by_blank_lines(scene.text, range);
        inserted.offset = edit::next_line_start(scene.text, range.end);
        if (inserted.offset == scene.text.size() && scene.text.back() != '\n')
            inserted.replacement += '\n';
        if (blank) inserted.replacement += '\n';
        inserted.replacement.append(edit::line_indent(scene.text, range.begin))
            .append(copy)
            .append("\n");
    } else {
        inserted = {range.end, 0, " "};
        inserted.replacement += copy;
    }
    return edit::edited_text(scene, {inserted});
}

Expected<std::string> delete_block(const SceneText& scene, BlockRef ref) {
    Expected<const BlockSource*> found = edit::find_block(scene, ref);
    if (!found) return found.error();
    std::vector<TextEdit> edits{edit::removal(scene.text, edit::block_range(**found), true)};
    if (ref.kind == BlockKind::camera) {
        const std::vector<Camera>& cameras = scene.scene.cameras;
        if (cameras.size() == 1)
            return Error{
                "camera 1 is the scene's only camera and every render needs one: add "
                "another camera before deleting this one"};
        const std::string& name = cameras[ref.index].name;
        const bool named_active =
            !name.empty() && scene.scene.settings.active_camera == name &&
            std::count_if(cameras.begin(), cameras.end(),
                          [&](const Camera& c) { return c.name == name; }) == 1;
        if (named_active && scene.source.render_settings)
            for (const PropertySource& p :
                 properties_of(scene.source, *scene.source.render_settings))
                if (p.name == "active_camera")
                    edits.push_back(
                        edit::removal(scene.text, edit::statement_range(scene.text, p), false));
    }
    return edit::edited_text(scene, std::move(edits));
}

namespace {

// Inserts `lines` as a nested block of a primitive that has no `keyword` block.
Expected<std::string> add_child_block(const SceneText& scene, std::size_t primitive,
                                      std::string_view keyword,
                                      const std::vector<std::string>& lines) {
    const BlockRef ref{BlockKind::primitive, primitive};
    Expected<const BlockSource*> found = edit::find_block(scene, ref);
    if (!found) return found.error();
    const BlockSource& block = **found;
    if (!edit::children_named(scene.source, block, keyword).empty())
        return Error{block_name(scene.scene, ref) + " already has a " + std::string(keyword) +
                     " block"};
    return edit::edited_text(
        scene, {edit::insertion_before_close(scene.text, block.close_brace,
                                             edit::first_item(scene.source, block), lines)});
}

}  // namespace

Expected<std::string> add_material_block(const SceneText& scene, std::size_t primitive,
                                         const Material& material) {
    if (!is_writable_string(material.finish->image_map))
        return Error{"the image_map \"" + material.finish->image_map +
                     "\" cannot be written in a .jts string"};
    return add_child_block(scene, primitive, schema_of<Material>().keyword, block_lines(material));
}

Expected<std::string> add_transform_block(const SceneText& scene, std::size_t primitive,
                                          const std::vector<TransformOp>& ops) {
    return add_child_block(scene, primitive, kTransformKeyword, transform_block_lines(ops));
}

}  // namespace jt
