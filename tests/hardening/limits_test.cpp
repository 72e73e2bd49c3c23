// Pathological but well-formed-looking input: each gives a clear message or
// works, never a crash, a hang or a NaN. The 10M-primitive scene lives in
// huge_scene_test.cpp.

#include "jtracer/bmp.hpp"
#include "jtracer/parser.hpp"
#include "jtracer/validate.hpp"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

namespace jt::test {
namespace {

const std::string camera =
    "cameras { perspective_camera { position: <0, 0, 5>; look_at: <0, 0, 0>; aspect: 1; } }\n";

std::string first_message(const ParseResult& r, Severity severity) {
    for (const Diagnostic& d : r.diagnostics)
        if (d.severity == severity) return d.message;
    return "(none)";
}

TEST(Limits, RecurseDepthIsClampedTo256WithAWarning) {
    ParseResult r = parse_scene("render_settings { recurse_depth: 1000000; }\n" + camera);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.scene.settings.recurse_depth, 256);
    ASSERT_FALSE(r.diagnostics.empty());
    EXPECT_EQ(r.diagnostics[0].pos, (SourcePos{1, 34}));
    EXPECT_NE(r.diagnostics[0].message.find("clamped to 256"), std::string::npos);

    r = parse_scene("render_settings { recurse_depth: -1; }\n");
    EXPECT_FALSE(r.ok());
}

TEST(Limits, DeepNestingIsAnErrorNotAStackOverflow) {
    for (const std::string& text :
         {std::string(200000, '{'), "scene { " + std::string(200000, '<'), [] {
              std::string s = "scene { ";
              for (int i = 0; i < 50000; ++i) s += "sphere { material { ";
              return s;
          }()}) {
        ParseResult r = parse_scene(text);
        EXPECT_FALSE(r.ok());
        ASSERT_FALSE(r.diagnostics.empty());
        EXPECT_GE(r.diagnostics[0].pos.line, 1);
        EXPECT_LT(r.diagnostics.size(), 1000u) << "errors must be capped";
    }
}

TEST(Limits, GiantStringIsReadWhole) {
    const std::string name(8 << 20, 'a');
    ParseResult r = parse_scene("render_settings { filename: \"" + name + "\"; }\n" + camera);
    ASSERT_TRUE(r.ok()) << first_message(r, Severity::error);
    EXPECT_EQ(r.scene.settings.filename, name);
}

TEST(Limits, GiantLineIsQuotedAsAWindow) {
    // An error at the end of a 1 MB line: the message quotes 200 bytes around it.
    const std::string text = "render_settings { filename: \"" + std::string(1 << 20, 'a') + "\" }";
    ParseResult r = parse_scene(text);
    ASSERT_FALSE(r.ok());
    std::string formatted = format_diagnostic(r.diagnostics[0], "big.jts", text);
    EXPECT_LT(formatted.size(), 1000u);
    EXPECT_NE(formatted.find("big.jts:1:"), std::string::npos) << formatted;
}

TEST(Limits, NumbersBeyondDoubleAreOutOfRange) {
    // Too small (not zero, yet its nearest double is) is said so.
    const std::vector<std::pair<std::string, std::string>> numbers{
        {"1e400", "out of range"},
        {"-1e400", "out of range"},
        {"1e-400", "too small"},
        {"1" + std::string(400, '0'), "out of range"},
        {"1e99999999999999999999", "out of range"},
        {"1e-99999999999999999999", "too small"},
        {"0." + std::string(400, '0') + "1", "too small"}};
    for (const auto& [number, what] : numbers) {
        SCOPED_TRACE(number);
        ParseResult r = parse_scene(camera + "scene { sphere { radius: " + number + "; } }\n");
        EXPECT_FALSE(r.ok());
        EXPECT_NE(first_message(r, Severity::error).find(what), std::string::npos)
            << first_message(r, Severity::error);
        // A sign is an operator (docs/language.md §15.1): the number starts after it.
        EXPECT_EQ(r.diagnostics[0].pos, (SourcePos{2, number[0] == '-' ? 27 : 26}));
    }
}

TEST(Limits, WholeNumbersBeyondTheirRangeAreErrors) {
    for (const char* number : {"65536", "99999999999", "2147483648", "-2147483649"}) {
        SCOPED_TRACE(number);
        ParseResult r = parse_scene(std::string("render_settings { width: ") + number + "; }\n");
        EXPECT_FALSE(r.ok());
        EXPECT_EQ(r.diagnostics[0].pos, (SourcePos{1, 26}));
    }
}

TEST(Limits, NanAndInfinitySpelledOutAreErrors) {
    for (const char* word : {"nan", "NaN", "inf", "-inf", "infinity", "Infinity", "+inf"}) {
        SCOPED_TRACE(word);
        ParseResult r = parse_scene(camera + "scene { sphere { radius: " + word + "; } }\n");
        EXPECT_FALSE(r.ok());
        r = parse_scene(camera + "scene { sphere { center: <0, " + word + ", 0>; } }\n");
        EXPECT_FALSE(r.ok());
        EXPECT_EQ(r.diagnostics[0].pos.line, 2);
    }
}

TEST(Limits, LargestBmpWidthDecodes) {
    Image8 wide(65535, 1);
    wide.pixel(65534, 0)[1] = 7;
    const Expected<Image8> back = decode_bmp(encode_bmp(wide));
    ASSERT_TRUE(back) << back.error().message;
    EXPECT_EQ(*back, wide);
}

}  // namespace
}  // namespace jt::test
