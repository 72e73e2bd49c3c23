// What reading a large picture costs in memory: the peak resident size of
// `jtracer-cli --check` on a scene whose sky map is a 16-bit PNG or a BMP,
// above the same check with a 1x1 map, counted in copies of the texels.

#include "common/files.hpp"
#include "common/scratch_dir.hpp"
#include "jtracer/bmp.hpp"
#include "jtracer/image.hpp"

#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <string>
#include <tuple>
#include <vector>

namespace jt {
namespace {

void put32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int shift : {24, 16, 8, 0}) out.push_back(static_cast<std::uint8_t>(v >> shift));
}

std::uint32_t crc32(const std::uint8_t* p, std::size_t n) {
    std::uint32_t c = 0xffffffffu;
    for (std::size_t i = 0; i < n; ++i) {
        c ^= p[i];
        for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
    }
    return ~c;
}

void chunk(std::vector<std::uint8_t>& out, const char* type,
           const std::vector<std::uint8_t>& data) {
    put32(out, static_cast<std::uint32_t>(data.size()));
    const std::size_t start = out.size();
    out.insert(out.end(), type, type + 4);
    out.insert(out.end(), data.begin(), data.end());
    put32(out, crc32(out.data() + start, out.size() - start));
}

// A 16-bit RGB PNG of noise-like samples, its image data in stored
// (uncompressed) deflate blocks: no compressor needed, and the file is as
// large as the texels, as a photograph's nearly is.
std::vector<std::uint8_t> png16(std::uint32_t width, std::uint32_t height) {
    std::vector<std::uint8_t> raw;
    raw.reserve((width * 6 + 1) * static_cast<std::size_t>(height));
    std::uint32_t state = 12345;
    for (std::uint32_t y = 0; y < height; ++y) {
        raw.push_back(0);  // no filter
        for (std::uint32_t i = 0; i < width * 6; ++i) {
            state = state * 1664525u + 1013904223u;
            raw.push_back(static_cast<std::uint8_t>(state >> 24));
        }
    }
    std::vector<std::uint8_t> z{0x78, 0x01};
    std::uint32_t a = 1, b = 0;
    for (const std::uint8_t byte : raw) {
        a = (a + byte) % 65521;
        b = (b + a) % 65521;
    }
    for (std::size_t at = 0; at < raw.size(); at += 65535) {
        const std::size_t n = std::min<std::size_t>(65535, raw.size() - at);
        z.push_back(at + n == raw.size() ? 1 : 0);
        z.push_back(static_cast<std::uint8_t>(n));
        z.push_back(static_cast<std::uint8_t>(n >> 8));
        z.push_back(static_cast<std::uint8_t>(~n));
        z.push_back(static_cast<std::uint8_t>(~n >> 8));
        z.insert(z.end(), raw.begin() + static_cast<std::ptrdiff_t>(at),
                 raw.begin() + static_cast<std::ptrdiff_t>(at + n));
    }
    put32(z, (b << 16) | a);
    std::vector<std::uint8_t> out{0x89, 'P', 'N', 'G', 0x0d, 0x0a, 0x1a, 0x0a};
    std::vector<std::uint8_t> header;
    put32(header, width);
    put32(header, height);
    header.insert(header.end(), {16, 2, 0, 0, 0});
    chunk(out, "IHDR", header);
    chunk(out, "IDAT", z);
    chunk(out, "IEND", {});
    return out;
}

// The peak resident size, in bytes, of `jtracer-cli --check scene` in `dir`.
long peak_of_check(const std::filesystem::path& dir, const std::string& scene) {
    const pid_t child = ::fork();
    if (child == 0) {
        if (::chdir(dir.c_str()) != 0) ::_exit(126);
        ::execl(JT_CLI, JT_CLI, "--check", scene.c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    int status = 0;
    struct rusage usage {};
    if (child < 0 || ::wait4(child, &status, 0, &usage) != child || !WIFEXITED(status) ||
        WEXITSTATUS(status) != 0)
        return -1;
    return usage.ru_maxrss * 1024L;
}

class ImageMemory : public test::ScratchTest {
  protected:
    // How far the peak of checking a scene whose sky map is `big` rises
    // above the same check with `small`, both files written in `dir`
    // already; -1 when a check fails.
    long extra_peak(const std::string& big, const std::string& small) {
        for (const std::string& name : {big, small})
            test::write_file(dir / (name + ".jts"),
                             "render_settings { width: 8; height: 8; background_map: \"" + name +
                                 "\"; }\ncameras { perspective_camera { aspect: 1; } }\n"
                                 "scene { sphere { } }\n");
        const long baseline = peak_of_check(dir, small + ".jts");
        const long peak = peak_of_check(dir, big + ".jts");
        return baseline > 0 && peak > 0 ? peak - baseline : -1;
    }
};

TEST_F(ImageMemory, A16BitPngSkyMapIsHeldOnceWhileItIsRead) {
#if JT_SANITIZED
    GTEST_SKIP() << "the sanitizers' allocator and shadow memory change the resident size";
#endif
    constexpr std::uint32_t width = 4096, height = 2048;
    const long texels = long{width} * height * 6;
    for (const auto& [name, w, h] : {std::tuple{"big.png", width, height}, {"small.png", 1u, 1u}}) {
        const std::vector<std::uint8_t> bytes = png16(w, h);
        test::write_file(dir / name, {reinterpret_cast<const char*>(bytes.data()), bytes.size()});
    }
    const long extra = extra_peak("big.png", "small.png");
    ASSERT_GT(extra, 0);
    // The file's bytes (as large as the texels here) and the texels, once:
    // two copies. Three or more is a copy too many (a decoder that holds its
    // inflated data and the image at once, or rows copied to turn them
    // round).
    EXPECT_LT(extra, texels * 5 / 2) << extra << " bytes over the baseline, texels " << texels;
}

TEST_F(ImageMemory, A24BitBmpSkyMapIsHeldOnceWhileItIsRead) {
#if JT_SANITIZED
    GTEST_SKIP() << "the sanitizers' allocator and shadow memory change the resident size";
#endif
    constexpr int width = 4096, height = 2048;
    const long texels = long{width} * height * 3;
    std::uint32_t state = 12345;
    for (const auto& [name, w, h] : {std::tuple{"big.bmp", width, height}, {"small.bmp", 1, 1}}) {
        Image8 image(w, h);
        for (std::uint8_t& byte : image.rgb) {
            state = state * 1664525u + 1013904223u;
            byte = static_cast<std::uint8_t>(state >> 24);
        }
        ASSERT_TRUE(write_bmp(dir / name, image));
    }
    const long extra = extra_peak("big.bmp", "small.bmp");
    ASSERT_GT(extra, 0);
    // The file (the texels, padded) and the texels: two copies, not three.
    EXPECT_LT(extra, texels * 5 / 2) << extra << " bytes over the baseline, texels " << texels;
}

}  // namespace
}  // namespace jt
