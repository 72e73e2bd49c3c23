#include "model/selection_commands.hpp"

#include "jtracer/primitive_bounds.hpp"
#include "model/app_actions.hpp"
#include "model/document_edits.hpp"
#include "model/picking.hpp"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>

namespace jt::view {

namespace {

std::optional<BlockRef> selected_block(const AppState& state) {
    const Selection s = current_selection(state.view, state.doc.scene);
    if (s.kind == Selection::Kind::none) return std::nullopt;
    return BlockRef{s.kind == Selection::Kind::light ? BlockKind::light : BlockKind::primitive,
                    static_cast<std::size_t>(s.index)};
}

const BlockSource* block_source(const AppState& state, Selection s) {
    const SceneSource& source = state.doc.source;
    const auto& blocks = s.kind == Selection::Kind::light ? source.lights : source.primitives;
    if (s.kind == Selection::Kind::none || s.index < 0 ||
        static_cast<std::size_t>(s.index) >= blocks.size())
        return nullptr;
    return &blocks[static_cast<std::size_t>(s.index)];
}

// The distance at which a ball of `radius` fills about half the view's height.
double framing_distance(double radius, double fov_degrees) {
    return 2.0 * radius / std::tan(glm::radians(fov_degrees) / 2.0);
}

}  // namespace

bool delete_selection(AppState& state) {
    const std::optional<BlockRef> block = selected_block(state);
    if (!block || !delete_block(state, *block)) return false;
    state.view.selection = {};
    return true;
}

bool duplicate_selection(AppState& state) {
    const std::optional<BlockRef> block = selected_block(state);
    return block && duplicate_block(state, *block);
}

bool frame_selection(AppState& state) {
    const Selection s = current_selection(state.view, state.doc.scene);
    if (s.kind == Selection::Kind::none || state.doc.scene.cameras.empty()) {
        state.message = "Nothing is selected to frame: click an object or light first";
        return false;
    }
    Vec3 centre{0.0};
    std::optional<double> radius;
    if (s.kind == Selection::Kind::light) {
        centre = state.doc.scene.lights[static_cast<std::size_t>(s.index)].position;
    } else if (const std::optional<Bounds> box = primitive_bounds(
                   state.doc.scene.primitives[static_cast<std::size_t>(s.index)])) {
        centre = box->centre();
        radius = glm::length(box->upper - box->lower) / 2.0;
    } else {
        state.message = "A plane or mesh has no size known to frame";
        return false;
    }
    use_free_camera(state.view, state.doc.scene);
    FreeCamera& camera = state.view.free_camera;
    Vec3 forward = camera.look_at - camera.position;
    const double length = glm::length(forward);
    forward = length > 0.0 && std::isfinite(length) ? forward / length : Vec3(0.0, 0.0, -1.0);
    const double distance = radius && *radius > 0.0 ? framing_distance(*radius, camera.fov)
                                                    : glm::length(centre - camera.position);
    camera.look_at = centre;
    camera.position = centre - forward * distance;
    state.message = "Framed the selection (the view's camera; Copy to scene keeps it)";
    return true;
}

std::optional<int> selection_line(const AppState& state) {
    const BlockSource* block = block_source(state, current_selection(state.view, state.doc.scene));
    // A block of an included file has no line in the scene file's text.
    if (!block || block->keyword_span.pos.file != 0) return std::nullopt;
    return block->keyword_span.pos.line;
}

Selection selection_at_offset(const AppState& state, std::size_t offset) {
    const SceneSource& source = state.doc.source;
    // Offsets are into each block's own file: one of an included file may
    // overlap any block of the scene file's text.
    const auto within = [&](const BlockSource& b) {
        return b.keyword_span.pos.file == 0 && offset >= b.keyword_span.offset &&
               offset <= b.close_brace;
    };
    for (std::size_t i = 0; i < source.primitives.size(); ++i)
        if (within(source.primitives[i])) return {Selection::Kind::primitive, static_cast<int>(i)};
    for (std::size_t i = 0; i < source.lights.size(); ++i)
        if (within(source.lights[i])) return {Selection::Kind::light, static_cast<int>(i)};
    return {};
}

}  // namespace jt::view
