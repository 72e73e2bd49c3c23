#include "model/ab_compare.hpp"

#include "jtracer/image_diff.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace jt::view {

void snapshot_a(AppState& state) {
    if (state.display.width <= 0) {
        state.message = "No image to keep as A yet";
        return;
    }
    state.compare.a = state.display;
    ++state.compare.a_version;
    if (state.compare.mode == CompareMode::live) state.compare.mode = CompareMode::split;
    state.message = "Kept the image as A: the split shows A left of the line, live right";
}

void clear_snapshot_a(AppState& state) {
    state.compare.a.reset();
    ++state.compare.a_version;
    state.compare.mode = CompareMode::live;
}

bool comparable(const AppState& state) {
    const std::optional<Image8>& a = state.compare.a;
    return a && a->width == state.display.width && a->height == state.display.height &&
           a->width > 0;
}

int split_column(const AppState& state) {
    const int w = state.display.width;
    return std::clamp(static_cast<int>(std::lround(state.compare.split * w)), 0, w);
}

CompareDifference compare_difference(const AppState& state) {
    if (!comparable(state)) return {};
    ImageDiff diff = diff_images(*state.compare.a, state.display);
    char summary[128];
    if (std::isinf(diff.psnr))
        std::snprintf(summary, sizeof summary, "identical");
    else
        std::snprintf(summary, sizeof summary,
                      "max difference %d, %.1f%% of pixels differ, PSNR %.1f dB",
                      diff.max_channel_difference, diff.percent_over, diff.psnr);
    return {std::move(diff.image), summary};
}

}  // namespace jt::view
