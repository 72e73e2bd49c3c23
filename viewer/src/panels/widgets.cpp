#include "panels/widgets.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace jt::view {

namespace {

// A float from a widget back to the double it stands for: 6 significant
// digits, so 0.3f is saved as 0.3 and not 0.30000001192092896.
double from_widget(float f) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", static_cast<double>(f));
    return std::strtod(text, nullptr);
}

}  // namespace

bool edit_number(const char* label, double& value, float speed, double min, double max) {
    float f = static_cast<float>(value);
    const bool bounded = max > min;
    if (!ImGui::DragFloat(label, &f, speed, static_cast<float>(min), static_cast<float>(max),
                          "%.4g", bounded ? ImGuiSliderFlags_AlwaysClamp : 0))
        return false;
    double next = from_widget(f);
    if (bounded) next = std::clamp(next, min, max);
    if (!std::isfinite(next) || next == value) return false;
    value = next;
    return true;
}

bool edit_vector(const char* label, Vec3& value, float speed) {
    float f[3] = {static_cast<float>(value.x), static_cast<float>(value.y),
                  static_cast<float>(value.z)};
    if (!ImGui::DragFloat3(label, f, speed, 0.0f, 0.0f, "%.4g")) return false;
    Vec3 next = value;
    for (int i = 0; i < 3; ++i)
        if (f[i] != static_cast<float>(value[i]) && std::isfinite(f[i]))
            next[i] = from_widget(f[i]);
    if (next == value) return false;
    value = next;
    return true;
}

bool edit_colour(const char* label, Colour& value) {
    float f[3] = {static_cast<float>(value.x), static_cast<float>(value.y),
                  static_cast<float>(value.z)};
    if (!ImGui::ColorEdit3(label, f, ImGuiColorEditFlags_Float)) return false;
    Colour next = value;
    for (int i = 0; i < 3; ++i)
        if (f[i] != static_cast<float>(value[i])) next[i] = std::clamp(from_widget(f[i]), 0.0, 1.0);
    if (next == value) return false;
    value = next;
    return true;
}

bool edit_int(const char* label, int& value, int min, int max) {
    int v = value;
    if (!ImGui::DragInt(label, &v, 1.0f, min, max, "%d", ImGuiSliderFlags_AlwaysClamp))
        return false;
    v = std::clamp(v, min, max);
    if (v == value) return false;
    value = v;
    return true;
}

}  // namespace jt::view
