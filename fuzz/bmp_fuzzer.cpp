// libFuzzer target: the BMP decoder on arbitrary bytes.
#include "invariants.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    jt::fuzz::abort_if_broken(jt::fuzz::check_bmp_bytes({data, size}));
    return 0;
}
