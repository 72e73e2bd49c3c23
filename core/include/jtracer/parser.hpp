#pragma once
// .jts text -> Scene + diagnostics. A pure function: it never throws and never
// crashes, whatever the bytes (SEMANTICS.md sections 1-3).

#include "jtracer/diagnostics.hpp"
#include "jtracer/scene.hpp"
#include "jtracer/source_map.hpp"

#include <string_view>
#include <vector>

namespace jt {

struct ParseResult {
    Scene scene;
    SceneSource source;
    std::vector<Diagnostic> diagnostics;  // in the order found
    bool ok() const { return !has_errors(diagnostics); }
};

// Lexes and parses; reports every error it can recover from (up to a cap).
ParseResult parse_scene(std::string_view text);

}  // namespace jt
