#include "io/jpeg.hpp"

#include <turbojpeg.h>

#include <algorithm>
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

// The frame header, as both the size check and the decoding read it (the
// decoding for the colour space: CMYK samples come out four to a texel).
struct JpegHeader {
    int width = 0;
    int height = 0;
    int colour_space = 0;  // TJCS_...
};

Expected<JpegHeader> read_header(void* handle, std::span<const std::uint8_t> bytes) {
    JpegHeader header;
    int subsampling = 0;
    if (tjDecompressHeader3(handle, bytes.data(), bytes.size(), &header.width, &header.height,
                            &subsampling, &header.colour_space) != 0)
        return Error{unreadable(handle)};
    return header;
}

// Whether a CMYK JPEG's samples are the white its inks leave rather than the
// inks: libjpeg (and so Pillow and the browsers) takes Adobe's APP14 segment
// as the sign, since Adobe's programs, which write most CMYK JPEGs, invert them.
bool inks_inverted(std::span<const std::uint8_t> bytes) {
    return jpeg_segment(bytes, kJpegApp14, "Adobe").has_value();
}

// CMYK samples, 4 bytes a texel, turned into RGB in the same vector's first
// three quarters (each texel is written at or before where it was read).
void cmyk_to_rgb(std::vector<std::uint8_t>& samples, bool inverted) {
    const std::size_t texels = samples.size() / 4;
    for (std::size_t i = 0; i < texels; ++i) {
        const std::uint8_t* in = &samples[4 * i];
        // What white each ink leaves: the sample itself when stored inverted.
        const unsigned left[4] = {inverted ? in[0] : 255u - in[0], inverted ? in[1] : 255u - in[1],
                                  inverted ? in[2] : 255u - in[2], inverted ? in[3] : 255u - in[3]};
        for (int c = 0; c < 3; ++c)
            samples[3 * i + c] = static_cast<std::uint8_t>((left[c] * left[3] + 127) / 255);
    }
    samples.resize(3 * texels);
    // A texture is kept for the whole render: the fourth quarter is given back.
    samples.shrink_to_fit();
}

}  // namespace

std::optional<std::span<const std::uint8_t>> jpeg_segment(std::span<const std::uint8_t> jpeg,
                                                          std::uint8_t wanted,
                                                          std::string_view name) {
    if (jpeg.size() < 4 || !has_jpeg_signature(jpeg)) return std::nullopt;
    std::size_t at = 2;
    while (at + 4 <= jpeg.size()) {
        if (jpeg[at] != 0xFF) return std::nullopt;
        const std::uint8_t marker = jpeg[at + 1];
        if (marker == 0xFF) {  // fill byte
            ++at;
            continue;
        }
        // The picture's data starts (SOS) or ends (EOI): no segment after counts.
        if (marker == 0xDA || marker == 0xD9) return std::nullopt;
        if (marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7)) {  // no length
            at += 2;
            continue;
        }
        const std::size_t length = static_cast<std::size_t>(jpeg[at + 2]) << 8 | jpeg[at + 3];
        if (length < 2 || at + 2 + length > jpeg.size()) return std::nullopt;
        const std::span<const std::uint8_t> data = jpeg.subspan(at + 4, length - 2);
        if (marker == wanted && data.size() >= name.size() &&
            std::equal(name.begin(), name.end(), data.begin(),
                       [](char a, std::uint8_t b) { return static_cast<std::uint8_t>(a) == b; }))
            return data.subspan(name.size());
        at += 2 + length;
    }
    return std::nullopt;
}

bool has_jpeg_signature(std::span<const std::uint8_t> bytes) {
    return bytes.size() >= 2 && bytes[0] == 0xFF && bytes[1] == 0xD8;
}

Expected<JpegSize> read_jpeg_size(std::span<const std::uint8_t> bytes) {
    const Decompressor handle(tjInitDecompress());
    if (!handle) return Error{"cannot start the JPEG decoder"};
    const Expected<JpegHeader> header = read_header(handle.get(), bytes);
    if (!header) return header.error();
    return JpegSize{header->width, header->height};
}

Expected<std::vector<std::uint8_t>> decode_jpeg(std::span<const std::uint8_t> bytes,
                                                JpegSize size) {
    const Decompressor handle(tjInitDecompress());
    if (!handle) return Error{"cannot start the JPEG decoder"};
    const Expected<JpegHeader> header = read_header(handle.get(), bytes);
    if (!header) return header.error();
    // libjpeg-turbo gives a CMYK JPEG's samples only as CMYK.
    const bool cmyk = header->colour_space == TJCS_CMYK || header->colour_space == TJCS_YCCK;
    std::vector<std::uint8_t> samples(static_cast<std::size_t>(size.width) * size.height *
                                      (cmyk ? 4 : 3));
    // A warning stops the decoding too; the scan limit refuses a progressive
    // file of thousands of scans, each of which would cost a pass over the
    // whole picture.
    const int flags = TJFLAG_STOPONWARNING | TJFLAG_LIMITSCANS | TJFLAG_BOTTOMUP;
    if (tjDecompress2(handle.get(), bytes.data(), bytes.size(), samples.data(), size.width, 0,
                      size.height, cmyk ? TJPF_CMYK : TJPF_RGB, flags) != 0)
        return Error{unreadable(handle.get())};
    if (cmyk) cmyk_to_rgb(samples, inks_inverted(bytes));
    return samples;
}

}  // namespace jt
