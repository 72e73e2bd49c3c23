#include "model/text_cursor.hpp"

#include <algorithm>
#include <cstddef>

namespace jt::view {

int cursor_after_replace(std::string_view before, std::string_view after, int cursor) {
    const std::size_t at = static_cast<std::size_t>(std::clamp<long>(cursor, 0, before.size()));
    const std::size_t shorter = std::min(before.size(), after.size());
    std::size_t prefix = 0;
    while (prefix < shorter && before[prefix] == after[prefix]) ++prefix;
    std::size_t suffix = 0;
    while (suffix < shorter - prefix &&
           before[before.size() - 1 - suffix] == after[after.size() - 1 - suffix])
        ++suffix;
    // An insertion at the cursor (a redo of typing, an undo of a deletion)
    // leaves it after the text, as typing that text would have.
    const bool insertion_at_cursor = prefix + suffix == before.size() && at == prefix;
    if (at <= prefix && !insertion_at_cursor) return static_cast<int>(at);
    if (at >= before.size() - suffix) return static_cast<int>(at - before.size() + after.size());
    return static_cast<int>(after.size() - suffix);
}

}  // namespace jt::view
