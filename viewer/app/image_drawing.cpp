#include "app/image_drawing.hpp"

#include "app/image_input.hpp"
#include "app/panels/panels.hpp"
#include "app/panels/widgets.hpp"
#include "app/ui_items.hpp"
#include "model/ab_compare.hpp"
#include "model/picking.hpp"
#include "model/pixel_inspector.hpp"
#include "model/render_region.hpp"

#include <imgui.h>

namespace jt::view {

namespace {

void draw_region(ImDrawList* draw_list, const ImagePlace& image, const FrameRegion& region,
                 ImU32 colour) {
    const PixelRect r = to_image_rect(region, image.height);
    const WindowPoint a =
        image_to_window(image.where, image.width, image.height, {1.0 * r.x0, 1.0 * r.y1});
    const WindowPoint b =
        image_to_window(image.where, image.width, image.height, {1.0 * r.x1, 1.0 * r.y0});
    draw_list->AddRect(ImVec2(a.x - 1, a.y - 1), ImVec2(b.x + 1, b.y + 1), IM_COL32(0, 0, 0, 200),
                       0.0f, 0, 3.0f);
    draw_list->AddRect(ImVec2(a.x - 1, a.y - 1), ImVec2(b.x + 1, b.y + 1), colour, 0.0f, 0, 1.0f);
}

// The image view's controls, over the image's top left corner.
void compare_mode_button(AppState& state, const char* label, CompareMode mode, const char* tip) {
    ImGui::SameLine();
    if (ImGui::RadioButton(label, state.view.compare.mode == mode)) state.view.compare.mode = mode;
    note_item(label, true);
    tooltip(tip);
}

// Snapshot A and how it shows against the live image.
void compare_controls(AppState& state, const FrameState& frame) {
    if (button("Snapshot A",
               "Keep the image as it is now as A, to compare the live render "
               "with (split, A alone, or their difference)"))
        snapshot_a(state);
    if (!state.view.compare.a) return;
    if (!comparable(state.view.compare, state.render.display)) {
        ImGui::SameLine();
        ImGui::TextUnformatted("A has another size than the image");
        return;
    }
    compare_mode_button(state, "Live", CompareMode::live, "The live image alone");
    compare_mode_button(state, "Split", CompareMode::split,
                        "A left of the line, the live image right; drag the slider to move it");
    compare_mode_button(state, "A", CompareMode::a, "A alone (the A key toggles A and live)");
    compare_mode_button(state, "Difference", CompareMode::difference,
                        "Where A and live differ, as jtracer-cli diff draws it: red to yellow "
                        "to white as the difference grows, the rest a dim copy of A");
    if (state.view.compare.mode == CompareMode::split) {
        ImGui::SameLine();
        ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8.0f);
        ImGui::SliderFloat("##split", &state.view.compare.split, 0.0f, 1.0f, "split %.2f");
        note_item("split", true);
        tooltip("Where the line between A (left) and live (right) is");
    } else if (state.view.compare.mode == CompareMode::difference) {
        ImGui::SameLine();
        ImGui::TextUnformatted(frame.compare_summary.c_str());
    }
}

void region_and_compare(AppState& state, const FrameState& frame) {
    if (button("Clear region",
               "Render the whole image again. Ctrl+drag on the image renders only that "
               "rectangle (as jtracer-cli --region); the rest keeps what it showed",
               state.view.render_region ? ""
                                        : "No region: Ctrl+drag on the image to render only a "
                                          "rectangle of it (as jtracer-cli --region)"))
        clear_render_region(state);
    if (state.view.render_region) {
        ImGui::SameLine();
        ImGui::Text("region %s", format_frame_region(*state.view.render_region).c_str());
    }
    compare_controls(state, frame);
}

}  // namespace

void update_compare_texture(const AppState& state, FrameState& frame, bool display_changed) {
    const CompareMode mode = state.view.compare.mode;
    if (!comparable(state.view.compare, state.render.display) || mode == CompareMode::live) return;
    const bool difference = mode == CompareMode::difference;
    const bool stale = frame.compare_holds_version != state.view.compare.a_version ||
                       frame.compare_holds_difference != difference;
    if (!stale && !(difference && display_changed)) return;
    if (difference) {
        CompareDifference diff = compare_difference(state.view.compare, state.render.display);
        frame.compare.upload(diff.image, std::nullopt);
        frame.compare_summary = std::move(diff.summary);
    } else {
        frame.compare.upload(*state.view.compare.a, std::nullopt);
    }
    frame.compare_holds_version = state.view.compare.a_version;
    frame.compare_holds_difference = difference;
}

void draw_image(const AppState& state, const FrameState& frame, ImDrawList* draw_list,
                const ImagePlace& image) {
    const CompareMode mode = state.view.compare.mode;
    if (!comparable(state.view.compare, state.render.display) || mode == CompareMode::live ||
        !frame.compare.has_image()) {
        frame.presenter.draw(draw_list, image.where);
        return;
    }
    if (mode != CompareMode::split) {
        frame.compare.draw(draw_list, image.where);
        return;
    }
    const float x =
        image_to_window(
            image.where, image.width, image.height,
            {static_cast<double>(split_column(state.view.compare, state.render.display)), 0.0})
            .x;
    const ScreenRect& r = image.where;
    draw_list->PushClipRect(ImVec2(r.x0, r.y0), ImVec2(x, r.y1), true);
    frame.compare.draw(draw_list, r);
    draw_list->PopClipRect();
    draw_list->PushClipRect(ImVec2(x, r.y0), ImVec2(r.x1, r.y1), true);
    frame.presenter.draw(draw_list, r);
    draw_list->PopClipRect();
    draw_list->AddLine(ImVec2(x, r.y0), ImVec2(x, r.y1), IM_COL32(255, 255, 255, 200), 1.0f);
}

