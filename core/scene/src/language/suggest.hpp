#pragma once
// Did-you-mean suggestions for unknown names.

#include <span>
#include <string>
#include <string_view>

namespace jt::lang {

// Levenshtein distance between two short words.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The allowed name nearest to `word`, or empty when none is close enough to be
// a plausible typo (case differences always count as close).
std::string_view nearest_name(std::string_view word, std::span<const std::string_view> allowed);

// Our word for a POV-Ray `word` that is a block or a property (`what`):
// 'light_source' is 'point_light'; empty for any other word.
std::string_view pov_ray_word(std::string_view what, std::string_view word);

// "a, b and c" (or "a, b or c" with `last` "or").
std::string listed(std::span<const std::string_view> names, std::string_view last);

// "a point_light takes no 'material': only sphere, ... and mesh do": one
// message for a material or transform in a light, whether written as a block
// or as a property (`material: NAME;`).
std::string takes_no_message(std::string_view light_keyword, std::string_view word);

// "unknown property 'radus' in sphere; did you mean 'radius'? (allowed: center, radius)"
std::string unknown_name_message(std::string_view what, std::string_view word,
                                 std::string_view where, std::span<const std::string_view> allowed);

}  // namespace jt::lang
