#pragma once
// What the pixel under the mouse holds: its position as jtracer-cli's
// --region counts pixels (from the top-left corner, docs/language.md §7.3 has
// rows from the bottom), its bytes, and the primitive its ray meets first.

#include "model/app_state.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <string>

namespace jt::view {

struct PixelReport {
    int x = 0, y = 0;  // from the top-left corner, as --region counts
    std::array<std::uint8_t, 3> rgb{};
    std::optional<PickedPrimitive> hit;
    // The pixel shows a render before the current one (whose first pass is
    // not shown yet): what the current view's ray meets there is not what
    // the pixel shows, and `hit` is left empty.
    bool earlier_render = false;
    // The pixel shows a render of the scene before its objects changed (the
    // scene as edited is not rendered: too large, invalid): there is no
    // frame to pick in, and `hit` is left empty.
    bool earlier_scene = false;
};

// Pixel (x, y) of state.display (Image8 coordinates: y from the bottom), or
// nothing outside it.
std::optional<PixelReport> inspect_pixel(AppState& state, int x, int y);

// "x 12, y 30   RGB 230 51 26 = 0.902 0.200 0.102   sphere 2 at 5.83", on
// two lines; "background" when the ray meets nothing; for a pixel of an
// earlier render, that it is rendering, and of an earlier scene, that it is.
std::string describe(const PixelReport& report, const Scene& scene);

}  // namespace jt::view
