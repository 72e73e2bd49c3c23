#pragma once
// Where the image goes in the window: plain geometry, shared by the frame
// code (which draws there) and the tests (which click there).

#include "jtracer/pick.hpp"

#include <optional>

namespace jt::view {

// An axis-aligned rectangle in window units (ImGui's coordinates, y down).
struct ScreenRect {
    float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    float width() const { return x1 - x0; }
    float height() const { return y1 - y0; }
};

enum class FitMode { fit, actual_pixels };

// Where an image of `image_w` x `image_h` pixels goes inside `area`, centred,
// aspect kept. `fit` scales it to fill the area; `actual_pixels` shows one image
// pixel per framebuffer pixel (HiDPI: `framebuffer_scale` framebuffer pixels per
// window unit).
ScreenRect place_image(int image_w, int image_h, ScreenRect area, float framebuffer_scale,
                       FitMode mode);

// The image point under window point (x, y), for an image of `image_w` x
// `image_h` pixels drawn at `where` (image pixels from the bottom left
// corner, as pick.hpp counts them), or nothing outside the image.
std::optional<ImagePoint> window_to_image(const ScreenRect& where, int image_w, int image_h,
                                          float x, float y);

struct WindowPoint {
    float x = 0, y = 0;
};
// Where image point `p` is drawn in the window.
WindowPoint image_to_window(const ScreenRect& where, int image_w, int image_h, const ImagePoint& p);

}  // namespace jt::view
