#pragma once
// Where the image goes in the window: plain geometry, shared by the frame
// code (which draws there) and the tests (which click there). The image view's
// zoom and pan live here and only here: picking, the pixel inspector, the
// light markers and the selection outline all go through place_image and the
// two mappings below, so they follow the view.

#include "jtracer/pick.hpp"

#include <optional>

namespace jt::view {

// An axis-aligned rectangle in window units (ImGui's coordinates, y down).
struct ScreenRect {
    float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    float width() const { return x1 - x0; }
    float height() const { return y1 - y0; }
    bool contains(float x, float y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
};

// How the user looks at the image, independent of the camera: fitted to the
// area, or at a zoom of their choosing moved by a pan.
struct ImageView {
    bool fit = true;  // the whole image, as large as the area allows; follows the area's size
    // Framebuffer pixels per image pixel when not fitted: 1 is actual pixels.
    float zoom = 1.0f;
    // The image centre's offset from the area's centre, window units.
    float pan_x = 0.0f, pan_y = 0.0f;
    bool operator==(const ImageView&) const = default;
};

inline constexpr float kMinImageZoom = 1.0f / 16.0f;
inline constexpr float kMaxImageZoom = 64.0f;

// Actual pixels: one image pixel per framebuffer pixel, centred.
inline ImageView actual_pixels_view() {
    return ImageView{false, 1.0f, 0.0f, 0.0f};
}

// The zoom `view` shows an image of `image_w` x `image_h` pixels at inside
// `area` (framebuffer pixels per image pixel; HiDPI: `framebuffer_scale`
// framebuffer pixels per window unit).
float shown_zoom(int image_w, int image_h, ScreenRect area, float framebuffer_scale,
                 const ImageView& view);

// Where the image goes: fitted and centred, or at the view's zoom and pan. The
// rectangle may reach past `area` when zoomed in (the frame code clips to it);
// its corner is on a whole framebuffer pixel so that each image pixel covers
// the same framebuffer pixels.
ScreenRect place_image(int image_w, int image_h, ScreenRect area, float framebuffer_scale,
                       const ImageView& view);

// The view zoomed to `zoom` (clamped to kMinImageZoom..kMaxImageZoom) keeping
// the image point under window point (x, y) where it is, as far as the pan's
// clamp allows.
ImageView zoom_view_to(const ImageView& view, int image_w, int image_h, ScreenRect area,
                       float framebuffer_scale, float zoom, float x, float y);
// The next power-of-two zoom above (`steps` > 0) or below the shown one,
// `steps` times, about (x, y): the +/- keys, so that zoomed-in pixels stay squares
// of whole framebuffer pixels.
ImageView zoom_view_step(const ImageView& view, int image_w, int image_h, ScreenRect area,
                         float framebuffer_scale, int steps, float x, float y);
// The view moved by (dx, dy) window units.
ImageView pan_view(const ImageView& view, int image_w, int image_h, ScreenRect area,
                   float framebuffer_scale, float dx, float dy);
// The view with its pan kept where the image cannot be lost: an image smaller
// than the area along an axis is centred on it, a larger one always covers it.
ImageView clamp_view(const ImageView& view, int image_w, int image_h, ScreenRect area,
                     float framebuffer_scale);

// The image point under window point (x, y), for an image of `image_w` x
// `image_h` pixels drawn at `where` (image pixels from the bottom left
// corner, as pick.hpp counts them), or nothing outside the image.
std::optional<ImagePoint> window_to_image(const ScreenRect& where, int image_w, int image_h,
                                          float x, float y);

// The same for any window point, moved onto the image's nearest edge when
// outside it (a drag that ends past the image).
ImagePoint window_to_image_clamped(const ScreenRect& where, int image_w, int image_h, float x,
                                   float y);

// The same for any window point, not moved: outside the image it is outside
// [0, image_w) x [0, image_h) (a drag that moves an object on past the edge).
ImagePoint window_to_image_plane(const ScreenRect& where, int image_w, int image_h, float x,
                                 float y);

struct WindowPoint {
    float x = 0, y = 0;
};
// Where image point `p` is drawn in the window.
WindowPoint image_to_window(const ScreenRect& where, int image_w, int image_h, const ImagePoint& p);

}  // namespace jt::view
