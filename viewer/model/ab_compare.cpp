#include "model/ab_compare.hpp"

#include "jtracer/image_diff.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace jt::view {

void snapshot_a(AppState& state) {
    if (state.render.display.width <= 0) {
        state.message = "No image to keep as A yet";
        return;
    }
    state.view.compare.a = state.render.display;
    ++state.view.compare.a_version;
    if (state.view.compare.mode == CompareMode::live) state.view.compare.mode = CompareMode::split;
    state.message = "Kept the image as A: the split shows A left of the line, live right";
}

void clear_snapshot_a(CompareState& compare) {
    compare.a.reset();
    ++compare.a_version;
    compare.mode = CompareMode::live;
}

bool comparable(const CompareState& compare, const Image8& display) {
    const std::optional<Image8>& a = compare.a;
    return a && a->width == display.width && a->height == display.height && a->width > 0;
}

int split_column(const CompareState& compare, const Image8& display) {
    const int w = display.width;
    return std::clamp(static_cast<int>(std::lround(compare.split * w)), 0, w);
}

CompareDifference compare_difference(const CompareState& compare, const Image8& display) {
    if (!comparable(compare, display)) return {};
    ImageDiff diff = diff_images(*compare.a, display);
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
