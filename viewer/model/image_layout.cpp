#include "image_layout.hpp"

#include <cmath>

namespace jt::view {

ScreenRect place_image(int image_w, int image_h, ScreenRect area, float framebuffer_scale,
                       FitMode mode) {
    if (image_w <= 0 || image_h <= 0 || area.width() <= 0 || area.height() <= 0) return {};
    const float aspect = static_cast<float>(image_w) / static_cast<float>(image_h);
    float w = 0, h = 0;
    if (mode == FitMode::actual_pixels) {
        const float scale = framebuffer_scale > 0 ? framebuffer_scale : 1.0f;
        w = static_cast<float>(image_w) / scale;
        h = static_cast<float>(image_h) / scale;
    } else if (area.width() / area.height() > aspect) {
        h = area.height();
        w = h * aspect;
    } else {
        w = area.width();
        h = w / aspect;
    }
    // Snap to whole framebuffer pixels so a 1:1 image is not resampled.
    const float s = framebuffer_scale > 0 ? framebuffer_scale : 1.0f;
    const float x0 = std::floor((area.x0 + (area.width() - w) * 0.5f) * s) / s;
    const float y0 = std::floor((area.y0 + (area.height() - h) * 0.5f) * s) / s;
    return {x0, y0, x0 + w, y0 + h};
}

std::optional<ImagePoint> window_to_image(const ScreenRect& where, int image_w, int image_h,
                                          float x, float y) {
    if (image_w <= 0 || image_h <= 0 || where.width() <= 0 || where.height() <= 0) return {};
    if (x < where.x0 || x >= where.x1 || y < where.y0 || y >= where.y1) return {};
    return ImagePoint{(x - where.x0) / where.width() * image_w,
                      (where.y1 - y) / where.height() * image_h};
}

WindowPoint image_to_window(const ScreenRect& where, int image_w, int image_h,
                            const ImagePoint& p) {
    if (image_w <= 0 || image_h <= 0) return {};
    return {where.x0 + static_cast<float>(p.x / image_w) * where.width(),
            where.y1 - static_cast<float>(p.y / image_h) * where.height()};
}

}  // namespace jt::view
