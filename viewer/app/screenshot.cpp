#include "app/screenshot.hpp"

#include "app/gl/gl.hpp"

namespace jt::view {

Image8 read_framebuffer(int width, int height) {
    Image8 image(width, height);
    if (width <= 0 || height <= 0) return image;
    glFinish();
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    // glReadPixels returns the bottom row first, which is Image8's order.
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, image.rgb.data());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    return image;
}

}  // namespace jt::view
