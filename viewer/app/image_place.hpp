#pragma once
// Where the frame puts the image, shared by the input over it (image_input.hpp)
// and what is drawn on it (image_drawing.hpp).

#include "app/viewer_frame.hpp"
#include "model/image_layout.hpp"

namespace jt::view {

// Where the image is this frame: the area it may use, where it is drawn
// (reaching past the area when zoomed in), its size in pixels.
struct ImagePlace {
    ScreenRect area;
    ScreenRect where;
    int width = 0, height = 0;
    float framebuffer_scale = 1.0f;
    // The window point is on the part of the image that shows.
    bool shows(float x, float y) const { return area.contains(x, y) && where.contains(x, y); }
};

inline ImagePlace place_in_area(const AppState& state, const FrameState& frame, ScreenRect area,
                                float framebuffer_scale) {
    const int w = frame.presenter.width(), h = frame.presenter.height();
    return {area, place_image(w, h, area, framebuffer_scale, state.view.image_view), w, h,
            framebuffer_scale};
}

// Zooms the image one step in (steps > 0) or out about the mouse, or the
// area's centre when the mouse is not over the image; or to one image pixel
// a screen pixel.
void zoom_step(AppState& state, const ImagePlace& image, int steps);
void zoom_actual_pixels(AppState& state, const ImagePlace& image);

}  // namespace jt::view
