// A parse at one clock taking the primitives that read no `clock` from a parse
// of the same texts at another (parser.hpp's EarlierParse): what a frame
// sequence does. The result must equal a parse from scratch.

#include "jtracer/parser.hpp"

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

namespace jt {
namespace {

// Every way a primitive can come to read `clock`, beside two that do not.
const std::string scene_text = R"(define speed = clock * 2;
define still = 3;
define twice = speed * 2;
material moving { pigment: <clock, 0, 0>; }
material fixed { pigment: <0, 1, 0>; }
cameras { perspective_camera { position: <0, 0, 5 + clock>; look_at: <0, 0, 0>; } }
scene {
    sphere {
        center: <0, 0, 0>;  # a comment
        radius: 1;
    }
    sphere { center: <twice, 0, 0>; radius: 1; }
    sphere {
        radius: 1;
        material: moving;
    }
    sphere { radius: 1; material: fixed; transform { yrotate: clock * 90; } }
    sphere { radius: still; material { pigment: <0.5, 0.5, 0.5>; } }
    plane { normal: <0, 1, 0>; distance: -1; material { reflection: clock / 2; } }
    sphere { radius: 0.5 + 0 * clock; }
    sphere { center: <1, 2, 3>; radius: 0.25; material: fixed; }
    point_light { position: <1, 1, clock>; intensity: <1, 1, 1>; }
}
)";
const std::vector<bool> reads_clock = {false, true, true, true, false, true, true, false};

ParseOptions at(double clock) {
    ParseOptions options;
    options.source_map = false;
    options.record_primitive_readings = true;
    options.clock = clock;
    return options;
}

// The earlier parse of `text` at clock 0, its primitives marked so that a
// primitive taken from it can be told from one read again.
EarlierParse marked_earlier(const std::string& text, ParseOptions options = at(0.0)) {
    ParseResult first = parse_scene(text, options);
    EXPECT_TRUE(first.ok());
    EarlierParse earlier{text, first.source.files, std::move(first.scene.primitives),
                         std::move(first.primitive_readings)};
    for (Primitive& p : earlier.primitives) p.material.finish.edit().specular_k = 7.25;
    return earlier;
}

std::vector<bool> taken(const ParseResult& r) {
    std::vector<bool> out;
    for (const Primitive& p : r.scene.primitives)
        out.push_back(p.material.finish->specular_k == 7.25);
    return out;
}

TEST(EarlierParse, EachPrimitiveSaysWhetherItReadsClock) {
    const ParseResult r = parse_scene(scene_text, at(0.25));
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r.primitive_readings.size(), r.scene.primitives.size());
    std::vector<bool> got;
    for (const PrimitiveReading& reading : r.primitive_readings) got.push_back(reading.reads_clock);
    EXPECT_EQ(got, reads_clock);
}

TEST(EarlierParse, TakesExactlyThePrimitivesThatReadNoClock) {
    EarlierParse earlier = marked_earlier(scene_text);
    ParseOptions options = at(0.5);
    options.earlier = &earlier;
    const ParseResult r = parse_scene(scene_text, options);
    ASSERT_TRUE(r.ok());
    std::vector<bool> expected;
    for (bool reads : reads_clock) expected.push_back(!reads);
    EXPECT_EQ(taken(r), expected);
}

TEST(EarlierParse, GivesTheSceneAParseFromScratchGives) {
    for (double clock : {0.0, 0.3, 1.0}) {
        ParseResult first = parse_scene(scene_text, at(clock));
        EarlierParse earlier{
            scene_text, {}, std::move(first.scene.primitives), std::move(first.primitive_readings)};
        for (double next : {0.1, 0.75}) {
            ParseOptions options = at(next);
            options.earlier = &earlier;
            const ParseResult again = parse_scene(scene_text, options);
            const ParseResult scratch = parse_scene(scene_text, at(next));
            EXPECT_TRUE(again.scene == scratch.scene) << clock << " -> " << next;
            EXPECT_EQ(again.primitive_readings.size(), scratch.primitive_readings.size());
            // Refill what the parse took, for the next one.
            ParseResult refill = parse_scene(scene_text, at(clock));
            earlier.primitives = std::move(refill.scene.primitives);
        }
    }
}

