#pragma once
// ImGui widgets for the scene's double-precision values, and buttons that
// explain themselves. ImGui edits floats; a value is written back only when
// the user changed it, rounded to the precision the widget shows, so
// untouched values stay exactly as parsed. Every widget is recorded in the
// frame's UI items (ui_items.hpp) under its label.

#include "jtracer/scene.hpp"

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace jt::view {

// A number (or each of a vector's components, or a whole number) held to [min, max] when
// max > min: dragging stops at the bounds, and a value typed past them is
// refused, the field keeping its value and saying `why()` ("must be at most
// 1e+09") under it until it is next changed. A value typed into a field
// (Ctrl+click or double-click) is taken when the typing ends (Enter, Tab, a
// click elsewhere; Escape drops it), never keystroke by keystroke: typing 60
// does not render at 6 first. A drag applies as it goes. The same holds for
// every widget below.
bool edit_number(const char* label, double& value, float speed, double min = 0.0, double max = 0.0,
                 const std::function<std::string()>& why = {});
bool edit_vector(const char* label, Vec3& value, float speed = 0.05f, double min = 0.0,
                 double max = 0.0, const std::function<std::string()>& why = {});
bool edit_colour(const char* label, Colour& value);
// A value is being typed into one of these fields (it was in typing mode last
// frame): not taken yet. Ending the typing (ImGui::ClearActiveID) before the
// panels are drawn has them take it this frame.
bool typing_a_value();
// The printf format a number's field shows `value` with: "%.4g", or more
// digits (up to "%.9g") where four would show a value inside [min, max] as
// one outside it (179.98 in a fov field held below 180 shows "179.98", not
// "180"); a value outside [min, max] (a bound moved inside an open one)
// shows as itself. A literal: nothing is allocated.
const char* number_format(float value, double min, double max);
// A slider of a value that is no scene property (the clock): dragged, it
// changes as it goes; typed (Ctrl+click), when the typing ends, as above.
bool slider_float(const char* label, float& value, float min, float max, const char* format);
bool edit_int(const char* label, int& value, int min, int max,
              const std::function<std::string()>& why = {});
// A colour that may be unset (a material's checker): a checkbox sets it (to
// `when_set`) or clears it, and its colour is edited while set.
bool edit_optional_colour(const char* label, std::optional<Colour>& value, const Colour& when_set);
// A number that may be unset (a camera's focus_distance, a mesh's
// smooth_angle): a checkbox sets it (to `when_set`) or clears it. While unset
// the field shows, greyed, what the property stands for then (`unset_note`,
// "7.07 = |look_at - position|"); while set it is edit_number's field.
bool edit_optional_number(const char* label, std::optional<double>& value, double when_set,
                          const char* unset_note, float speed, double min = 0.0, double max = 0.0,
                          const std::function<std::string()>& why = {});
// One of a string property's few allowed words (a mesh's shading), as a combo.
bool edit_choice(const char* label, std::string& value, std::span<const std::string_view> choices);
// A file name (a material's image_map), applied when Enter is pressed; a
// name a .jts string cannot hold is refused and the field shows why.
bool edit_file_name(const char* label, std::string& value, const char* tooltip_text);

// A panel's collapsing header, recorded under `id` (its label without counts).
bool panel_header(const char* label, const char* id, bool default_open);

// A button that says what it does when hovered. With `why_disabled` set (not
// empty) it is greyed out and its tooltip says why instead. A literal reason
// takes the const char* form, which builds no string on every frame.
// `width` 0: as wide as the label; more: that wide (a button whose label
// changes keeps what follows it in place).
bool button(const char* label, const char* tooltip, const char* why_disabled = "",
            float width = 0.0f);
bool button(const char* label, const char* tooltip, const std::string& why_disabled);
// Shows `text` while the last item is hovered, also when it is disabled.
void tooltip(const char* text);
// Scrolls the window so that the next item is in view, only when it is not:
// a reveal of what the user just added there must not move what they are
// about to click next.
void scroll_here_if_hidden();
// A greyed-out hint at the rest of the line: `full` when it fits, else
// `brief` with `full` as its tooltip, else none. Never wrapped: a hint that
// took a second line would move what is under it. Recorded under `id`.
void hint_text(const char* full, const char* brief, const char* id);
// Puts the next button on the line of the last item when `label` fits there,
// so that a row of buttons wraps instead of running off the panel.
void same_line_if_fits(const char* label);

}  // namespace jt::view
