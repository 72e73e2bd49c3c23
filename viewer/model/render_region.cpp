#include "model/render_region.hpp"

#include "model/app_actions.hpp"

#include <algorithm>
#include <cmath>

namespace jt::view {

std::optional<FrameRegion> region_spanning(const ImagePoint& a, const ImagePoint& b, int image_w,
                                           int image_h) {
    if (image_w <= 0 || image_h <= 0) return std::nullopt;
    const auto column = [&](double x, bool end) {
        const int c = static_cast<int>(end ? std::ceil(x) : std::floor(x));
        return std::clamp(c, 0, image_w);
    };
    const auto row = [&](double y, bool end) {
        const int r = static_cast<int>(end ? std::ceil(y) : std::floor(y));
        return std::clamp(r, 0, image_h);
    };
    // The pixels in image rows (from the bottom), then as --region counts them (from the top).
    const PixelRect pixels{column(std::min(a.x, b.x), false), row(std::min(a.y, b.y), false),
                           column(std::max(a.x, b.x), true), row(std::max(a.y, b.y), true)};
    const FrameRegion region = to_frame_region(pixels, image_h);
    if (region.width() <= 0 || region.height() <= 0) return std::nullopt;
    return region;
}

namespace {

// The view a render of `request` shows: the free camera, or the scene camera.
std::optional<ViewState::RegionView> view_of(const AppState& state, const RenderRequest& request) {
    Camera camera;
    if (request.free_camera) {
        camera = camera_from(*request.free_camera, "");
    } else {
        const auto& cameras = state.doc.scene.cameras;
        const int index = request.options.camera;
        if (index < 0 || static_cast<std::size_t>(index) >= cameras.size()) return std::nullopt;
        camera = cameras[static_cast<std::size_t>(index)];
    }
    camera.name.clear();
    return ViewState::RegionView{camera, request.options.width, request.options.height};
}

}  // namespace

void set_render_region(AppState& state, const FrameRegion& region) {
    state.view.render_region = region;
    // The image shows the view of the render under way or last finished.
    std::string note;
    if (const std::optional<RenderRequest> now = render_request(state, note))
        state.view.region_view = view_of(state, *now);
    state.message = "Rendering region " + format_frame_region(region) +
                    " alone (as jtracer-cli --region " + format_frame_region(region) + ")";
}

void clear_render_region(AppState& state) {
    if (!state.view.render_region) return;
    state.view.render_region.reset();
    state.message = "Region cleared: the whole image renders";
}

bool clear_region_for_new_view(AppState& state, const RenderRequest& next) {
    if (!state.view.render_region) {
        state.view.region_view.reset();
        return false;
    }
    const std::optional<ViewState::RegionView> view = view_of(state, next);
    // The first render with the region: the rest shows this view.
    if (!state.view.region_view) {
        state.view.region_view = view;
        return false;
    }
    if (view == state.view.region_view) return false;
    state.view.render_region.reset();
    state.view.region_view.reset();
    state.message = "The view changed: the region is cleared and the whole image renders";
    return true;
}

std::optional<PixelRect> render_region_rect(const ViewState& view, int width, int height) {
    if (!view.render_region || !check_region_in_frame(*view.render_region, width, height))
        return std::nullopt;
    return to_image_rect(*view.render_region, height);
}

}  // namespace jt::view
