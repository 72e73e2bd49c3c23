#pragma once
// Upper bounds on how many records a text can make, counted before it is
// parsed, so that the scene's arrays are sized once instead of growing by
// copies: for a million spheres those copies cost more than the parsing.

#include <cstddef>
#include <string_view>

namespace jt::lang {

// The '{' and ':' of a text.
struct BraceAndColonCount {
    std::size_t braces = 0;
    std::size_t colons = 0;
};

// Counted in one pass, sixteen or eight bytes at a time: two byte-by-byte
// counts were 8% of a dense parse.
BraceAndColonCount count_braces_and_colons(std::string_view text);

// An upper bound on the primitives `text` can hold (each has a '{'), capped by its size.
std::size_t primitive_count_hint(std::string_view text, const BraceAndColonCount& count);

// The same for property records: each has a ':' and takes 4 bytes at least.
std::size_t property_count_hint(std::string_view text, const BraceAndColonCount& count);

}  // namespace jt::lang
