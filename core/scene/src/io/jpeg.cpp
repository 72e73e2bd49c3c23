#include "io/jpeg.hpp"

#include <turbojpeg.h>

#include <memory>
#include <string>

namespace jt {

namespace {

struct TurboJpegFree {
    void operator()(void* handle) const { tjDestroy(handle); }
};
using Decompressor = std::unique_ptr<void, TurboJpegFree>;

std::string unreadable(void* handle) {
    return std::string("cannot read the JPEG: ") + tjGetErrorStr2(handle);
}

}  // namespace

bool has_jpeg_signature(std::span<const std::uint8_t> bytes) {
    return bytes.size() >= 2 && bytes[0] == 0xFF && bytes[1] == 0xD8;
}

Expected<JpegSize> read_jpeg_size(std::span<const std::uint8_t> bytes) {
    const Decompressor handle(tjInitDecompress());
    if (!handle) return Error{"cannot start the JPEG decoder"};
    JpegSize size;
    int subsampling = 0, colour_space = 0;
    if (tjDecompressHeader3(handle.get(), bytes.data(), bytes.size(), &size.width, &size.height,
                            &subsampling, &colour_space) != 0)
        return Error{unreadable(handle.get())};
    if (colour_space == TJCS_CMYK || colour_space == TJCS_YCCK)
        return Error{"a CMYK JPEG: save the picture as RGB"};
    return size;
}

Expected<std::vector<std::uint8_t>> decode_jpeg(std::span<const std::uint8_t> bytes,
                                                JpegSize size) {
    const Decompressor handle(tjInitDecompress());
    if (!handle) return Error{"cannot start the JPEG decoder"};
    std::vector<std::uint8_t> rgb(static_cast<std::size_t>(size.width) * size.height * 3);
    // A warning stops the decoding too; the scan limit refuses a progressive
    // file of thousands of scans, each of which would cost a pass over the
    // whole picture.
    const int flags = TJFLAG_STOPONWARNING | TJFLAG_LIMITSCANS | TJFLAG_BOTTOMUP;
    if (tjDecompress2(handle.get(), bytes.data(), bytes.size(), rgb.data(), size.width, 0,
                      size.height, TJPF_RGB, flags) != 0)
        return Error{unreadable(handle.get())};
    return rgb;
}

}  // namespace jt
