#include "model/text_cursor.hpp"

#include "model/common_ends.hpp"

#include <algorithm>
#include <cstddef>

namespace jt::view {

int cursor_after_replace(std::string_view before, std::string_view after, int cursor) {
    const std::size_t at = static_cast<std::size_t>(std::clamp<long>(cursor, 0, before.size()));
    const auto [prefix, tail, suffix] = common_ends(before, after);
    // An insertion at the cursor (a redo of typing, an undo of a deletion)
    // leaves it after the text, as typing that text would have. Where the
    // inserted text repeats its neighbours ("1|0" -> "10|0") it could stand
    // anywhere in a run of places; the cursor's is taken when it is one.
    if (after.size() > before.size()) {
        const std::size_t first_place = before.size() - tail;
        if (first_place <= prefix && at >= first_place && at <= prefix)
            return static_cast<int>(at + after.size() - before.size());
    }
    // Else the changed span, between the unchanged start and end.
    if (at <= prefix) return static_cast<int>(at);
    if (at >= before.size() - suffix) return static_cast<int>(at - before.size() + after.size());
    return static_cast<int>(after.size() - suffix);
}

}  // namespace jt::view
