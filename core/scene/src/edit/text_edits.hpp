#pragma once
// Splicing replacements into a text at byte offsets, all against the original
// offsets, so that edits made in any order do not shift one another.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace jt::edit {

struct TextEdit {
    std::size_t offset = 0;  // into the original text
    std::size_t length = 0;  // bytes replaced (0: an insertion)
    std::string replacement;
};

// Applies every edit. Insertions at the same offset keep the order they were
// given in. Edits must not replace overlapping bytes (JT_DCHECK).
std::string apply_text_edits(std::string_view text, std::vector<TextEdit> edits);

// The whitespace that starts the line holding `offset`.
std::string_view line_indent(std::string_view text, std::size_t offset);
// True when only spaces and tabs precede `offset` on its line.
bool starts_its_line(std::string_view text, std::size_t offset);
// Offset of the first byte of the line holding `offset`.
std::size_t line_start(std::string_view text, std::size_t offset);

}  // namespace jt::edit
