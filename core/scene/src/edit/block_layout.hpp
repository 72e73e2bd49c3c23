#pragma once
// Where a block or a property statement lies in a .jts text, and the edits
// that remove one or insert new lines in the style of the text around them:
// a block that has lines to itself is removed or written as whole lines with
// its neighbours' indentation, a one-line block is edited inline.

#include "edit/text_edits.hpp"
#include "jtracer/source_map.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace jt::edit {

// Bytes [begin, end) of a text.
struct Range {
    std::size_t begin = 0;
    std::size_t end = 0;
};

// A block from its keyword to its closing brace.
Range block_range(const BlockSource& block);
// A property statement from its name to its ';' (comments between included).
Range statement_range(std::string_view text, const PropertySource& property);

// True when only spaces, tabs or a comment follow `offset` on its line.
bool ends_its_line(std::string_view text, std::size_t offset);
// Offset just past the '\n' that ends the line holding `offset` (or the text's end).
std::size_t next_line_start(std::string_view text, std::size_t offset);
// True when `range` has its lines to itself: only whitespace before it, and
// only whitespace or a comment after it, on its first and last lines.
bool has_own_lines(std::string_view text, Range range);

// Removes `range`: its whole lines (a comment after it on its last line
// included) when it has them to itself, otherwise the range and one space
// beside it. With `collapse_blank_lines`, a blank line left next to another
// blank line (or between one and the enclosing block's closing brace) goes too.
TextEdit removal(std::string_view text, Range range, bool collapse_blank_lines);

// The offset of a block's first property or nested block, if it has one.
std::optional<std::size_t> first_item(const SceneSource& source, const BlockSource& block);

// Inserts `lines` (one statement each, or the lines of a nested block) just
// before the closing brace at `close`: on lines of their own with the
// indentation of the block's first item (at `first_item`) when the brace has
// its own line, otherwise inline before the brace. With `blank_line_before`
// (own-line style only) an empty line separates them from what precedes.
TextEdit insertion_before_close(std::string_view text, std::size_t close,
                                std::optional<std::size_t> first_item,
                                const std::vector<std::string>& lines,
                                bool blank_line_before = false);

// Inserts `lines` just after `range`: on the lines after its own, with its
// indentation, when it has its lines to itself, otherwise inline after it.
TextEdit insertion_after(std::string_view text, Range range, const std::vector<std::string>& lines,
                         bool blank_line_before = false);

// Inserts `lines` just before `range`, in the same way.
TextEdit insertion_before(std::string_view text, Range range,
                          const std::vector<std::string>& lines);

// Each line prefixed with `indent` (empty lines left empty), each ending in '\n'.
std::string indented_lines(const std::vector<std::string>& lines, std::string_view indent);

// True when a blank line precedes the range (above the comment lines just
// above it, if any) or follows it: the text separates its blocks so.
bool set_apart_by_blank_lines(std::string_view text, Range range);

}  // namespace jt::edit
