#pragma once
// Render region: the user's rectangle of the image that renders alone, with
// jtracer-cli's --region semantics (region.hpp: X0,Y0,X1,Y1, half-open, from
// the top-left). The rest of the image keeps the pixels it showed.

#include "jtracer/region.hpp"
#include "model/app_state.hpp"

#include <optional>

namespace jt::view {

// The whole pixels a drag from image point `a` to `b` covers (image points from
// the bottom left, as pick.hpp counts them), inside an `image_w` x `image_h`
// image, as --region counts them; nothing when it covers no pixel.
std::optional<FrameRegion> region_spanning(const ImagePoint& a, const ImagePoint& b, int image_w,
                                           int image_h);

// Renders only `region` from now on (each edit re-renders it alone), until cleared.
void set_render_region(AppState& state, const FrameRegion& region);
void clear_render_region(AppState& state);

// Before a render of `next` starts: with a region set, the rest of the image
// shows the view of the renders before; when `next` shows another view (the
// camera moved, another camera, another size) the region is cleared, so that
// the whole image renders from the new view and no pixel shows an old one.
// True when it was.
bool clear_region_for_new_view(AppState& state, const RenderRequest& next);

// The region the render is limited to, in Image8 coordinates: state.view.render_region
// while it lies inside a `width` x `height` frame, else nothing.
std::optional<PixelRect> render_region_rect(const ViewState& view, int width, int height);

}  // namespace jt::view
