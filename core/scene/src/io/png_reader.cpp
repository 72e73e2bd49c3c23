#include "io/png_reader.hpp"

#include "jtracer/texture.hpp"

#include <png.h>

#include <csetjmp>
#include <cstring>
#include <string>

namespace jt {

namespace {

struct Source {
    std::span<const std::uint8_t> bytes;
    std::size_t at = 0;
    // libpng's message, or ours, for the one failure that ends the read.
    char message[256] = {};
    bool ended_early = false;
};

void on_error(png_structp png, png_const_charp message) {
    auto* source = static_cast<Source*>(png_get_error_ptr(png));
    std::strncpy(source->message, message ? message : "", sizeof source->message - 1);
    png_longjmp(png, 1);
}

// libpng prints its warnings on stderr unless told otherwise: a picture it
// can read is read without a word, as stb_image read it.
void on_warning(png_structp, png_const_charp) {}

void read_bytes(png_structp png, png_bytep out, png_size_t count) {
    auto* source = static_cast<Source*>(png_get_io_ptr(png));
    if (count > source->bytes.size() - source->at) {
        source->ended_early = true;
        png_error(png, "the file ends early");
    }
    std::memcpy(out, source->bytes.data() + source->at, count);
    source->at += count;
}

struct ReadStruct {
    png_structp png = nullptr;
    png_infop info = nullptr;
    ~ReadStruct() { png_destroy_read_struct(&png, info ? &info : nullptr, nullptr); }
};

// After png_read_info: the transformations that make every PNG 8- or 16-bit
// RGB, and the rows' addresses in `pixels`, bottom row first. Everything that can fail (and
// longjmp) happens in libpng's calls; what is set up here is complete
// between them.
void decode(png_structp png, png_infop info, bool keep_16_bits, PngPixels& pixels,
            std::vector<png_bytep>& rows) {
    const png_uint_32 width = png_get_image_width(png, info);
    const png_uint_32 height = png_get_image_height(png, info);
    const int colour = png_get_color_type(png, info);
    const int depth = png_get_bit_depth(png, info);
    if (colour == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
    if (colour == PNG_COLOR_TYPE_GRAY && depth < 8) png_set_expand_gray_1_2_4_to_8(png);
    if (colour == PNG_COLOR_TYPE_GRAY || colour == PNG_COLOR_TYPE_GRAY_ALPHA)
        png_set_gray_to_rgb(png);
    // Expanding a palette or grey picture turns its tRNS chunk into alpha too.
    if ((colour & PNG_COLOR_MASK_ALPHA) || png_get_valid(png, info, PNG_INFO_tRNS))
        png_set_strip_alpha(png);
    const bool sixteen = depth == 16 && keep_16_bits;
    if (depth == 16 && !sixteen) png_set_strip_16(png);
    if (sixteen) png_set_swap(png);  // PNG's samples are big-endian
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    pixels.width = static_cast<int>(width);
    pixels.height = static_cast<int>(height);
    const std::size_t samples = static_cast<std::size_t>(width) * height * 3;
    std::uint8_t* data = nullptr;
    if (sixteen) {
        pixels.rgb16.resize(samples);
        data = reinterpret_cast<std::uint8_t*>(pixels.rgb16.data());
    } else {
        pixels.rgb8.resize(samples);
        data = pixels.rgb8.data();
    }
    const std::size_t stride = static_cast<std::size_t>(width) * 3 * (sixteen ? 2 : 1);
    if (png_get_rowbytes(png, info) != stride) png_error(png, "unexpected row size");
    rows.resize(height);
    for (png_uint_32 y = 0; y < height; ++y) rows[y] = data + stride * (height - 1 - y);
    png_read_image(png, rows.data());
}

}  // namespace

Expected<PngPixels> read_png_pixels(std::span<const std::uint8_t> bytes, bool keep_16_bits) {
    Source source;
    source.bytes = bytes;
    PngPixels pixels;
    std::vector<png_bytep> rows;
    ReadStruct read;
    read.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &source, on_error, on_warning);
    if (!read.png) return Error{"cannot start the PNG decoder"};
    read.info = png_create_info_struct(read.png);
    if (!read.info) return Error{"cannot start the PNG decoder"};
    if (setjmp(png_jmpbuf(read.png))) {
        if (source.ended_early)
            return Error{"its data ends early (the file is truncated or damaged)"};
        // Out of memory is the program's to report (jtracer/error.hpp).
        if (std::strstr(source.message, "Out of memory") ||
            std::strstr(source.message, "out of memory"))
            throw std::bad_alloc();
        return Error{std::string("its data is damaged (") + source.message + ")"};
    }
    png_set_read_fn(read.png, &source, read_bytes);
    // stb_image checked no CRC, and pictures it read must still read.
    png_set_crc_action(read.png, PNG_CRC_QUIET_USE, PNG_CRC_QUIET_USE);
    png_read_info(read.png, read.info);
    // A few bytes may claim billions of pixels: refused before any is kept.
    const std::uint64_t width = png_get_image_width(read.png, read.info);
    const std::uint64_t height = png_get_image_height(read.png, read.info);
    if (width * height > static_cast<std::uint64_t>(kMaxTextureTexels))
        return Error{"too large (" + std::to_string(width) + "x" + std::to_string(height) +
                     " pixels; at most " + std::to_string(kMaxTextureTexels) + ")"};
    decode(read.png, read.info, keep_16_bits, pixels, rows);
    return pixels;
}

}  // namespace jt
