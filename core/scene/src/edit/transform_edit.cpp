#include "jtracer/transform_edit.hpp"

#include "edit/block_layout.hpp"
#include "edit/scene_blocks.hpp"
#include "jtracer/block_edit.hpp"
#include "jtracer/schema.hpp"
#include "jtracer/serializer.hpp"

namespace jt {

namespace {

using edit::Range;
using edit::TextEdit;

struct Operations {
    const BlockSource* primitive = nullptr;
    std::vector<const BlockSource*> blocks;  // the transform blocks, in file order
    std::vector<Range> statements;           // every operation's statement, in order
};

Expected<Operations> operations_of(const SceneText& scene, std::size_t primitive) {
    const BlockRef ref{BlockKind::primitive, primitive};
    Expected<const BlockSource*> found = edit::find_block(scene, ref);
    if (!found) return found.error();
    Operations ops;
    ops.primitive = *found;
    ops.blocks = edit::children_named(scene.source, **found, kTransformKeyword);
    for (const BlockSource* block : ops.blocks)
        for (const PropertySource& p : properties_of(scene.source, *block))
            ops.statements.push_back(edit::statement_range(scene.text, p));
    if (ops.statements.size() != scene.scene.primitives[primitive].transforms.size())
        return Error{"the text's transform blocks do not match its scene"};
    return ops;
}

std::string no_operation(const SceneText& scene, std::size_t primitive, std::size_t index,
                         std::size_t count) {
    return block_name(scene.scene, {BlockKind::primitive, primitive}) +
           " has no transform operation " + std::to_string(index + 1) + " (it has " +
           std::to_string(count) + ")";
}

}  // namespace

Expected<std::string> add_transform_op(const SceneText& scene, std::size_t primitive,
                                       std::size_t index, const TransformOp& op) {
    Expected<Operations> ops = operations_of(scene, primitive);
    if (!ops) return ops.error();
    const std::size_t count = ops->statements.size();
    if (index > count)
        return Error{"cannot insert transform operation " + std::to_string(index + 1) + " into " +
                     block_name(scene.scene, {BlockKind::primitive, primitive}) + ": it has " +
                     std::to_string(count)};
    const std::vector<std::string> statement{transform_op_statement(op)};
    if (ops->blocks.empty()) return add_transform_block(scene, primitive, {op});
    if (count == 0) {
        const BlockSource& last = *ops->blocks.back();
        return edit::edited_text(scene, {edit::insertion_before_close(scene.text, last.close_brace,
                                                                      std::nullopt, statement)});
    }
    if (index < count)
        return edit::edited_text(
            scene, {edit::insertion_before(scene.text, ops->statements[index], statement)});
    return edit::edited_text(
        scene, {edit::insertion_after(scene.text, ops->statements.back(), statement)});
}

Expected<std::string> move_transform_op(const SceneText& scene, std::size_t primitive,
                                        std::size_t from, std::size_t to) {
    Expected<Operations> ops = operations_of(scene, primitive);
    if (!ops) return ops.error();
    const std::vector<Range>& slots = ops->statements;
    for (std::size_t index : {from, to})
        if (index >= slots.size())
            return Error{no_operation(scene, primitive, index, slots.size())};
    std::vector<std::string> texts;
    for (const Range& slot : slots)
        texts.emplace_back(scene.text.substr(slot.begin, slot.end - slot.begin));
    std::string moved = std::move(texts[from]);
    texts.erase(texts.begin() + static_cast<std::ptrdiff_t>(from));
    texts.insert(texts.begin() + static_cast<std::ptrdiff_t>(to), std::move(moved));
    std::vector<TextEdit> edits;
    for (std::size_t i = std::min(from, to); i <= std::max(from, to); ++i)
        edits.push_back({slots[i].begin, slots[i].end - slots[i].begin, texts[i]});
    return edit::edited_text(scene, std::move(edits));
}

Expected<std::string> remove_transform_op(const SceneText& scene, std::size_t primitive,
                                          std::size_t index) {
    Expected<Operations> ops = operations_of(scene, primitive);
    if (!ops) return ops.error();
    if (index >= ops->statements.size())
        return Error{no_operation(scene, primitive, index, ops->statements.size())};
    return edit::edited_text(scene, {edit::removal(scene.text, ops->statements[index], false)});
}

}  // namespace jt
