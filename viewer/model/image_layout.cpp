#include "model/image_layout.hpp"

#include <algorithm>
#include <cmath>

namespace jt::view {

namespace {

float positive_scale(float framebuffer_scale) {
    return framebuffer_scale > 0 ? framebuffer_scale : 1.0f;
}

bool placeable(int image_w, int image_h, ScreenRect area) {
    return image_w > 0 && image_h > 0 && area.width() > 0 && area.height() > 0;
}

float centre_x(ScreenRect r) {
    return (r.x0 + r.x1) * 0.5f;
}
float centre_y(ScreenRect r) {
    return (r.y0 + r.y1) * 0.5f;
}

// The pan along one axis that keeps an image `size` long visible in an area
// `room` long.
float clamp_pan(float pan, float size, float room) {
    const float slack = std::max(0.0f, (size - room) * 0.5f);
    return std::clamp(pan, -slack, slack);
}

}  // namespace

float shown_zoom(int image_w, int image_h, ScreenRect area, float framebuffer_scale,
                 const ImageView& view) {
    if (!placeable(image_w, image_h, area)) return 1.0f;
    if (!view.fit) return std::clamp(view.zoom, kMinImageZoom, kMaxImageZoom);
    const float s = positive_scale(framebuffer_scale);
    return std::min(area.width() / image_w, area.height() / image_h) * s;
}

ScreenRect place_image(int image_w, int image_h, ScreenRect area, float framebuffer_scale,
                       const ImageView& view) {
    if (!placeable(image_w, image_h, area)) return {};
    const float s = positive_scale(framebuffer_scale);
    const float units_per_pixel = shown_zoom(image_w, image_h, area, s, view) / s;
    const float w = image_w * units_per_pixel, h = image_h * units_per_pixel;
    const float pan_x = view.fit ? 0.0f : clamp_pan(view.pan_x, w, area.width());
    const float pan_y = view.fit ? 0.0f : clamp_pan(view.pan_y, h, area.height());
    // Snap to whole framebuffer pixels so a 1:1 or 2:1 image is not resampled.
    const float x0 = std::floor((centre_x(area) + pan_x - w * 0.5f) * s) / s;
    const float y0 = std::floor((centre_y(area) + pan_y - h * 0.5f) * s) / s;
    return {x0, y0, x0 + w, y0 + h};
}

ImageView clamp_view(const ImageView& view, int image_w, int image_h, ScreenRect area,
                     float framebuffer_scale) {
    if (view.fit || !placeable(image_w, image_h, area)) return view;
    ImageView out = view;
    out.zoom = std::clamp(view.zoom, kMinImageZoom, kMaxImageZoom);
    const float units_per_pixel = out.zoom / positive_scale(framebuffer_scale);
    out.pan_x = clamp_pan(view.pan_x, image_w * units_per_pixel, area.width());
    out.pan_y = clamp_pan(view.pan_y, image_h * units_per_pixel, area.height());
    return out;
}

ImageView zoom_view_to(const ImageView& view, int image_w, int image_h, ScreenRect area,
                       float framebuffer_scale, float zoom, float x, float y) {
    if (!placeable(image_w, image_h, area)) return view;
    const ScreenRect before = place_image(image_w, image_h, area, framebuffer_scale, view);
    // Where (x, y) is across the image now, as fractions of its size.
    const float u = (x - before.x0) / before.width(), v = (y - before.y0) / before.height();
    ImageView out{false, std::clamp(zoom, kMinImageZoom, kMaxImageZoom), 0.0f, 0.0f};
    const float units_per_pixel = out.zoom / positive_scale(framebuffer_scale);
    const float w = image_w * units_per_pixel, h = image_h * units_per_pixel;
    out.pan_x = x - u * w + w * 0.5f - centre_x(area);
    out.pan_y = y - v * h + h * 0.5f - centre_y(area);
    return clamp_view(out, image_w, image_h, area, framebuffer_scale);
}

ImageView zoom_view_step(const ImageView& view, int image_w, int image_h, ScreenRect area,
                         float framebuffer_scale, int steps, float x, float y) {
    const float now = shown_zoom(image_w, image_h, area, framebuffer_scale, view);
    // The power of two next to `now` in the step's direction (a fitted zoom
    // between two goes to either, never stays).
    const float exponent = std::log2(now);
    const float rounded = steps > 0 ? std::floor(exponent + 1e-4f) : std::ceil(exponent - 1e-4f);
    const float zoom = std::exp2(rounded + static_cast<float>(steps));
    return zoom_view_to(view, image_w, image_h, area, framebuffer_scale, zoom, x, y);
}

ImageView pan_view(const ImageView& view, int image_w, int image_h, ScreenRect area,
                   float framebuffer_scale, float dx, float dy) {
    ImageView out = view;
    if (out.fit) {
        out = ImageView{false, shown_zoom(image_w, image_h, area, framebuffer_scale, view), 0, 0};
    }
    out.pan_x += dx;
    out.pan_y += dy;
    return clamp_view(out, image_w, image_h, area, framebuffer_scale);
}

ImagePoint window_to_image_plane(const ScreenRect& where, int image_w, int image_h, float x,
                                 float y) {
    if (image_w <= 0 || image_h <= 0 || where.width() <= 0 || where.height() <= 0) return {};
    return ImagePoint{(x - where.x0) / where.width() * image_w,
                      (where.y1 - y) / where.height() * image_h};
}

std::optional<ImagePoint> window_to_image(const ScreenRect& where, int image_w, int image_h,
                                          float x, float y) {
    if (image_w <= 0 || image_h <= 0 || where.width() <= 0 || where.height() <= 0) return {};
    if (!where.contains(x, y)) return {};
    return window_to_image_plane(where, image_w, image_h, x, y);
}

ImagePoint window_to_image_clamped(const ScreenRect& where, int image_w, int image_h, float x,
                                   float y) {
    if (image_w <= 0 || image_h <= 0 || where.width() <= 0 || where.height() <= 0) return {};
    const double u = std::clamp((x - where.x0) / where.width(), 0.0f, 1.0f);
    const double v = std::clamp((where.y1 - y) / where.height(), 0.0f, 1.0f);
    return ImagePoint{u * image_w, v * image_h};
}

WindowPoint image_to_window(const ScreenRect& where, int image_w, int image_h,
                            const ImagePoint& p) {
    if (image_w <= 0 || image_h <= 0) return {};
    return {where.x0 + static_cast<float>(p.x / image_w) * where.width(),
            where.y1 - static_cast<float>(p.y / image_h) * where.height()};
}

}  // namespace jt::view
