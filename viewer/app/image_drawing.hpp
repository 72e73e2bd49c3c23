#pragma once
// What a frame draws over the image area: the image (live, A, split or the
// difference), the render region, the image toolbar (zoom, region, A/B
// compare) and the pixel inspector's box.

#include "app/image_place.hpp"

#include <imgui.h>

#include <string>

namespace jt::view {

// Keeps the compare texture holding what the view shows: A, or the difference
// of A and the live image (again whenever the live image changed).
void update_compare_texture(const AppState& state, FrameState& frame, bool display_changed);
// The live image, or A and the difference as the compare mode asks.
void draw_image(const AppState& state, const FrameState& frame, ImDrawList* draw_list,
                const ImagePlace& image);
// The render region over the image, and the one being dragged.
void draw_regions(const AppState& state, ImDrawList* draw_list, const ImagePlace& image);
// The image view's controls, over the image's top left corner.
void image_toolbar(AppState& state, const FrameState& frame, const ImagePlace& image);
// Hovering the image (not dragging) shows what the pixel under the mouse
// holds, in a box in the image's corner when it fits (inspector_box_fits).
void inspect_hovered_pixel(AppState& state, const ImagePlace& image);
// Whether the inspector's box holding `text` fits in the image area; when not
// (a narrow area at a large scale) the status line shows the text instead:
// the box covered a fifth of the image and reached over the panel.
bool inspector_box_fits(const std::string& text, const ScreenRect& area);

}  // namespace jt::view
