#pragma once
// The value of a --define (docs/language.md §15.2), read and evaluated alone.

#include "language/names.hpp"

#include <string>
#include <string_view>

namespace jt::lang {

// Reads `text` as one whole value with no names but `pi` and `clock`. A
// string's `value.text` views `text`. False with `error` set when it is not one.
bool evaluate_define_value(std::string_view text, double clock, ExprValue& value,
                           std::string& error);

}  // namespace jt::lang
