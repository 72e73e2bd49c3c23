// Replays every saved fuzz input (regressions/parser, bmp, image_map, model) through
// the very checks the fuzz targets make (fuzz/invariants.cpp): no crash, no
// sanitizer report, diagnostics within the text, round trips that hold.

#include "invariants.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace jt::test {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> inputs(const std::string& folder) {
    std::vector<fs::path> paths;
    for (const auto& entry :
         fs::directory_iterator(fs::path(JT_SOURCE_DIR) / "tests/hardening/regressions" / folder))
        if (entry.is_regular_file()) paths.push_back(entry.path());
    std::sort(paths.begin(), paths.end());
    return paths;
}

std::vector<std::uint8_t> bytes_of(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(FuzzRegressions, ParserInputsKeepTheirInvariants) {
    const std::vector<fs::path> paths = inputs("parser");
    ASSERT_GE(paths.size(), 5u);
    for (const fs::path& path : paths) {
        std::vector<std::uint8_t> bytes = bytes_of(path);
        std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
        EXPECT_EQ(fuzz::check_scene_text(text), "") << path.filename();
    }
}

TEST(FuzzRegressions, BmpInputsKeepTheirInvariants) {
    const std::vector<fs::path> paths = inputs("bmp");
    ASSERT_GE(paths.size(), 5u);
    for (const fs::path& path : paths)
        EXPECT_EQ(fuzz::check_bmp_bytes(bytes_of(path)), "") << path.filename();
}

TEST(FuzzRegressions, ImageMapInputsKeepTheirInvariants) {
    const std::vector<fs::path> paths = inputs("image_map");
    ASSERT_GE(paths.size(), 3u);
    for (const fs::path& path : paths)
        EXPECT_EQ(fuzz::check_texture_bytes(bytes_of(path)), "") << path.filename();
}

// Each input's first byte picks the model file's extension (fuzz/invariants.hpp).
TEST(FuzzRegressions, ModelInputsKeepTheirInvariants) {
    const std::vector<fs::path> paths = inputs("model");
    ASSERT_GE(paths.size(), 3u);
    for (const fs::path& path : paths)
        EXPECT_EQ(fuzz::check_model_bytes(bytes_of(path)), "") << path.filename();
}

// The location check must be able to fail, or the replay proves little.
TEST(FuzzRegressions, TheLocationCheckRejectsDiagnosticsOutsideTheText) {
    const std::string text = "scene {\n  sphere { }\n";
    auto at = [](int line, int column) {
        return std::vector<Diagnostic>{{Severity::error, {line, column}, "m"}};
    };
    EXPECT_EQ(fuzz::check_diagnostics_within(at(2, 13), text), "");  // one past the line's end
    EXPECT_EQ(fuzz::check_diagnostics_within(at(0, 0), text), "");   // the file as a whole
    EXPECT_NE(fuzz::check_diagnostics_within(at(2, 14), text), "");
    EXPECT_NE(fuzz::check_diagnostics_within(at(4, 1), text), "");
    EXPECT_NE(fuzz::check_diagnostics_within(at(1, 0), text), "");
    EXPECT_NE(fuzz::check_diagnostics_within({{Severity::error, {1, 1}, ""}}, text), "");
}

}  // namespace
}  // namespace jt::test
