#pragma once
// Helpers for the language tests.

#include "jtracer/parser.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace jt::test {

// "3:12: error: MESSAGE" for each diagnostic, joined by newlines: compact to compare.
inline std::string brief(const std::vector<Diagnostic>& diagnostics) {
    std::string out;
    for (const Diagnostic& d : diagnostics) {
        if (!out.empty()) out += '\n';
        out += std::to_string(d.pos.line) + ':' + std::to_string(d.pos.column) +
               (d.severity == Severity::error     ? ": error: "
                : d.severity == Severity::warning ? ": warning: "
                                                  : ": note: ") +
               d.message;
    }
    return out;
}

inline std::string brief(std::string_view text) {
    return brief(parse_scene(text).diagnostics);
}

// A scene whose only diagnostics must be none; returns the parse.
inline ParseResult parse_clean(std::string_view text) {
    ParseResult r = parse_scene(text);
    EXPECT_EQ(brief(r.diagnostics), "") << text;
    return r;
}

inline Camera named_camera(std::string_view name) {
    Camera c;
    c.name.assign(name.data(), name.size());
    return c;
}

inline Material reflective(double reflection) {
    Material m;
    m.finish.edit().reflection = reflection;
    return m;
}

}  // namespace jt::test