void draw_regions(const AppState& state, ImDrawList* draw_list, const ImagePlace& image) {
    if (image.width <= 0) return;
    if (state.view.render_region &&
        check_region_in_frame(*state.view.render_region, image.width, image.height))
        draw_region(draw_list, image, *state.view.render_region, IM_COL32(120, 220, 255, 255));
    const ImageDrag& drag = state.drags.image;
    if (drag.button >= 0 && drag.mode == ImageDrag::Mode::region && drag.moved)
        if (const auto region = dragged_region(drag, image, drag.last_x, drag.last_y))
            draw_region(draw_list, image, *region, IM_COL32(255, 255, 255, 255));
}

namespace {

// Fit, 1:1, zoom out and in, and the zoom shown.
void zoom_controls(AppState& state, const ImagePlace& image) {
    if (button("Fit", "The whole image, as large as it fits (F)"))
        state.view.image_view = ImageView{};
    ImGui::SameLine();
    if (button("1:1", "One image pixel per screen pixel (1)")) zoom_actual_pixels(state, image);
    ImGui::SameLine();
    if (button("-", "Zoom the image out (-, or Ctrl+wheel)")) zoom_step(state, image, -1);
    ImGui::SameLine();
    if (button("+",
               "Zoom the image in (+, or Ctrl+wheel); pan with the middle button or "
               "Space+drag"))
        zoom_step(state, image, 1);
    ImGui::SameLine();
    const float zoom = shown_zoom(image.width, image.height, image.area, image.framebuffer_scale,
                                  state.view.image_view);
    ImGui::Text("%.0f%%", zoom * 100.0f);
}

// Image areas narrower than these (in font sizes) get a shorter toolbar: at
// 700x450 on a 2x screen the whole row covered a third of the image, and in
// the smallest window at Xft.dpi 192 even the zoom row ran past its edge.
constexpr float kFullToolbarWidth = 28.0f;
constexpr float kZoomRowWidth = 17.0f;

}  // namespace

void image_toolbar(AppState& state, const FrameState& frame, const ImagePlace& image) {
    const float pad = ImGui::GetStyle().WindowPadding.x;
    ImGui::SetNextWindowPos(ImVec2(image.area.x0 + pad, image.area.y0 + pad));
    ImGui::SetNextWindowBgAlpha(0.75f);
    ImGui::Begin("##image_view", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_AlwaysAutoResize |
                     ImGuiWindowFlags_NoFocusOnAppearing);
    const float width = image.area.width() / ImGui::GetFontSize();
    if (width < kZoomRowWidth) {
        if (button("Image", "Fit and zoom, render region and A/B compare"))
            ImGui::OpenPopup("##view_more");
    } else {
        zoom_controls(state, image);
        ImGui::SameLine();
        if (width >= kFullToolbarWidth)
            region_and_compare(state, frame);
        else if (button("More", "Render region and A/B compare"))
            ImGui::OpenPopup("##view_more");
    }
    if (ImGui::BeginPopup("##view_more")) {
        if (width < kZoomRowWidth) zoom_controls(state, image);
        region_and_compare(state, frame);
        ImGui::EndPopup();
    }
    // Over the image, where it stays in view while the panels scroll.
    time_panel(state, image.area.x1 - pad - ImGui::GetStyle().WindowPadding.x);
    note_window("image toolbar");
    ImGui::End();
}

bool inspector_box_fits(const std::string& text, const ScreenRect& area) {
    const float pad = ImGui::GetStyle().WindowPadding.x;
    return ImGui::CalcTextSize(text.c_str()).x + pad * 4.0f <= area.width();
}

void inspect_hovered_pixel(AppState& state, const ImagePlace& image) {
    state.view.inspected.clear();
    const ImGuiIO& io = ImGui::GetIO();
    if (state.drags.image.button >= 0 || io.WantCaptureMouse || !ImGui::IsMousePosValid()) return;
    // A popup opened this frame (Esc's prompt) is not in WantCaptureMouse yet,
    // and ImGui 1.86 asserts on a window that appears under a modal.
    if (ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel)) return;
    if (!image.shows(io.MousePos.x, io.MousePos.y)) return;
    const std::optional<ImagePoint> at =
        window_to_image(image.where, image.width, image.height, io.MousePos.x, io.MousePos.y);
    if (!at) return;
    const std::optional<PixelReport> report =
        inspect_pixel(state, static_cast<int>(at->x), static_cast<int>(at->y));
    if (!report) return;
    state.view.inspected = describe(*report, state.doc.scene);
    if (!inspector_box_fits(state.view.inspected, image.area)) return;
    // In the image's bottom corner away from the mouse: a box at the mouse sat
    // on the object just picked and hid its outline.
    const float pad = ImGui::GetStyle().WindowPadding.x;
    const bool left = io.MousePos.x > (image.area.x0 + image.area.x1) * 0.5f;
    ImGui::SetNextWindowPos(
        ImVec2(left ? image.area.x0 + pad : image.area.x1 - pad, image.area.y1 - pad),
        ImGuiCond_Always, ImVec2(left ? 0.0f : 1.0f, 1.0f));
    ImGui::SetNextWindowBgAlpha(0.8f);
    ImGui::Begin("##pixel_inspector", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoInputs |
                     ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
    ImGui::TextUnformatted(state.view.inspected.c_str());
    note_window("pixel inspector");
    ImGui::End();
}

}  // namespace jt::view
