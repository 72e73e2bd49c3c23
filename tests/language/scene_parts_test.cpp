// A large scene block read by several threads, a part each
// (language/scene_parts.hpp): whatever the layout, the names, the errors and
// the words that only look like a block's start, the result must be the one a
// single thread gives, to the last record and diagnostic.

#include "language/scene_parts.hpp"

#include "jtracer/parser.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <string>

namespace jt {
namespace {

// Enough text for four parts (kSceneBytesPerPart each).
constexpr std::size_t kLargeText = 4 * lang::kSceneBytesPerPart + 4096;

enum class Layout { lines, one_line, indented };

// Random spheres, cylinders, triangles and lights up to `bytes`, each using
// the file's names now and then; `extra(i)` is written before block i.
template <class Extra>
std::string scene_text(Layout layout, std::size_t bytes, unsigned seed, Extra extra) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-10.0, 10.0), c(0.0, 1.0);
    std::string text =
        "define r = 0.25;\ndefine lift = <0, 1, 0>;\n"
        "material shiny { specular: <1, 1, 1>; specular_k: 40; }\n"
        "render_settings { width: 64; height: 48; }\n"
        "cameras { perspective_camera { position: <0, 0, 10>; } }\n"
        "scene {\n";
    const char* gap = layout == Layout::one_line ? "" : "\n";
    const char* indent = layout == Layout::indented ? "    " : "";
    char buffer[512];
    for (int i = 0; text.size() < bytes; ++i) {
        text += extra(i);
        text += indent;
        switch (i % 9) {
            case 0:
                std::snprintf(buffer, sizeof buffer,
                              "point_light{position:<%.3f,5,%.3f>;intensity:<0.2,0.2,0.2>;}",
                              u(rng), u(rng));
                break;
            case 1:
                std::snprintf(buffer, sizeof buffer,
                              "cylinder { radius: r * 2; height: %.2f; material: shiny; "
                              "transform { translate: lift; } }",
                              c(rng) + 0.5);
                break;
            case 2:
                std::snprintf(
                    buffer, sizeof buffer,
                    "triangle{a:<%.2f,0,0>;b:<0,%.2f,0>;c:<0,0,1>;material{pigment:<1,0,0>;}}",
                    u(rng), u(rng));
                break;
            default:
                std::snprintf(
                    buffer, sizeof buffer,
                    "sphere{center:<%.4f,%.4f,%.4f>;radius:%.4f;material{pigment:<%.3f,%.3f,"
                    "%.3f>;ambient:<0.2,0.2,0.2>;}}",
                    u(rng), u(rng), u(rng), c(rng) + 0.01, c(rng), c(rng), c(rng));
                break;
        }
        text += buffer;
        text += gap;
    }
    text += "\n}\n";
    return text;
}

std::string scene_text(Layout layout, std::size_t bytes, unsigned seed) {
    return scene_text(layout, bytes, seed, [](int) { return std::string(); });
}

// Parses `text` with one thread and with four, with and without the source
// map, and expects the same result; returns the four-thread reading's count
// of parts taken (with the map).
std::size_t expect_same_reading(const std::string& text) {
    std::size_t taken = 0;
    for (bool map : {true, false}) {
        const ParseResult one = parse_scene(text, {.source_map = map, .threads = 1});
        const ParseResult four = parse_scene(text, {.source_map = map, .threads = 4});
        EXPECT_EQ(one.scene_parts_taken, 0u);
        EXPECT_TRUE(four.scene == one.scene);
        EXPECT_TRUE(four.source == one.source);
        EXPECT_EQ(four.diagnostics, one.diagnostics);
        EXPECT_EQ(four.reads_clock, one.reads_clock);
        EXPECT_EQ(four.out_of_memory, one.out_of_memory);
        if (map) taken = four.scene_parts_taken;
    }
    return taken;
}

TEST(SceneParts, EveryLayoutReadsTheSameInParts) {
    for (Layout layout : {Layout::lines, Layout::one_line, Layout::indented}) {
        SCOPED_TRACE(static_cast<int>(layout));
        const std::string text = scene_text(layout, kLargeText, 7);
        const ParseResult clean = parse_scene(text, {.threads = 4});
        ASSERT_TRUE(clean.ok());
        EXPECT_EQ(expect_same_reading(text), 3u);  // the parser reads the first part itself
    }
}

TEST(SceneParts, ASmallSceneIsReadByOneThread) {
    const std::string text = scene_text(Layout::lines, lang::kSceneBytesPerPart / 2, 3);
    EXPECT_EQ(expect_same_reading(text), 0u);
}

