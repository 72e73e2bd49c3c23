// Writes a few small BMPs with the core's own encoder, as the BMP fuzzer's seeds:
// odd widths (row padding), one pixel, and a top-down variant.
#include "jtracer/bmp.hpp"

#include <cstdio>
#include <fstream>
#include <string>

namespace {

jt::Image8 gradient(int width, int height) {
    jt::Image8 image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            std::uint8_t* p = image.pixel(x, y);
            p[0] = static_cast<std::uint8_t>(x * 37);
            p[1] = static_cast<std::uint8_t>(y * 53);
            p[2] = static_cast<std::uint8_t>(x ^ y);
        }
    return image;
}

void save(const std::string& path, const std::vector<std::uint8_t>& bytes) {
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()),
               static_cast<std::streamsize>(bytes.size()));
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: make_bmp_seeds DIR\n");
        return 2;
    }
    const std::string dir = argv[1];
    save(dir + "/1x1.bmp", jt::encode_bmp(gradient(1, 1)));
    save(dir + "/3x2.bmp", jt::encode_bmp(gradient(3, 2)));
    save(dir + "/5x4.bmp", jt::encode_bmp(gradient(5, 4)));
    // The same image stored top-down: a negative height and the rows reversed.
    std::vector<std::uint8_t> top_down = jt::encode_bmp(gradient(5, 4));
    const std::size_t header = 54, stride = 16;
    std::vector<std::uint8_t> flipped(top_down.begin(), top_down.begin() + header);
    for (int row = 3; row >= 0; --row)
        flipped.insert(flipped.end(), top_down.begin() + header + row * stride,
                       top_down.begin() + header + (row + 1) * stride);
    const auto minus_four = static_cast<std::uint32_t>(-4);
    for (int i = 0; i < 4; ++i) flipped[22 + i] = static_cast<std::uint8_t>(minus_four >> (8 * i));
    save(dir + "/5x4-top-down.bmp", flipped);
    return 0;
}
