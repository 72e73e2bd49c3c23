// libFuzzer target: the .jts parser, validator and serializer on arbitrary bytes.
#include "invariants.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    jt::fuzz::abort_if_broken(
        jt::fuzz::check_scene_text({reinterpret_cast<const char*>(data), size}));
    return 0;
}