TEST(SceneParts, AnErrorInAPartIsReportedAsOneThreadReportsIt) {
    // Errors and warnings late in the text, in what other threads read: the
    // parser reads such a part again itself, so every message comes once, in order.
    std::string text = scene_text(Layout::lines, kLargeText, 11, [](int i) {
        if (i == 20000) return std::string("sphere { radius: -1; colour: 2; }\n");
        if (i == 25000) return std::string("sphere { center: <0, 0, nowhere>; }\n");
        return std::string();
    });
    const ParseResult four = parse_scene(text, {.threads = 4});
    EXPECT_FALSE(four.ok());
    EXPECT_GE(four.diagnostics.size(), 3u);
    expect_same_reading(text);
}

TEST(SceneParts, WordsThatOnlyLookLikeABlockChangeNothing) {
    // Comments holding "sphere {" now and then: a guessed start may lie in one.
    const std::string decoy = "# sphere { center: <1, 2, 3>; }\n";
    const std::string commented = scene_text(
        Layout::lines, kLargeText, 5, [&](int i) { return i % 100 == 0 ? decoy : std::string(); });
    EXPECT_GE(expect_same_reading(commented), 1u);
    // A string holding one, in a block the scene block does not hold (an error).
    const std::string quoted = scene_text(Layout::lines, kLargeText, 5, [](int i) {
        return i % 500 == 250 ? std::string("render_settings { filename: \"sphere { }\"; }\n")
                              : std::string();
    });
    expect_same_reading(quoted);
    // Nothing but decoys past the first MiB: no part may be taken.
    std::string decoys = scene_text(Layout::lines, lang::kSceneBytesPerPart, 5);
    decoys.resize(decoys.size() - 3);  // reopen the scene block
    while (decoys.size() < kLargeText) decoys += decoy;
    decoys += "}\n";
    EXPECT_EQ(expect_same_reading(decoys), 0u);
}

TEST(SceneParts, ClockIncludeAndTheEndOfTheText) {
    // `clock` read only in the last part.
    std::string text = scene_text(Layout::lines, kLargeText, 9, [](int i) {
        return i == 30000 ? std::string("sphere { center: <clock, 0, 0>; }\n") : std::string();
    });
    EXPECT_TRUE(parse_scene(text, {.threads = 4}).reads_clock);
    expect_same_reading(text);
    // A scene block that never closes.
    std::string open = scene_text(Layout::lines, kLargeText, 9);
    open.resize(open.size() - 3);
    expect_same_reading(open);
    // An include (of a file that is not there) among the blocks.
    std::string with_include = scene_text(Layout::lines, kLargeText, 9, [](int i) {
        return i == 28000 ? std::string("include \"no-such-file.jts\";\n") : std::string();
    });
    expect_same_reading(with_include);
}

TEST(SceneParts, StartsAreKeywordsBeforeABrace) {
    const std::string text = "scene {xsphere{}sphere  {}# plane{\ncylinder\n{}point_light{}}";
    const std::size_t from = text.find('{') + 1;
    const std::vector<std::size_t> starts = lang::guess_scene_part_starts(text, from, 8);
    ASSERT_FALSE(starts.empty());
    for (std::size_t i = 0; i < starts.size(); ++i) {
        const std::string_view word = std::string_view(text).substr(starts[i]);
        EXPECT_TRUE(word.starts_with("sphere") || word.starts_with("plane") ||
                    word.starts_with("cylinder") || word.starts_with("point_light"))
            << starts[i];
        EXPECT_NE(text[starts[i] - 1], 'x');
        if (i > 0) {
            EXPECT_GT(starts[i], starts[i - 1]);
        }
    }
    EXPECT_TRUE(lang::guess_scene_part_starts("scene { radius: 1; }", 7, 4).empty());
}

TEST(SceneParts, PartCountFollowsSizeAndThreads) {
    EXPECT_EQ(lang::scene_part_count(lang::kSceneBytesPerPart - 1, 8), 1u);
    EXPECT_EQ(lang::scene_part_count(3 * lang::kSceneBytesPerPart, 8), 3u);
    EXPECT_EQ(lang::scene_part_count(100 * lang::kSceneBytesPerPart, 2), 2u);
    EXPECT_EQ(lang::scene_part_count(100 * lang::kSceneBytesPerPart, 64), lang::kMaxSceneParts);
    EXPECT_EQ(lang::scene_part_count(100 * lang::kSceneBytesPerPart, 1), 1u);
}

}  // namespace
}  // namespace jt
