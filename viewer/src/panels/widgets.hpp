#pragma once
// ImGui widgets for the scene's double-precision values. ImGui edits floats;
// a value is written back only when the user changed it, rounded to the
// precision the widget shows, so untouched values stay exactly as parsed.

#include "jtracer/scene.hpp"

namespace jt::view {

bool edit_number(const char* label, double& value, float speed, double min = 0.0, double max = 0.0);
bool edit_vector(const char* label, Vec3& value, float speed = 0.05f);
bool edit_colour(const char* label, Colour& value);
bool edit_int(const char* label, int& value, int min, int max);

}  // namespace jt::view
