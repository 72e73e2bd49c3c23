// Files from strangers named by a scene: pictures whose headers claim sizes
// no machine could hold, or whose tables would make stb_image write out of
// bounds. Each is refused before anything is decoded or allocated, with an
// error at the image_map string, through --check and through a render alike.

#include "cli_sandbox.hpp"

#include <filesystem>

namespace jt::test {
namespace {

namespace fs = std::filesystem;

const fs::path hostile = fs::path(JT_SOURCE_DIR) / "tests/hardening/regressions/image_map";

class HostileImageMaps : public CliSandbox {
  protected:
    // A scene whose one image_map string starts at line 4, column 16.
    void write_scene_naming(const std::string& picture) {
        fs::copy_file(hostile / picture, dir / picture);
        write_file(dir / "hostile.jts",
                   "render_settings { width: 8; height: 8; }\n"
                   "cameras { perspective_camera { position: <0, 0, 5>; look_at: <0, 0, 0>; } }\n"
                   "scene { sphere { material {\n"
                   "    image_map: \"" +
                       picture + "\"; } } }\n");
    }
    void expect_refused(const ProgramRun& r, const std::string& problem) const {
        EXPECT_EQ(r.code, 1) << r.err;
        EXPECT_EQ(r.err.rfind("hostile.jts:4:16: error: image_map: " + problem + "\n", 0), 0u)
            << r.err;
        EXPECT_FALSE(exists("out.bmp"));
        EXPECT_TRUE(temporary_files().empty());
    }
};

TEST_F(HostileImageMaps, SizesNoMachineCouldHoldAreRefusedAtTheImageMapString) {
    const std::pair<const char*, const char*> pictures[] = {
        {"claims-100000x100000.png", "100000x100000"},
        {"claims-100000x100000.bmp", "100000x100000"},
        {"claims-65535x65535.jpg", "65535x65535"},
        // Found by the fuzzer: the product of the two sides overflowed.
        {"png-claiming-4294967295x4294967295.png", "4294967295x4294967295"},
    };
    for (const auto& [picture, claimed] : pictures) {
        SCOPED_TRACE(picture);
        write_scene_naming(picture);
        const std::string problem = "the image is too large (" + std::string(claimed) + " texels)";
        expect_refused(run({"hostile.jts", "--check"}), problem);
        expect_refused(run({"hostile.jts", "-o", "out.bmp"}), problem);
    }
}

// Found by fuzz/image_map_fuzzer: stb_image 2.27 wrote past its Huffman table
// for the JPEG (io/jpeg_tables.hpp), spent a minute decoding zeros into the 58
// million pixels the 90-byte BMP claims (io/image_claims.hpp), decoded a
// BMP of no pixels, which sampling would have divided by, and copied a PNG's
// empty first IDAT chunk to a null pointer (io/png_chunks.hpp; the second PNG
// is otherwise sound).
TEST_F(HostileImageMaps, FilesThatMisledStbImageAreRefused) {
    const std::pair<const char*, const char*> pictures[] = {
        {"jpeg-huffman-table-of-too-many-codes.jpg",
         "a corrupt JPEG: a Huffman table of 1928 codes (at most 256)"},
        {"jpeg-huffman-counts-past-the-end.jpg",  // stb_image reads zeros past the end
         "a corrupt JPEG: a Huffman table of 1671 codes (at most 256)"},
        {"bmp-90-bytes-claiming-5x11665411.bmp",
         "the file is too short for the 5x11665411 pixels its header claims (90 bytes)"},
        {"bmp-of-0x0-pixels.bmp", "the image has no pixels (0x0)"},
        {"png-first-idat-empty.png", "a PNG whose first IDAT chunk is empty (at byte 33)"},
        {"png-4x3-empty-idat-first.png", "a PNG whose first IDAT chunk is empty (at byte 33)"},
    };
    for (const auto& [picture, problem] : pictures) {
        SCOPED_TRACE(picture);
        write_scene_naming(picture);
        expect_refused(run({"hostile.jts", "--check"}), problem);
        expect_refused(run({"hostile.jts", "-o", "out.bmp"}), problem);
    }
}

}  // namespace
}  // namespace jt::test
