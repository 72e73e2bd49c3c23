#pragma once
// What every structure-edit test checks: the edit's text parses to the
// expected scene, and only the bytes of the changed block differ.

#include "jtracer/error.hpp"
#include "jtracer/parser.hpp"
#include "jtracer/scene_text.hpp"

#include <gtest/gtest.h>

#include <string>
#include <string_view>

namespace jt::test {

// A parse that must succeed, kept with its text.
struct Parsed {
    std::string text;
    ParseResult result;
    explicit Parsed(std::string t) : text(std::move(t)), result(parse_scene(text)) {
        EXPECT_TRUE(result.ok()) << "the fixture does not parse:\n" << text;
    }
    SceneText scene_text() const { return {text, result.scene, result.source}; }
    const Scene& scene() const { return result.scene; }
};

// The edit succeeded and its text parses without errors to `expected`.
inline std::string expect_scene(const Expected<std::string>& edited, const Scene& expected) {
    EXPECT_TRUE(edited.has_value()) << (edited ? "" : edited.error().message);
    if (!edited) return {};
    const ParseResult again = parse_scene(*edited);
    EXPECT_TRUE(again.ok()) << *edited;
    EXPECT_TRUE(again.scene == expected) << *edited;
    return *edited;
}

// `after` is `before` with only bytes [begin, end) of it replaced: the text
// before `begin` and after `end` is byte-identical.
inline void expect_only_changed(std::string_view before, std::string_view after, std::size_t begin,
                                std::size_t end) {
    ASSERT_LE(begin, end);
    ASSERT_LE(end, before.size());
    ASSERT_GE(after.size(), begin + (before.size() - end)) << after;
    EXPECT_EQ(after.substr(0, begin), before.substr(0, begin)) << after;
    EXPECT_EQ(after.substr(after.size() - (before.size() - end)), before.substr(end)) << after;
}

// The offsets of `part` in `text`, which must hold it once.
inline std::pair<std::size_t, std::size_t> span_of(std::string_view text, std::string_view part) {
    const std::size_t at = text.find(part);
    EXPECT_NE(at, std::string_view::npos) << part;
    EXPECT_EQ(text.find(part, at + 1), std::string_view::npos) << "twice: " << part;
    return {at, at + part.size()};
}

// The error's message (the edit must have failed).
inline std::string error_of(const Expected<std::string>& edited) {
    EXPECT_FALSE(edited.has_value()) << (edited ? *edited : "");
    return edited ? std::string() : edited.error().message;
}

}  // namespace jt::test
