#pragma once
// The files a scene is read from (docs/language.md §15.6): the main text and
// every file `include` reads. A SourcePos's `file` indexes them: 0 is the main
// text, which the caller holds; k > 0 is SceneSource::files[k - 1]. A file
// included twice is read twice and listed twice: each reading has its own
// include chain.

#include "jtracer/diagnostics.hpp"

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace jt {

struct SourceFile {
    // As diagnostics print it: the including file's printed name's folder
    // joined with the include string, normalised lexically, with '/'.
    std::string name;
    std::string path;       // where it was read: the including file's folder joined with the string
    std::string canonical;  // absolute, symlinks resolved: two includes of one file have the same
    std::string text;
    SourcePos included_at;  // the opening quote of the include's string (its file: the includer)
    bool operator==(const SourceFile&) const = default;
};

// The text of file `file`: `main_text` for 0, else files[file - 1]'s (empty
// when out of range).
std::string_view file_text(std::span<const SourceFile> files, std::string_view main_text,
                           std::uint32_t file);

// The name diagnostics print for file `file`: `main_name` for 0.
std::string_view file_name(std::span<const SourceFile> files, std::string_view main_name,
                           std::uint32_t file);

// format_diagnostic for a scene read from several files: the diagnostic is
// named and quoted from its own file, then one line
// "note: included from FILE:LINE:COL" per include on the way, innermost first.
std::string format_diagnostic(const Diagnostic& diagnostic, std::string_view main_name,
                              std::string_view main_text, std::span<const SourceFile> files);

}  // namespace jt
