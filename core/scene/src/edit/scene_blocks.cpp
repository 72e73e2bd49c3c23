#include "edit/scene_blocks.hpp"

#include "jtracer/schema.hpp"

namespace jt {

std::string block_name(const Scene& scene, BlockRef block) {
    const std::string number = std::to_string(block.index + 1);
    switch (block.kind) {
        case BlockKind::camera:
            return std::string(schema_of<Camera>().noun) + " " + number;
        case BlockKind::primitive:
            if (block.index < scene.primitives.size())
                return std::string(keyword_of(scene.primitives[block.index].shape)) + " " + number;
            return "object " + number;
        case BlockKind::light:
            return std::string(schema_of<PointLight>().noun) + " " + number;
    }
    return number;
}

namespace edit {

namespace {

// The list of blocks of that kind: the scene's count and the source map's records.
std::pair<std::size_t, const std::vector<BlockSource>*> blocks_of(const SceneText& scene,
                                                                  BlockKind kind) {
    switch (kind) {
        case BlockKind::camera:
            return {scene.scene.cameras.size(), &scene.source.cameras};
        case BlockKind::primitive:
            return {scene.scene.primitives.size(), &scene.source.primitives};
        case BlockKind::light:
            return {scene.scene.lights.size(), &scene.source.lights};
    }
    return {0, &scene.source.cameras};
}

std::string_view plural(BlockKind kind) {
    switch (kind) {
        case BlockKind::camera:
            return "cameras";
        case BlockKind::primitive:
            return "objects";
        case BlockKind::light:
            return "lights";
    }
    return "blocks";
}

}  // namespace

Expected<const BlockSource*> find_block(const SceneText& scene, BlockRef block) {
    const auto [count, records] = blocks_of(scene, block.kind);
    if (records->size() != count)
        return Error{"the text's source map does not match its scene (was it parsed without one?)"};
    if (block.index >= count)
        return Error{"there is no " + block_name(scene.scene, block) + ": the scene has " +
                     std::to_string(count) + " " + std::string(plural(block.kind))};
    const BlockSource& found = (*records)[block.index];
    // Its offsets are into the text of the file it is written in, not into
    // scene.text: an edit there would cut or insert at a place of another block.
    if (const std::uint32_t file = found.keyword_span.pos.file; file != 0) {
        const std::vector<SourceFile>& files = scene.source.files;
        return Error{block_name(scene.scene, block) + " is written in " +
                     (file <= files.size() ? files[file - 1].name : "an included file") +
                     ", which the scene includes: change it in that file"};
    }
    return &found;
}

std::vector<const BlockSource*> children_named(const SceneSource& source, const BlockSource& block,
                                               std::string_view keyword) {
    std::vector<const BlockSource*> found;
    for (const BlockSource& child : children_of(source, block))
        if (child.keyword == keyword) found.push_back(&child);
    return found;
}

std::string edited_text(const SceneText& scene, std::vector<TextEdit> edits) {
    return apply_text_edits(scene.text, std::move(edits));
}

}  // namespace edit
}  // namespace jt
