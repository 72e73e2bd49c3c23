// Writes small pictures of every kind the image-map loader reads, as the
// image_map fuzzer's seeds: PNG grey, grey+alpha, RGB and RGBA, and a 16-bit
// RGB PNG; baseline JPEG at two qualities; BMP 24- and 32-bit.
#include "jtracer/bmp.hpp"

#include <stb_image_write.h>
#include <zlib.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace {

using Bytes = std::vector<std::uint8_t>;

void save(const std::string& path, const Bytes& bytes) {
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()),
               static_cast<std::streamsize>(bytes.size()));
}

// `channels` bytes a pixel, varied enough for the filters and the DCT to matter.
Bytes pattern(int width, int height, int channels) {
    Bytes samples;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < channels; ++c)
                samples.push_back(static_cast<std::uint8_t>(x * 37 + y * 53 + c * 91));
    return samples;
}

void append(void* context, void* data, int size) {
    auto* out = static_cast<Bytes*>(context);
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    out->insert(out->end(), bytes, bytes + size);
}

void put32(Bytes& out, std::uint32_t value) {
    for (int shift = 24; shift >= 0; shift -= 8)
        out.push_back(static_cast<std::uint8_t>(value >> shift));
}

void chunk(Bytes& png, const char* type, const Bytes& data) {
    put32(png, static_cast<std::uint32_t>(data.size()));
    const std::size_t start = png.size();
    png.insert(png.end(), type, type + 4);
    png.insert(png.end(), data.begin(), data.end());
    put32(png, static_cast<std::uint32_t>(crc32_z(0, png.data() + start, png.size() - start)));
}

// stb_image_write has no 16-bit PNG: one by hand, its rows in a stored
// (uncompressed) deflate block.
Bytes png16(int width, int height) {
    Bytes raw;
    for (int y = 0; y < height; ++y) {
        raw.push_back(0);  // filter: none
        for (int x = 0; x < width * 3; ++x) {
            const auto sample = static_cast<std::uint16_t>(x * 9000 + y * 20000);
            raw.push_back(static_cast<std::uint8_t>(sample >> 8));
            raw.push_back(static_cast<std::uint8_t>(sample));
        }
    }
    Bytes zlib{0x78, 0x01, 0x01};  // deflate, no compression, the final block
    const auto length = static_cast<std::uint16_t>(raw.size());
    for (std::uint16_t v : {length, static_cast<std::uint16_t>(~length)}) {
        zlib.push_back(static_cast<std::uint8_t>(v));
        zlib.push_back(static_cast<std::uint8_t>(v >> 8));
    }
    zlib.insert(zlib.end(), raw.begin(), raw.end());
    put32(zlib, static_cast<std::uint32_t>(adler32_z(1, raw.data(), raw.size())));
    Bytes png{0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    Bytes header;
    put32(header, static_cast<std::uint32_t>(width));
    put32(header, static_cast<std::uint32_t>(height));
    header.insert(header.end(), {16, 2, 0, 0, 0});  // 16 bits, RGB, deflate, adaptive, no interlace
    chunk(png, "IHDR", header);
    chunk(png, "IDAT", zlib);
    chunk(png, "IEND", {});
    return png;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: make_image_seeds DIR\n");
        return 2;
    }
    const std::string dir = argv[1];
    const int width = 5, height = 3;
    for (int channels = 1; channels <= 4; ++channels) {
        Bytes png;
        const Bytes samples = pattern(width, height, channels);
        stbi_write_png_to_func(append, &png, width, height, channels, samples.data(),
                               width * channels);
        save(dir + "/" + std::to_string(channels) + "-channel.png", png);
    }
    for (int quality : {30, 90}) {  // stb writes colour JPEGs only; quality sets the tables
        Bytes jpeg;
        const Bytes samples = pattern(17, 9, 3);  // past one 8x8 block each way
        stbi_write_jpg_to_func(append, &jpeg, 17, 9, 3, samples.data(), quality);
        save(dir + "/quality-" + std::to_string(quality) + ".jpg", jpeg);
    }
    Bytes bmp32;
    const Bytes rgba = pattern(width, height, 4);
    stbi_write_bmp_to_func(append, &bmp32, width, height, 4, rgba.data());
    save(dir + "/32-bit.bmp", bmp32);
    jt::Image8 image(width, height);
    image.rgb = pattern(width, height, 3);
    save(dir + "/24-bit.bmp", jt::encode_bmp(image));
    save(dir + "/16-bit.png", png16(width, height));
    return 0;
}
