#include "app/panels/widgets.hpp"

#include "app/ui_items.hpp"
#include "jtracer/value_text.hpp"

#include <imgui.h>
#include <imgui_internal.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iterator>

namespace jt::view {

namespace {

// A float from a widget back to the double it stands for (jtracer/value_text.hpp: ui_rounded).
double from_widget(float f) {
    return ui_rounded(static_cast<double>(f));
}

// The one field whose typed value was last refused, and why. ImGui keeps no
// text for an item between frames, and only one field is typed into at a time.
struct Refusal {
    ImGuiID field = 0;
    std::string message;
};
Refusal& refusal() {
    static Refusal r;
    return r;
}

// After a field's widget (`id`): a refused value notes why, an accepted one
// clears the note, and the note is drawn under its field.
// A whole number's field (`whole`) says the number as typed, not as 1e+05.
void settle_refusal(ImGuiID id, const char* label, bool refused, bool accepted, double typed,
                    const std::function<std::string()>& why, bool whole = false) {
    Refusal& r = refusal();
    if (refused) {
        r.field = id;
        r.message = std::string(label) + ": ";
        r.message += !std::isfinite(typed) ? std::string("the value typed")
                     : whole               ? std::to_string(static_cast<long long>(typed))
                                           : number_text(typed);
        r.message += " is refused: ";
        r.message += why ? why() : std::string("outside the field's range");
    } else if (accepted && r.field == id) {
        r.field = 0;
    }
    if (r.field != id || id == 0) return;
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", r.message.c_str());
    ImGui::PopTextWrapPos();
    note_item(r.message.c_str(), false);
}

// A value typed into a field (Ctrl+click or double-click puts a drag field in
// ImGui's typing mode) is held here until the typing ends, and only then
// taken: ImGui hands back the value of every keystroke, and the scene would
// render at 6 on the way to 60. One field is typed into at a time; the
// values live here, not on the heap, since fields are drawn every frame.
struct Typing {
    ImGuiID field = 0;
    int frame = -1;  // the last frame the field was typed into
    double values[3] = {};
};
Typing& typing() {
    static Typing t;
    return t;
}

// Before a field's widget: whether the user was typing into it (`field`)
// last frame. If so, `values` (n of them) become the ones typed so far, so
// that the widget's text and ImGui's Escape, which restores the text from
// before the typing, both work from them.
template <class T>
bool held_typing(ImGuiID field, T* values, int n) {
    const Typing& t = typing();
    const bool held = field != 0 && t.field == field && t.frame == ImGui::GetFrameCount() - 1;
    if (held)
        for (int i = 0; i < n; ++i) values[i] = static_cast<T>(t.values[i]);
    return held;
}

// After the widget: whether its `values` are to be taken now. While it is
// in typing mode they are held (false); when that ends (Enter, Tab, a click
// elsewhere, Escape) the held ones are taken, which Escape has put back to
// the value from before. A drag is taken as it goes (`changed`). A field
// that stops being drawn while typed into drops what was typed, as ImGui's
// own text fields do.
template <class T>
bool take_typed(ImGuiID field, bool held, const T* values, int n, bool changed) {
    Typing& t = typing();
    const ImGuiID item = ImGui::GetItemID();  // the group's active part, for a vector
    if (item != 0 && ImGui::TempInputIsActive(item)) {
        t.field = field;
        t.frame = ImGui::GetFrameCount();
        for (int i = 0; i < n; ++i) t.values[i] = static_cast<double>(values[i]);
        return false;
    }
    if (held) t.field = 0;
    return changed || held;
}

bool outside(double v, double min, double max) {
    return !std::isfinite(v) || (max > min && !(v >= min && v <= max));
}

// Of two formats number_format gives, the one with more digits.
const char* more_digits(const char* a, const char* b) {
    return std::strcmp(a, b) >= 0 ? a : b;  // "%.4g" < "%.9g"
}

}  // namespace

bool typing_a_value() {
    const Typing& t = typing();
    return t.field != 0 && t.frame == ImGui::GetFrameCount() - 1;
}

const char* number_format(float value, double min, double max) {
    static constexpr const char* formats[] = {"%.4g", "%.5g", "%.6g", "%.7g", "%.8g", "%.9g"};
    if (!(max > min) || !std::isfinite(value)) return formats[0];
    const bool inside = !outside(value, min, max);
    for (const char* format : formats) {
        char shown[64];
        std::snprintf(shown, sizeof shown, format, static_cast<double>(value));
        const float read = std::strtof(shown, nullptr);
        if (inside ? !outside(read, min, max) : read == value) return format;
    }
    return formats[std::size(formats) - 1];  // nine digits read back as the float itself
}

// Drags stop at the bounds; typed values are not clamped by ImGui (no
// AlwaysClamp), so one past them is refused with the reason, never moved.
bool edit_number(const char* label, double& value, float speed, double min, double max,
                 const std::function<std::string()>& why) {
    const ImGuiID id = ImGui::GetID(label);  // the id the widget takes
    float f = static_cast<float>(value);
    const bool held = held_typing(id, &f, 1);
    const bool dragged = ImGui::DragFloat(label, &f, speed, static_cast<float>(min),
                                          static_cast<float>(max), number_format(f, min, max));
    note_item(label, false);
    // Typing the value it had (or Escape) changes nothing, not even its rounding.
    const bool changed = take_typed(id, held, &f, 1, dragged) && f != static_cast<float>(value);
    const double next = changed ? from_widget(f) : value;
    const bool refused = changed && outside(next, min, max);
    const bool accepted = changed && !refused && next != value;
    settle_refusal(id, label, refused, accepted, next, why);
    if (!accepted) return false;
    value = next;
    return true;
}

bool slider_float(const char* label, float& value, float min, float max, const char* format) {
    const ImGuiID id = ImGui::GetID(label);
    float f = value;
    const bool held = held_typing(id, &f, 1);
    const bool moved = ImGui::SliderFloat(label, &f, min, max, format);
    if (!take_typed(id, held, &f, 1, moved) || f == value) return false;
    value = f;
    return true;
}

bool edit_vector(const char* label, Vec3& value, float speed, double min, double max,
                 const std::function<std::string()>& why) {
    const ImGuiID id = ImGui::GetID(label);
    float f[3] = {static_cast<float>(value.x), static_cast<float>(value.y),
                  static_cast<float>(value.z)};
    const bool held = held_typing(id, f, 3);
    const char* format =
        more_digits(number_format(f[0], min, max),
                    more_digits(number_format(f[1], min, max), number_format(f[2], min, max)));
    const bool dragged = ImGui::DragFloat3(label, f, speed, static_cast<float>(min),
                                           static_cast<float>(max), format);
    note_item(label, false);
    const bool changed = take_typed(id, held, f, 3, dragged);
    Vec3 next = value;
    bool refused = false;
    double typed = 0.0;
    for (int i = 0; changed && i < 3; ++i) {
        if (f[i] == static_cast<float>(value[i])) continue;  // untouched: stays exact
        next[i] = from_widget(f[i]);
        if (outside(next[i], min, max)) {
            refused = true;
            typed = next[i];
        }
    }
    const bool accepted = changed && !refused && next != value;
    settle_refusal(id, label, refused, accepted, typed, why);
    if (!accepted) return false;
    value = next;
    return true;
}

bool edit_colour(const char* label, Colour& value) {
    const ImGuiID id = ImGui::GetID(label);
    float f[3] = {static_cast<float>(value.x), static_cast<float>(value.y),
                  static_cast<float>(value.z)};
    const bool held = held_typing(id, f, 3);
    const bool edited = ImGui::ColorEdit3(label, f, ImGuiColorEditFlags_Float);
    note_item(label, false);
    if (!take_typed(id, held, f, 3, edited)) return false;
    Colour next = value;
    for (int i = 0; i < 3; ++i)
        if (f[i] != static_cast<float>(value[i])) next[i] = std::clamp(from_widget(f[i]), 0.0, 1.0);
    if (next == value) return false;
    value = next;
    return true;
}

// Whole numbers follow the same rule as edit_number: a typed value past the
// bounds is refused and the field says why, never clamped to the bound.
bool edit_int(const char* label, int& value, int min, int max,
              const std::function<std::string()>& why) {
    const ImGuiID id = ImGui::GetID(label);
    int v = value;
    const bool held = held_typing(id, &v, 1);
    const bool dragged = ImGui::DragInt(label, &v, 1.0f, min, max, "%d");
    note_item(label, false);
    const bool changed = take_typed(id, held, &v, 1, dragged);
    const bool refused = changed && max > min && (v < min || v > max);
    const bool accepted = changed && !refused && v != value;
    settle_refusal(id, label, refused, accepted, v, why, /*whole=*/true);
    if (!accepted) return false;
    value = v;
    return true;
}

bool edit_optional_colour(const char* label, std::optional<Colour>& value, const Colour& when_set) {
    bool on = value.has_value();
    ImGui::PushID(label);
    const bool toggled = ImGui::Checkbox("##set", &on);
    note_item(label, true);
    tooltip(on ? "Set: clear the box to take it out of the material"
               : "Not set: tick the box to give the material one");
    ImGui::SameLine();
    bool changed = false;
    if (toggled) {
        value = on ? std::optional<Colour>(when_set) : std::nullopt;
        changed = true;
    }
    if (value) {
        Colour colour = *value;
        if (edit_colour(label, colour)) {
            value = colour;
            changed = true;
        }
    } else {
        ImGui::TextDisabled("%s (none)", label);
    }
    ImGui::PopID();
    return changed;
}

bool edit_file_name(const char* label, std::string& value, const char* tooltip_text) {
    std::string edited = value;
    const bool enter =
        ImGui::InputTextWithHint(label, "none", &edited, ImGuiInputTextFlags_EnterReturnsTrue);
    note_item(label, true);
    const bool writable = is_writable_string(edited);
    tooltip(writable ? tooltip_text
                     : "This name cannot be written in a .jts string (quotes, control or "
                       "non-ASCII characters): Enter does not apply it");
    if (!enter || !writable || edited == value) return false;
    value = edited;
    return true;
}

bool panel_header(const char* label, const char* id, bool default_open) {
    const bool open =
        ImGui::CollapsingHeader(label, default_open ? ImGuiTreeNodeFlags_DefaultOpen : 0);
    note_item(id, false);
    return open;
}

void tooltip(const char* text) {
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 28.0f);
        ImGui::TextUnformatted(text);
        ImGui::PopTextWrapPos();
        ImGui::EndTooltip();
    }
}

