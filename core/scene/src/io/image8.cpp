#include "io/reserve_records.hpp"
#include "jtracer/image.hpp"

namespace jt {

// An image is megabytes filled at once: its pages come huge when they can.
Image8::Image8(int w, int h)
    : width(w), height(h), rgb(zeroed_records<std::uint8_t>(static_cast<std::size_t>(w) * h * 3)) {}

}  // namespace jt
