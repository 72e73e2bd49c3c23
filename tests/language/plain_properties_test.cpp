// A run of properties written directly one after another on a line
// (`center:<1,2,3>;radius:0.5;`, as generators write) is read without tokens
// for the names and ':' (block_body.hpp's read_plain_run). These tests hold that
// reading to the tokens' (ParseOptions::plain_properties = false) on random
// texts, dense and laid out, well formed and not: the same scene, the same
// source map, the same diagnostics in the same order, the same readings.

#include "jtracer/parser.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <random>
#include <string>
#include <vector>

namespace jt {
namespace {

// What may stand where a value goes: plain numbers and vectors (read by the
// run), and what ends a run or is wrong (expressions, names, strings,
// malformed numbers, values out of range, a missing ';').
std::string random_value(std::mt19937_64& rng) {
    static const char* const values[] = {"0.5",
                                         "-1.25",
                                         "+2",
                                         "1e2",
                                         "0.000",
                                         "-0",
                                         "<1,2,3>",
                                         "<0.2,0.2,0.2>",
                                         "< 1 , -2 ,3 >",
                                         "<-1.5,0,.5>",
                                         "<2,0,0>",
                                         "<1,2>",
                                         "-1",
                                         "1..2",
                                         "1e999",
                                         "r",
                                         "r*2",
                                         "1+2",
                                         "\"a.png\"",
                                         "<1,2,3",
                                         "",
                                         "- 3",
                                         "0.1234567890123456",
                                         "<1e3,0,0>",
                                         "40",
                                         "1.5 2",
                                         "<1,2,3>>",
                                         "$",
                                         "<r,0,0>"};
    return values[rng() % std::size(values)];
}

// Names of sphere, material and transform properties, child blocks' names,
// unknown ones and keywords.
std::string random_name(std::mt19937_64& rng) {
    static const char* const names[] = {
        "center",  "radius",   "pigment", "ambient",    "diffuse", "specular", "specular_k",
        "reflect", "material", "colour",  "transform",  "define",  "include",  "translate",
        "scale",   "radius",   "center",  "reflection", "pigment", "x9_",      "Radius"};
    return names[rng() % std::size(names)];
}

// Between two pieces: mostly nothing (the dense text), sometimes blanks, a
// line break or a comment.
std::string random_gap(std::mt19937_64& rng, bool dense) {
    const unsigned pick = static_cast<unsigned>(rng() % 16);
    if (dense && pick < 13) return "";
    static const char* const gaps[] = {" ", "\n", "\n    ", "\t", " # note\n", "\r\n", ""};
    return gaps[pick % std::size(gaps)];
}

std::string random_property(std::mt19937_64& rng, bool dense) {
    std::string p = random_name(rng);
    if (rng() % 20 != 0) p += (rng() % 10 == 0 ? " :" : ":");
    p += random_gap(rng, true) + random_value(rng);
    if (rng() % 25 != 0) p += ";";
    return p + random_gap(rng, dense);
}

std::string block_body(std::mt19937_64& rng, bool dense, int depth) {
    std::string body;
    const int count = static_cast<int>(rng() % 7);
    for (int i = 0; i < count; ++i) {
        const unsigned pick = static_cast<unsigned>(rng() % 12);
        if (pick == 0 && depth < 2) {
            body += "material{" + block_body(rng, dense, depth + 1) + "}";
        } else if (pick == 1 && depth < 2) {
            body += "transform{" + block_body(rng, dense, depth + 1) + "}";
        } else if (pick == 2) {
            body += "material:shiny;";
        } else {
            body += random_property(rng, dense);
        }
        body += random_gap(rng, dense);
    }
    return body;
}

std::string random_scene(std::mt19937_64& rng, bool dense) {
    std::string text =
        "define r = 0.25;\nmaterial shiny{specular:<1,1,1>;specular_k:40;ambient:<0.1,0.1,0.1>;}\n"
        "render_settings{width:64;height:48;}\n"
        "cameras{perspective_camera{position:<0,0,10>;look_at:<0,0,0>;}}\nscene{";
    const int blocks = 1 + static_cast<int>(rng() % 12);
    for (int i = 0; i < blocks; ++i) {
        static const char* const keywords[] = {"sphere",      "sphere", "sphere",  "cylinder",
                                               "point_light", "plane",  "triangle"};
        text += keywords[rng() % std::size(keywords)];
        text += rng() % 10 == 0 ? " {" : "{";
        text += block_body(rng, dense, 0);
        if (rng() % 30 != 0) text += "}";
        text += random_gap(rng, dense);
    }
    if (rng() % 30 != 0) text += "}\n";
    return text;
}

// Many errors in one run of properties: the sink stops (after 20) inside it.
std::string many_errors(std::mt19937_64& rng) {
    std::string text = "scene{sphere{center:<0,0,0>;";
    const int count = 15 + static_cast<int>(rng() % 15);
    for (int i = 0; i < count; ++i) text += rng() % 3 == 0 ? "radius:0.5;" : "radius:-1;";
    text += rng() % 2 == 0 ? "colour:<1,0,0>;}}\n" : "}sphere{center:<1,2,3>;radius:2;}}\n";
    return text;
}

struct Compared {
    bool stopped = false;  // the parse hit the error cap
    bool clean = false;
};

Compared expect_same_parse(const std::string& text, const IncludeReader& read_include = {}) {
    Compared seen;
    for (bool map : {true, false}) {
        ParseOptions options{.source_map = map, .threads = 1};
        options.read_include = read_include;
        options.record_primitive_readings = !map;
        ParseOptions tokens = options;
        tokens.plain_properties = false;
        const ParseResult plain = parse_scene(text, options);
        const ParseResult token = parse_scene(text, tokens);
        EXPECT_TRUE(plain.scene == token.scene) << text;
        EXPECT_TRUE(plain.source == token.source) << text;
        EXPECT_EQ(plain.diagnostics, token.diagnostics) << text;
        EXPECT_EQ(plain.reads_clock, token.reads_clock);
        EXPECT_EQ(plain.out_of_memory, token.out_of_memory);
        EXPECT_EQ(plain.primitive_readings.size(), token.primitive_readings.size()) << text;
        for (std::size_t i = 0;
             i < std::min(plain.primitive_readings.size(), token.primitive_readings.size()); ++i) {
            const PrimitiveReading& a = plain.primitive_readings[i];
            const PrimitiveReading& b = token.primitive_readings[i];
            EXPECT_TRUE(a.file == b.file && a.keyword == b.keyword && a.resume == b.resume &&
                        a.resume_pos == b.resume_pos && a.reads_clock == b.reads_clock)
                << text;
        }
        for (const Diagnostic& d : token.diagnostics)
            if (d.message.find("too many errors") != std::string::npos) seen.stopped = true;
        seen.clean = token.diagnostics.empty();
    }
    return seen;
}

TEST(PlainProperties, RandomTextsReadAsTheTokensReadThem) {
    std::mt19937_64 rng(31);
    int stopped = 0, clean = 0;
    constexpr int kTexts = 3000;
    for (int i = 0; i < kTexts; ++i) {
        const bool dense = i % 3 != 0;
        const std::string text = i % 10 == 9 ? many_errors(rng) : random_scene(rng, dense);
        const Compared seen = expect_same_parse(text);
        stopped += seen.stopped;
        clean += seen.clean;
        if (HasFailure()) break;
    }
    // The texts reach both ends: the error cap inside a run, and no message.
    EXPECT_GT(stopped, kTexts / 50);
    EXPECT_GT(clean, 0);
}

// The same in an included file, whose lexer and positions are its own.
TEST(PlainProperties, IncludedTextsReadAsTheTokensReadThem) {
    std::mt19937_64 rng(32);
    std::string included;
    const IncludeReader reader = [&](const std::string& path,
                                     std::uintmax_t) -> Expected<IncludedText> {
        return IncludedText{path, included};
    };
    for (int i = 0; i < 300; ++i) {
        included = i % 10 == 9 ? many_errors(rng) : random_scene(rng, i % 3 != 0);
        expect_same_parse("# a scene in another file\ninclude \"a.jts\";\n", reader);
        if (HasFailure()) break;
    }
}

TEST(PlainProperties, GeneratedSpheresReadAsTheTokensReadThem) {
    std::string text = "scene{\n";
    for (int i = 0; i < 50; ++i) {
        text += "sphere{center:<4.4209,-1.8828," + std::to_string(i) +
                ".0996>;radius:0.5149;material{pigment:<0.306,0.419,0.379>;ambient:<0.2,0.2,0.2>;"
                "diffuse:<0.8,0.8,0.8>;}}\n";
    }
    text += "}\n";
    const Compared seen = expect_same_parse(text);
    EXPECT_TRUE(seen.clean);
    const ParseResult result = parse_scene(text);
    ASSERT_EQ(result.scene.primitives.size(), 50u);
    ASSERT_EQ(result.source.properties.size(), 250u);
    // The first sphere's material's third property, where the tokens put it.
    const PropertySource* diffuse = nullptr;
    for (const PropertySource& p : result.source.properties)
        if (!diffuse && p.name == "diffuse") diffuse = &p;
    ASSERT_NE(diffuse, nullptr);
    const auto column = static_cast<int>(text.find("diffuse") - text.find('\n'));
    EXPECT_EQ(diffuse->name_span.pos, (SourcePos{2, column, 0}));
    EXPECT_EQ(diffuse->name_span.offset, text.find("diffuse"));
}

}  // namespace
}  // namespace jt
