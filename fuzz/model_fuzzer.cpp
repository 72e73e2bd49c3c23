// libFuzzer target: the model loader (read_model, through Assimp) on arbitrary
// bytes. The first byte picks the file's extension, which is how Assimp picks
// its importer (fuzz/invariants.hpp, model_extensions); the rest is the file.
#include "invariants.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    jt::fuzz::abort_if_broken(jt::fuzz::check_model_bytes({data, size}));
    return 0;
}
