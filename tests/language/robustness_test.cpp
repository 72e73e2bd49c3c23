// Pathological input: parse_scene never crashes, never hangs, never throws,
// and says something useful. Each case must finish well within a second in a
// release build.

#include "test_util.hpp"

#include <chrono>
#include <random>

namespace jt {
namespace {

using test::brief;

class Timed : public ::testing::Test {
  protected:
    void SetUp() override { start_ = std::chrono::steady_clock::now(); }
    void TearDown() override {
        double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        // Generous so that sanitizer builds pass; release runs take milliseconds.
        EXPECT_LT(seconds, 20.0);
    }
    std::chrono::steady_clock::time_point start_;
};

TEST_F(Timed, TwoHundredThousandNestedBraces) {
    std::string text(200000, '{');
    EXPECT_EQ(brief(text),
              "1:1: error: expected a block name (render_settings, cameras or scene) before '{'\n"
              "1:1: error: this '{' is never closed: expected '}' before the end of the file");
    text += std::string(200000, '}');
    EXPECT_EQ(brief(text),
              "1:1: error: expected a block name (render_settings, cameras or scene) before '{'");
}

// Each unknown name looks for the nearest defined one: a name defined a
// megabyte long is never near, and is not measured against every use.
TEST_F(Timed, UnknownNamesBesideVeryLongDefinedNames) {
    std::string text;
    for (int i = 0; i < 40; ++i)
        text += "define n" + std::to_string(i) + std::string(700000, 'a') + " = 1;\n";
    text += "define near = 1;\nscene {\n";
    for (int i = 0; i < 20; ++i)
        text += "sphere { radius: " + std::string(62, 'b') + std::to_string(i + 10) + "; }\n";
    text += "sphere { radius: naer; }\n}\n";
    const ParseResult r = parse_scene(text);
    ASSERT_EQ(r.diagnostics.size(), 21u);
    EXPECT_EQ(r.diagnostics.back().message, "too many errors (20); stopping here");
    EXPECT_EQ(r.diagnostics.front().message, "unknown name '" + std::string(40, 'b') +
                                                 "' (names must be defined before they are used)");
    EXPECT_EQ(brief("define n" + std::string(100, 'a') +
                    " = 1;\ndefine near = 1;\n"
                    "scene { sphere { radius: naer; } }"),
              "3:26: error: unknown name 'naer' (names must be defined before they are used); "
              "did you mean 'near'?");
}

TEST_F(Timed, NestedBracesInsideAPrimitive) {
    std::string text = "scene { sphere { " + std::string(200000, '{') + std::string(200000, '}') +
                       " radius: 2; } }";
    ParseResult r = parse_scene(text);
    EXPECT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(shape_as<Sphere>(r.scene.primitives.at(0).shape).radius, 2.0);
}

TEST_F(Timed, TwoMegabyteStringLiteral) {
    std::string name(2'000'000, 'x');
    ParseResult r = parse_scene("render_settings { filename: \"" + name + "\"; }");
    EXPECT_TRUE(r.ok());
    EXPECT_EQ(r.scene.settings.filename, name);
    EXPECT_EQ(brief("render_settings { filename: \"" + name),
              "1:29: error: string is not closed before the end of the file\n"
              "1:1: error: this 'render_settings' block is never closed: expected '}' before "
              "the end of the file");
}

TEST_F(Timed, HundredMegabyteFile) {
    // Mostly comments and blank lines around a valid scene.
    std::string text = "render_settings { width: 8; }\n";
    const std::string filler = "# " + std::string(97, '-') + "\n";
    text.reserve(100'000'100);
    while (text.size() < 100'000'000) text += filler;
    text += "scene { sphere { radius: 2; } }\n";
    ParseResult r = parse_scene(text);
    EXPECT_TRUE(r.diagnostics.empty());
    EXPECT_EQ(r.scene.primitives.size(), 1u);
    EXPECT_EQ(r.source.primitives.at(0).keyword_span.pos.line, 1'000'002);
}

TEST_F(Timed, RandomBytes) {
    std::mt19937 rng(12345);
    for (int trial = 0; trial < 200; ++trial) {
        std::string text(rng() % 4000, '\0');
        for (char& c : text) c = static_cast<char>(rng());
        ParseResult r = parse_scene(text);
        if (!text.empty()) {
            EXPECT_FALSE(r.diagnostics.empty());
        }
    }
}

TEST_F(Timed, RandomTokenSoup) {
    // Valid UTF-8 made of the language's own pieces: reaches deep into the parser.
    const std::vector<std::string> pieces = {"{",
                                             "}",
                                             "<",
                                             ">",
                                             ",",
                                             ":",
                                             ";",
                                             "\"s\"",
                                             "\"",
                                             "1",
                                             "-2.5",
                                             ".5",
                                             "1e400",
                                             "1..2",
                                             "nan",
                                             "scene",
                                             "cameras",
                                             "render_settings",
                                             "perspective_camera",
                                             "sphere",
                                             "plane",
                                             "cylinder",
                                             "point_light",
                                             "material",
                                             "transform",
                                             "radius",
                                             "center",
                                             "width",
                                             "translate",
                                             "scale",
                                             "pigment",
                                             "active_camera",
                                             "name",
                                             "#c\n",
                                             "\n",
                                             " ",
                                             "@"};
    std::mt19937 rng(777);
    for (int trial = 0; trial < 2000; ++trial) {
        std::string text;
        int n = static_cast<int>(rng() % 200);
        for (int i = 0; i < n; ++i) text += pieces[rng() % pieces.size()] + " ";
        ParseResult r = parse_scene(text);
        int errors = 0;
        for (const Diagnostic& d : r.diagnostics) {
            EXPECT_GE(d.pos.line, 0);
            EXPECT_FALSE(d.message.empty());
            errors += d.severity == Severity::error;
        }
        EXPECT_LE(errors, 21);
        EXPECT_EQ(r.source.primitives.size(), r.scene.primitives.size());
        EXPECT_EQ(r.source.lights.size(), r.scene.lights.size());
        EXPECT_EQ(r.source.cameras.size(), r.scene.cameras.size());
        for (const Diagnostic& d : r.diagnostics) format_diagnostic(d, "f", text);
    }
}

TEST_F(Timed, ManyRepeatedPropertiesStayLinear) {
    std::string text = "render_settings {\n";
    while (text.size() < 5'000'000) text += "width: 1; height: 2;\n";
    text += "}\n";
    ParseResult r = parse_scene(text);
    EXPECT_TRUE(r.ok());
    EXPECT_EQ(r.diagnostics.back().message, "too many warnings; the rest are not shown");
}

TEST_F(Timed, NulAndControlBytes) {
    EXPECT_EQ(brief(std::string("\0", 1)),
              "1:1: error: the file is not a text file: it contains a NUL byte");
    EXPECT_EQ(brief("scene {\x01}"), "1:8: error: unexpected byte 0x01");
}

}  // namespace
}  // namespace jt
