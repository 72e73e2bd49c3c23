#pragma once
// Reads what the current GL context drew, for --screenshot and the tests.

#include "jtracer/image.hpp"

namespace jt::view {

// The framebuffer's colour, rows bottom-up as in Image8.
Image8 read_framebuffer(int width, int height);

}  // namespace jt::view
