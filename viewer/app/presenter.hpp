#pragma once
// Shows the render as an OpenGL texture: uploads only the rectangles that
// changed and draws the texture fitted to an area of the window.

#include "jtracer/image.hpp"
#include "model/image_layout.hpp"

#include <optional>

struct ImDrawList;

namespace jt::view {

class Presenter {
  public:
    Presenter() = default;
    ~Presenter();
    Presenter(const Presenter&) = delete;
    Presenter& operator=(const Presenter&) = delete;

    // Sends `changed` (or all of `image` when the size changed or no rect is
    // given) to the texture. Needs a current GL context.
    void upload(const Image8& image, std::optional<PixelRect> changed);
    // Draws the texture at `where` (behind any ImGui window).
    void draw(ImDrawList* draw_list, ScreenRect where) const;

    bool has_image() const { return texture_ != 0 && width_ > 0; }
    int width() const { return width_; }
    int height() const { return height_; }
    unsigned texture() const { return texture_; }
    // Counts texels sent since creation, so tests can check that only changed
    // regions go to the GPU.
    long long texels_uploaded() const { return texels_uploaded_; }
    // Reads the whole texture back (rows bottom-up, like Image8).
    Image8 read_texture() const;

  private:
    unsigned texture_ = 0;
    int width_ = 0;
    int height_ = 0;
    long long texels_uploaded_ = 0;
};

}  // namespace jt::view
