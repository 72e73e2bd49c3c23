#include "model/text_cursor.hpp"

#include <algorithm>
#include <cstddef>

namespace jt::view {

namespace {

std::size_t common_prefix(std::string_view a, std::string_view b) {
    const std::size_t shorter = std::min(a.size(), b.size());
    std::size_t n = 0;
    while (n < shorter && a[n] == b[n]) ++n;
    return n;
}

std::size_t common_suffix(std::string_view a, std::string_view b) {
    const std::size_t shorter = std::min(a.size(), b.size());
    std::size_t n = 0;
    while (n < shorter && a[a.size() - 1 - n] == b[b.size() - 1 - n]) ++n;
    return n;
}

}  // namespace

int cursor_after_replace(std::string_view before, std::string_view after, int cursor) {
    const std::size_t at = static_cast<std::size_t>(std::clamp<long>(cursor, 0, before.size()));
    const std::size_t prefix = common_prefix(before, after);
    const std::size_t tail = common_suffix(before, after);
    // An insertion at the cursor (a redo of typing, an undo of a deletion)
    // leaves it after the text, as typing that text would have. Where the
    // inserted text repeats its neighbours ("1|0" -> "10|0") it could stand
    // anywhere in a run of places; the cursor's is taken when it is one.
    if (after.size() > before.size()) {
        const std::size_t first_place = before.size() - tail;
        if (first_place <= prefix && at >= first_place && at <= prefix)
            return static_cast<int>(at + after.size() - before.size());
    }
    // The changed span, with the unchanged end not reaching back into the
    // unchanged start.
    const std::size_t suffix = std::min(tail, std::min(before.size(), after.size()) - prefix);
    if (at <= prefix) return static_cast<int>(at);
    if (at >= before.size() - suffix) return static_cast<int>(at - before.size() + after.size());
    return static_cast<int>(after.size() - suffix);
}

}  // namespace jt::view
