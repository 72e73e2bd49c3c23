#pragma once
// How far two sequences (two texts' bytes, two texts' lines) agree from the
// start and from the end: what a change left alone on either side of it.

#include <algorithm>
#include <cstddef>

namespace jt::view {

struct CommonEnds {
    std::size_t prefix = 0;  // leading elements shared
    // Trailing elements shared, counted on their own: they may reach back
    // into the prefix ("aa" -> "aaa" shares two at each end).
    std::size_t tail = 0;
    // The tail cut where the prefix ends, so that the two never overlap and
    // the middles between them are what changed.
    std::size_t suffix = 0;
};

// `Sequence`: anything with size() and operator[] whose elements compare
// with == (std::string_view, a vector of lines).
template <class Sequence>
CommonEnds common_ends(const Sequence& a, const Sequence& b) {
    const std::size_t shorter = std::min(a.size(), b.size());
    CommonEnds ends;
    while (ends.prefix < shorter && a[ends.prefix] == b[ends.prefix]) ++ends.prefix;
    while (ends.tail < shorter && a[a.size() - 1 - ends.tail] == b[b.size() - 1 - ends.tail])
        ++ends.tail;
    ends.suffix = std::min(ends.tail, shorter - ends.prefix);
    return ends;
}

}  // namespace jt::view
