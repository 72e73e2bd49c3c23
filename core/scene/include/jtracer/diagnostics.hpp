#pragma once
// Compiler-style diagnostics: FILE:LINE:COL: error: MESSAGE, the source line, a caret.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace jt {

// 1-based line and column (columns count bytes). line == 0 means "no location":
// the diagnostic is about the file as a whole. `file` says which text: 0 the
// main file, k > 0 the k-th included file read (SceneSource::files[k - 1],
// jtracer/source_files.hpp), so that every span and message knows its file.
struct SourcePos {
    int line = 0;
    int column = 0;
    std::uint32_t file = 0;
    bool operator==(const SourcePos&) const = default;
};

// A note neither stops a render nor counts as a warning: it says what was
// done on request (a definition overridden by --define).
enum class Severity { warning, error, note };

struct Diagnostic {
    Severity severity = Severity::error;
    SourcePos pos;
    std::string message;
    // The render setting ("width") this diagnostic asks to be set, when it
    // asks for one: a front end with its own way to set it (a command-line
    // flag) can say so. Empty otherwise. Static storage (a schema name).
    std::string_view setting = {};
    bool operator==(const Diagnostic&) const = default;
};

bool has_errors(const std::vector<Diagnostic>& diagnostics);

// Whether `d` asks for the frame's size (a width or height of 0): a render may
// still set it, so a front end that sets the size itself (Python's
// render(width=)) or describes the scene whatever its size (`jtracer-cli info`)
// leaves it aside.
bool asks_for_frame_size(const Diagnostic& d);

// "scene.jts:3:12: error: MESSAGE\n    radius 2;\n           ^\n"
// `source` is the whole file text, used to quote the line; it may be empty.
std::string format_diagnostic(const Diagnostic& diagnostic, std::string_view filename,
                              std::string_view source);

}  // namespace jt