TEST(EarlierParse, ADefineFromTheCommandLineThatReadsClockCounts) {
    ParseOptions options = at(0.0);
    options.defines = {{"still", "clock + 1"}};
    EarlierParse earlier = marked_earlier(scene_text, options);
    options.clock = 0.5;
    options.earlier = &earlier;
    const ParseResult r = parse_scene(scene_text, options);
    ASSERT_TRUE(r.ok());
    EXPECT_FALSE(taken(r)[4]);
    EXPECT_DOUBLE_EQ(shape_as<Sphere>(r.scene.primitives[4].shape).radius, 1.5);
    EXPECT_TRUE(taken(r)[0]);
}

TEST(EarlierParse, PositionsAfterATakenPrimitiveAreTheSame) {
    // A warning and an error after taken primitives, one of them on many
    // lines: the lexer resumes on the right line and column.
    const std::string text = scene_text.substr(0, scene_text.rfind('}')) +
                             "    sphere { radius: 1 + 0 * clock; radius: 2; }\n"
                             "    sphere { radius: sqrt(0.25 - clock); }\n}\n";
    EarlierParse earlier = marked_earlier(text);
    ParseOptions options = at(0.75);
    options.earlier = &earlier;
    const ParseResult again = parse_scene(text, options);
    const ParseResult scratch = parse_scene(text, at(0.75));
    ASSERT_FALSE(scratch.ok());
    EXPECT_EQ(again.diagnostics, scratch.diagnostics);
}

// Included texts from memory: `files` maps a path to its text.
IncludeReader reader_of(const std::map<std::string, std::string>& files) {
    return [&files](const std::string& path, std::uintmax_t) -> Expected<IncludedText> {
        const auto found = files.find(path);
        if (found == files.end()) return Error{"cannot read '" + path + "': no such file"};
        return IncludedText{"/mem/" + path, found->second};
    };
}

TEST(EarlierParse, TakesFromIncludedFilesOnlyWhileTheyAreUnchanged) {
    std::map<std::string, std::string> files = {
        {"parts.jts", "sphere {\n    radius: 1;\n}\nsphere { radius: clock + 1; }\n"}};
    const std::string text =
        "cameras { perspective_camera { position: <0, 0, 5>; look_at: <0, 0, 0>; } }\n"
        "scene {\n    include \"parts.jts\";\n    sphere { radius: 2; }\n}\n";
    ParseOptions options = at(0.0);
    options.read_include = reader_of(files);
    EarlierParse earlier = marked_earlier(text, options);
    options.clock = 0.5;
    options.earlier = &earlier;
    ParseResult r = parse_scene(text, options);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(taken(r), (std::vector<bool>{true, false, true}));

    // The same length, another radius: nothing after it may be taken.
    files["parts.jts"] = "sphere {\n    radius: 3;\n}\nsphere { radius: clock + 1; }\n";
    options.clock = 0.0;
    earlier = marked_earlier(text, options);
    files["parts.jts"] = "sphere {\n    radius: 4;\n}\nsphere { radius: clock + 1; }\n";
    options.clock = 0.5;
    options.earlier = &earlier;
    r = parse_scene(text, options);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(taken(r), (std::vector<bool>{false, false, false}));
    EXPECT_DOUBLE_EQ(shape_as<Sphere>(r.scene.primitives[0].shape).radius, 4.0);
}

TEST(EarlierParse, AnotherMainTextIsReadWhole) {
    EarlierParse earlier = marked_earlier(scene_text);
    const std::string edited = scene_text + "\n";
    ParseOptions options = at(0.5);
    options.earlier = &earlier;
    const ParseResult r = parse_scene(edited, options);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(taken(r), std::vector<bool>(reads_clock.size(), false));
}

TEST(EarlierParse, NotWithTheSourceMap) {
    EarlierParse earlier = marked_earlier(scene_text);
    ParseOptions options = at(0.5);
    options.source_map = true;
    options.earlier = &earlier;
    const ParseResult r = parse_scene(scene_text, options);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.source.primitives.size(), r.scene.primitives.size());
    EXPECT_EQ(taken(r), std::vector<bool>(reads_clock.size(), false));
}

}  // namespace
}  // namespace jt
