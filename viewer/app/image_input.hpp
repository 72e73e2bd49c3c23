#pragma once
// What the keyboard and the mouse do in a frame: the shortcuts (Esc, Space,
// Ctrl+Z, the letters), and the mouse over the image (click to select, drag
// to orbit, pan, move an object or mark a region, the wheel to dolly or zoom).

#include "app/image_place.hpp"
#include "jtracer/region.hpp"

#include <optional>

namespace jt::view {

void handle_shortcuts(AppState& state, FrameState& frame, const ImagePlace& image);
void handle_image_mouse(AppState& state, const ImagePlace& image);
// The region a Ctrl+drag from the press to (x, y) spans, as --region counts it.
std::optional<FrameRegion> dragged_region(const ImageDrag& drag, const ImagePlace& image, float x,
                                          float y);

}  // namespace jt::view