bool button(const char* label, const char* tooltip_text, const char* why_disabled, float width) {
    const bool disabled = why_disabled && *why_disabled;
    ImGui::BeginDisabled(disabled);
    const bool clicked = ImGui::Button(label, ImVec2(width, 0.0f));
    ImGui::EndDisabled();
    tooltip(disabled ? why_disabled : tooltip_text);
    note_item(label, true);
    return clicked && !disabled;
}

bool button(const char* label, const char* tooltip_text, const std::string& why_disabled) {
    return button(label, tooltip_text, why_disabled.c_str());
}

void scroll_here_if_hidden() {
    const float y = ImGui::GetCursorPosY();
    const float top = ImGui::GetScrollY();
    const float bottom = top + ImGui::GetWindowHeight() - 3.0f * ImGui::GetFrameHeightWithSpacing();
    if (y < top || y > bottom) ImGui::SetScrollHereY(0.2f);
}

void hint_text(const char* full, const char* brief, const char* id) {
    const float room = ImGui::GetContentRegionAvail().x;
    const bool fits = ImGui::CalcTextSize(full).x <= room;
    // Not even the brief form fits (a tiny window): no hint, but the line
    // still ends here, as it would after the text.
    if (!fits && ImGui::CalcTextSize(brief).x > room) {
        ImGui::Dummy(ImVec2(0.0f, ImGui::GetTextLineHeight()));
        return;
    }
    ImGui::TextDisabled("%s", fits ? full : brief);
    if (!fits) tooltip(full);
    note_item(id, !fits);
}

