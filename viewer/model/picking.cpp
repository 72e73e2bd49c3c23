#include "model/picking.hpp"

#include "jtracer/schema.hpp"
#include "model/app_actions.hpp"

#include <cmath>

namespace jt::view {

std::shared_ptr<const PreparedFrame> shown_frame(AppState& state) {
    if (!state.render.started ||
        state.render.started->primitive_count != state.doc.scene.primitives.size())
        return nullptr;
    std::shared_ptr<const PreparedScene> scene = state.render.renderer.current_prepared();
    if (!scene) return nullptr;
    const RenderOptions& o = state.render.started->options;
    ShownFrame& shown = state.view.shown_frame;
    if (shown.scene != scene || shown.width != o.width || shown.height != o.height ||
        shown.camera != o.camera) {
        shown = {scene, o.width, o.height, o.camera, prepare_frame(scene, o)};
    }
    return shown.frame;
}

std::optional<PickedPrimitive> primitive_at(AppState& state, int x, int y) {
    const std::shared_ptr<const PreparedFrame> frame = shown_frame(state);
    if (!frame) return std::nullopt;
    return pick_primitive(*frame, x, y);
}

std::vector<LightMarker> light_markers(AppState& state) {
    std::vector<LightMarker> markers;
    const std::shared_ptr<const PreparedFrame> frame = shown_frame(state);
    if (!frame) return markers;
    const auto& lights = state.doc.scene.lights;
    for (std::size_t i = 0; i < lights.size(); ++i)
        if (const std::optional<ImagePoint> at = project_to_image(*frame, lights[i].position))
            markers.push_back({static_cast<int>(i), *at});
    return markers;
}

void select(ViewState& view, Selection selection) {
    view.selection = selection;
    view.reveal_selection = selection.kind != Selection::Kind::none;
}

void select_at(AppState& state, double x, double y, double marker_radius) {
    double nearest = marker_radius;
    std::optional<int> light;
    for (const LightMarker& m : light_markers(state)) {
        const double d = std::hypot(m.at.x - x, m.at.y - y);
        if (d <= nearest) {
            nearest = d;
            light = m.light;
        }
    }
    if (light) {
        select(state.view, {Selection::Kind::light, *light});
        state.message = "Selected point_light " + std::to_string(*light + 1);
        return;
    }
    const std::optional<PickedPrimitive> hit =
        primitive_at(state, static_cast<int>(std::floor(x)), static_cast<int>(std::floor(y)));
    if (!hit) {
        select(state.view, {});
        state.message = "Selection cleared";
        return;
    }
    select(state.view, {Selection::Kind::primitive, hit->primitive});
    const Primitive& p = state.doc.scene.primitives[static_cast<std::size_t>(hit->primitive)];
    state.message =
        "Selected " + std::string(keyword_of(p.shape)) + " " + std::to_string(hit->primitive + 1);
}

Selection current_selection(const ViewState& view, const Scene& scene) {
    const Selection& s = view.selection;
    const std::size_t count = s.kind == Selection::Kind::primitive ? scene.primitives.size()
                              : s.kind == Selection::Kind::light   ? scene.lights.size()
                                                                   : 0;
    if (s.index < 0 || static_cast<std::size_t>(s.index) >= count) return {};
    return s;
}

const Expected<MeshInfo>& mesh_figures(AppState& state, int primitive) {
    std::optional<MeshFigures>& kept = state.view.mesh_figures;
    if (!kept || kept->primitive != primitive || kept->revision != state.doc.revision) {
        const auto& primitives = state.doc.scene.primitives;
        kept.emplace();
        kept->primitive = primitive;
        kept->revision = state.doc.revision;
        if (primitive >= 0 && static_cast<std::size_t>(primitive) < primitives.size())
            kept->info =
                mesh_info(state.doc.scene, primitives[static_cast<std::size_t>(primitive)]);
    }
    return kept->info;
}

std::shared_ptr<const PrimitiveIdImage> shown_primitive_ids(AppState& state) {
    const std::shared_ptr<const PreparedFrame> frame = shown_frame(state);
    if (!frame) return nullptr;
    state.view.primitive_ids.request(frame);
    return state.view.primitive_ids.ready(frame.get());
}

}  // namespace jt::view
