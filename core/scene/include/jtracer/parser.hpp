#pragma once
// .jts text -> Scene + diagnostics. A pure function: it never throws and never
// crashes, whatever the bytes (docs/language.md §2-§4).

#include "jtracer/diagnostics.hpp"
#include "jtracer/scene.hpp"
#include "jtracer/source_map.hpp"

#include <string_view>
#include <vector>

namespace jt {

struct ParseOptions {
    // False: leave ParseResult::source empty. A tool that only renders needs
    // the source map only to locate validation findings, and for a million
    // spheres the map costs more than the scene (see check_scene).
    bool source_map = true;
};

struct ParseResult {
    Scene scene;
    SceneSource source;                   // empty when parsed with source_map = false
    std::vector<Diagnostic> diagnostics;  // in the order found
    bool out_of_memory = false;           // parsing stopped for want of memory (one diagnostic)
    bool ok() const { return !has_errors(diagnostics); }
};

// Lexes and parses; reports every error it can recover from (up to a cap).
ParseResult parse_scene(std::string_view text, ParseOptions options = {});

}  // namespace jt
