#pragma once
// The selection drawn over the image, never into it: the selected primitive's
// pixels tinted and outlined (a texture made from the primitive ids of the
// shown frame), and every light as a small marker at its projected position.

#include "model/app_state.hpp"
#include "model/image_layout.hpp"

#include <memory>

struct ImDrawList;

namespace jt::view {

class SelectionOverlay {
  public:
    SelectionOverlay() = default;
    ~SelectionOverlay();
    SelectionOverlay(const SelectionOverlay&) = delete;
    SelectionOverlay& operator=(const SelectionOverlay&) = delete;

    // Draws the outline of the selected primitive and the light markers over
    // the image drawn at `where`. Needs a current GL context.
    void draw(AppState& state, ImDrawList* draw_list, const ScreenRect& where, int image_w,
              int image_h);
    // How many pixels the last draw marked as the selected primitive (for tests).
    int outlined_pixels() const { return outlined_; }

  private:
    void rebuild(const PrimitiveIdImage& ids, int primitive);

    unsigned texture_ = 0;
    std::shared_ptr<const PrimitiveIdImage> ids_;  // what the texture was made from
    int primitive_ = -1;
    int outlined_ = 0;
};

// The radius of a light's marker, in window units: also how near a click
// must be to select it.
float light_marker_radius();

}  // namespace jt::view
