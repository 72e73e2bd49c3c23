// libFuzzer target: the image-map loader (PNG, JPEG, BMP through stb_image) on
// arbitrary bytes, as a scene's image_map file would give it.
#include "invariants.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    jt::fuzz::abort_if_broken(jt::fuzz::check_texture_bytes({data, size}));
    return 0;
}
