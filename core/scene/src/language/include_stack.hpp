#pragma once
// The files being read by `include` (docs/language.md §15.6): which file a
// path names, how deep and whether in a cycle, the texts read, and how a
// position in any of them is named in messages.

#include "jtracer/parser.hpp"
#include "jtracer/source_files.hpp"
#include "language/diagnostic_sink.hpp"

#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace jt::lang {

class IncludeStack {
  public:
    explicit IncludeStack(const ParseOptions& options);

    struct Opened {
        std::uint32_t file = 0;  // its SourcePos::file
        std::string_view text;   // stays put until take_files
    };

    // At an include's string `path`, whose opening quote is at `at` (in the
    // file including): reads the file and makes it the one being read, or
    // reports why not and returns nullopt: at `at`, or for a file that is
    // not text at its first bad byte (the file is then kept, not read).
    // `unreadable` is set when the file could not be read (missing,
    // unreadable or not text).
    std::optional<Opened> open(std::string_view path, SourcePos at, DiagnosticSink& sink,
                               bool& unreadable);
    // The file opened last is read to its end.
    void close();

    // A path written in file `file` (`file`, `image_map`, `background_map`),
    // relative to the main file's folder as the scene holds it: "" when it
    // needs no change (the main file, a file of the main file's folder or an
    // absolute path).
    std::string rebased_asset(std::string_view path, std::uint32_t file) const;

    // "FILE:LINE:COL, included from FILE:LINE:COL, ..." for a position in an
    // included file; "LINE:COL" for one in the main file, for a message in the
    // main file too (`from`), else "FILE:LINE:COL".
    std::string where(SourcePos pos, SourcePos from) const;
    // Where `pos` is, for a message located at `from`: "line N" in the same
    // file, else "FILE:LINE:COL" (a line alone would be read in the wrong file).
    std::string line_from(SourcePos pos, SourcePos from) const;
    // As line_from, with the column: "LINE:COL" in the same file, else
    // "FILE:LINE:COL".
    std::string line_column_from(SourcePos pos, SourcePos from) const;
    // ", included from FILE:LINE:COL, ..." for file `file` ("" for the main file).
    std::string chain(std::uint32_t file) const;

    std::vector<SourceFile> take_files();
    std::vector<std::string> take_unread() { return std::move(unread_); }

  private:
    std::string location(SourcePos pos) const;
    std::string_view name(std::uint32_t file) const;

    std::deque<SourceFile> files_;      // a deque: tokens view the texts while more are read
    std::deque<std::string> relative_;  // each file's path from the main file's folder, lexically
    std::vector<std::uint32_t> open_;   // the files being read, outermost first
    std::string main_name_;
    std::string main_path_;  // as given: includes from it are relative to its folder
    std::string main_canonical_;
    IncludeReader read_;
    std::uintmax_t bytes_left_;
    std::vector<std::string> unread_;
};

}  // namespace jt::lang
