#pragma once
// The differences between two texts, line by line, as `diff -u` shows them:
// what the reload choice shows between the viewer's text and the file's.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace jt::view {

struct DiffLine {
    enum class Kind { same, removed, added, file } kind = Kind::same;
    std::string text;  // without its newline
    int old_line = 0;  // from 1, in the old text (0 for an added line)
    int new_line = 0;  // from 1, in the new text (0 for a removed line)
};

struct TextDiff {
    std::vector<DiffLine> lines;  // the changed lines with `context` lines around each run
    int removed = 0, added = 0;
    // The middles (past the common first and last lines) differ in too many
    // places to compare line by line: the diff shows them removed and added whole.
    bool coarse = false;
};

// Past this many lines times lines in the changed middles, the diff is
// found as the shortest edit script (quick when few lines changed, however
// long the texts), and is coarse when that takes more than kMaxEditWork
// (paths kept plus lines compared: about a thousand changed lines).
inline constexpr std::size_t kMaxDiffCells = std::size_t{4} << 20;
inline constexpr std::size_t kMaxEditWork = std::size_t{1} << 20;

// `old_text` to `new_text`, with `context` unchanged lines around each change.
TextDiff diff_lines(std::string_view old_text, std::string_view new_text, int context = 3);

}  // namespace jt::view
