#pragma once
// Values made with the mouse (a dragged widget, an orbited camera) are kept to
// the precision a person works at, 6 significant digits, so that the file
// gets 0.3 and -2.23547 rather than 0.30000001192092896 (a float widget's
// value) or -2.2354736889656803 (an orbit's). Values typed in the file are
// never rounded: only what the UI made.

#include "jtracer/scene.hpp"

namespace jt::view {

constexpr int kUiDigits = 6;

double ui_rounded(double value);
Vec3 ui_rounded(const Vec3& value);

}  // namespace jt::view