void same_line_if_fits(const char* label) {
    const ImGuiStyle& style = ImGui::GetStyle();
    const float width = ImGui::CalcTextSize(label, nullptr, true).x + style.FramePadding.x * 2.0f;
    const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    if (ImGui::GetItemRectMax().x + style.ItemSpacing.x + width <= right) ImGui::SameLine();
}

bool edit_optional_number(const char* label, std::optional<double>& value, double when_set,
                          const char* unset_note, float speed, double min, double max,
                          const std::function<std::string()>& why) {
    bool on = value.has_value();
    ImGui::PushID(label);
    const bool toggled = ImGui::Checkbox("##set", &on);
    note_item(label, true);
    tooltip(on ? "Set: clear the box to go back to the value it takes when not written"
               : "Not set: tick the box to write the value shown, then edit it");
    ImGui::SameLine();
    bool changed = false;
    if (toggled) {
        value = on ? std::optional<double>(when_set) : std::nullopt;
        changed = true;
    }
    if (value) {
        double number = *value;
        if (edit_number(label, number, speed, min, max, why)) {
            value = number;
            changed = true;
        }
    } else {
        ImGui::TextDisabled("%s: %s", label, unset_note);
        char shown[160];
        std::snprintf(shown, sizeof shown, "%s: %s", label, unset_note);
        note_item(shown, false);
    }
    ImGui::PopID();
    return changed;
}

bool edit_choice(const char* label, std::string& value, std::span<const std::string_view> choices) {
    std::string chosen = value;
    if (ImGui::BeginCombo(label, value.c_str())) {
        for (std::string_view choice : choices) {
            const std::string word(choice);
            if (ImGui::Selectable(word.c_str(), word == value)) chosen = word;
            note_item(word.c_str(), false);
        }
        ImGui::EndCombo();
    }
    note_item(label, true);
    if (chosen == value) return false;
    value = chosen;
    return true;
}

}  // namespace jt::view
