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

// Whether `text` is a good --define value before the clock is known: one
// that evaluates at clock 0, or one that names `clock` and is whole and
// well formed (whether it evaluates depends on the clock, and the parse at
// that clock says). False with `error` set (the reason at clock 0) otherwise.
bool check_define_value(std::string_view text, std::string& error);

}  // namespace jt::lang
