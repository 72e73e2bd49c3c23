#pragma once
// Values as .jts text (docs/language.md §2.4 numbers, §2.5 strings). Everything that writes a value
// (the serializer, save-in-place, messages, the viewer) writes it this way.

#include "jtracer/scene.hpp"

#include <string>
#include <string_view>

namespace jt {

// The shortest text that reads back as exactly `value` (std::to_chars):
// "0.5", "2", "1e-05", "-2.2354736889656803" only when nothing shorter reads
// back the same. -0 is written "0". Finite values only ("nan", "inf" do not parse).
std::string number_text(double value);

// `value` rounded to a multiple of the power of ten three digits below
// `scale`'s first (scale 2.5: a multiple of 0.01), so that the number an
// editor makes for a scene of that size is short. Below 1 the step is divided
// out by an exact power of ten, so the result is the double nearest the
// decimal and its number_text is short ("1.23"). Never -0; a scale that is
// not positive and finite leaves the value as it is.
double rounded_to_scale(double value, double scale);
Vec3 rounded_to_scale(const Vec3& value, double scale);

// Values made with the mouse (a dragged widget, an orbited camera) are kept to
// the precision a person works at, 6 significant digits, so that the file
// gets 0.3 and -2.23547 rather than 0.30000001192092896 (a float widget's
// value) or -2.2354736889656803 (an orbit's). Values typed in the file are
// never rounded: only what a UI made.
constexpr int kUiDigits = 6;
double ui_rounded(double value);
Vec3 ui_rounded(const Vec3& value);

// "<1, 0.5, 0>": three number_texts.
std::string vector_text(const Vec3& value);

// True when `text` can stand between double quotes in a .jts file:
// printable ASCII and no double quote (there are no escapes).
bool is_writable_string(std::string_view text);

// `text` in double quotes; the caller makes sure it is writable.
std::string string_text(std::string_view text);

// The value `written` (a vector as it appears in a file, "<-5.0, 8.0, 6.0>")
// rewritten to hold `value`: components that already read as their new value
// keep their text (and any comments or spacing between them), the others
// become number_text. Falls back to vector_text when `written` is not a
// plain three-number vector.
std::string edited_vector_text(std::string_view written, const Vec3& value);

}  // namespace jt
