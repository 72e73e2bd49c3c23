#include "app/panels/property_fields.hpp"

#include "app/ui_items.hpp"
#include "jtracer/value_text.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace jt::view {

FieldBounds field_bounds(const ValueRange& range) {
    constexpr double open_step = 1e-4;  // relative to the bound's size
    FieldBounds b{range.low, range.high};
    if (range.low_open) b.min += open_step * std::max(1.0, std::abs(range.low));
    if (range.high_open) b.max -= open_step * std::max(1.0, std::abs(range.high));
    return b;
}

float field_speed(const ValueRange& range, std::string_view unit, double size) {
    // The language's limit on every number is no scale for a drag.
    if (range.low > -kMaxMagnitude && range.high < kMaxMagnitude)
        return static_cast<float>((range.high - range.low) / 200.0);
    if (unit == "degrees") return 0.5f;
    return static_cast<float>(std::max(0.01, 0.01 * std::abs(size)));
}

void shared_text_line(const SceneDocument& doc, const BlockSource* block) {
    const SharedText shared = shared_text(doc, block);
    char buffer[256];
    const std::string_view note = shared_text_note(shared, buffer);
    if (note.empty()) return;
    // Read once it is only where the value is; read more than once, a warning.
    const bool many = shared.readings > 1;
    ImGui::PushStyleColor(ImGuiCol_Text, many ? IM_COL32(230, 190, 80, 255)
                                              : ImGui::GetColorU32(ImGuiCol_TextDisabled));
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(note.data(), note.data() + note.size());
    ImGui::PopTextWrapPos();
    ImGui::PopStyleColor();
    note_item("included text", false);
}

FieldMark::FieldMark(const SceneDocument* doc, const FieldSource& source)
    : doc_(doc), source_(source), read_only_(doc && jt::view::read_only(source)) {
    if (!doc_) return;
    if (read_only_) {
        ImGui::BeginDisabled();
    } else if (source_.origin == FieldOrigin::inherited) {
        // Tinted: the value is the named material's until edited here.
        ImGui::PushStyleColor(ImGuiCol_FrameBg, ImVec4(0.16f, 0.30f, 0.27f, 0.70f));
        ImGui::PushStyleColor(ImGuiCol_FrameBgHovered, ImVec4(0.20f, 0.40f, 0.36f, 0.70f));
        colours_ = 2;
    }
}

FieldMark::~FieldMark() {
    if (!doc_) return;
    if (read_only_) ImGui::EndDisabled();
    ImGui::PopStyleColor(colours_);
    if (source_.origin == FieldOrigin::unwritten || source_.origin == FieldOrigin::literal) return;
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
        const std::string text = describe_source(*doc_, source_);
        tooltip(text.c_str());
    }
    if (!read_only_) return;
    // What it is computed from, under the field: `= r * 2`, cut to one line.
    const std::string_view written = written_text(*doc_, source_);
    constexpr int most = 48;
    const int shown = static_cast<int>(std::min<std::size_t>(written.size(), most));
    const std::size_t line_end = written.find('\n');
    const int cut = line_end < static_cast<std::size_t>(shown) ? static_cast<int>(line_end) : shown;
    char line[64];
    std::snprintf(line, sizeof line, "= %.*s%s", cut, written.data(),
                  cut < static_cast<int>(written.size()) ? "..." : "");
    ImGui::Indent();
    ImGui::TextDisabled("%s", line);
    ImGui::Unindent();
    note_item(line, true);
    if (ImGui::IsItemHovered()) {
        const std::string text = describe_source(*doc_, source_);
        tooltip(text.c_str());
    }
}

UnsetNumber unset_note(double when_set, const char* note) {
    UnsetNumber unset;
    unset.when_set = when_set;
    std::snprintf(unset.note.data(), unset.note.size(), "%s", note);
    return unset;
}

UnsetNumber unset_number(std::string_view property, const Camera& camera) {
    if (property != "focus_distance") return unset_note(0.0, "not set");
    // As the render takes it: the length that normalises look_at - position.
    const Vec3 d = camera.look_at - camera.position;
    const double distance = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    if (!(distance > 0.0) || !std::isfinite(distance))
        return unset_note(1.0, "not set (look_at is the position)");
    // A number's shortest text fits the small-string buffer: no allocation.
    const std::string shown = number_text(ui_rounded(distance));
    UnsetNumber unset;
    unset.when_set = distance;
    std::snprintf(unset.note.data(), unset.note.size(), "%s = |look_at - position|", shown.c_str());
    return unset;
}

UnsetNumber unset_number(std::string_view property, const Mesh&) {
    // 60 degrees rounds a curved model and keeps a box's 90-degree edges.
    if (property == "smooth_angle")
        return unset_note(60.0, "off (corners without a normal in the file are flat)");
    return unset_note(0.0, "not set");
}

}  // namespace jt::view
