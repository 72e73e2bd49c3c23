#include "render_region.hpp"

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
    // Image rows count from the bottom, --region's from the top.
    const auto row = [&](double y, bool end) {
        const int r = static_cast<int>(end ? std::ceil(image_h - y) : std::floor(image_h - y));
        return std::clamp(r, 0, image_h);
    };
    const FrameRegion region{column(std::min(a.x, b.x), false), row(std::max(a.y, b.y), false),
                             column(std::max(a.x, b.x), true), row(std::min(a.y, b.y), true)};
    if (region.width() <= 0 || region.height() <= 0) return std::nullopt;
    return region;
}

void set_render_region(AppState& state, const FrameRegion& region) {
    state.render_region = region;
    state.message = "Rendering region " + format_frame_region(region) +
                    " alone (as jtracer-cli --region " + format_frame_region(region) + ")";
}

void clear_render_region(AppState& state) {
    if (!state.render_region) return;
    state.render_region.reset();
    state.message = "Region cleared: the whole image renders";
}

std::optional<PixelRect> render_region_rect(const AppState& state, int width, int height) {
    if (!state.render_region || !check_region_in_frame(*state.render_region, width, height))
        return std::nullopt;
    return to_image_rect(*state.render_region, height);
}

}  // namespace jt::view
