#include "app/viewer_frame.hpp"

#include "app/keys.hpp"
#include "app/panels/panels.hpp"
#include "app/panels/widgets.hpp"
#include "app/selection_keys.hpp"
#include "app/ui_items.hpp"
#include "model/ab_compare.hpp"
#include "model/app_actions.hpp"
#include "model/document_edits.hpp"
#include "model/object_drag.hpp"
#include "model/picking.hpp"
#include "model/pixel_inspector.hpp"
#include "model/render_region.hpp"

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace jt::view {

namespace {

constexpr const char* unsaved_popup = "Unsaved edits";
// How much one step of Ctrl+wheel zooms the image.
constexpr float kWheelZoomFactor = 1.25f;

bool pressed(int key) {
    return ImGui::IsKeyPressed(key, false);
}

// Esc cancels a drag that moves an object, else closes whatever is open first
// (a popup, a colour picker, a combo; a text field or a widget being dragged
// handles Esc itself) and asks to quit only when nothing is.
void handle_escape(AppState& state) {
    if (!pressed(keys::escape)) return;
    if (state.drags.object) {
        cancel_object_drag(state);
        return;
    }
    if (ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId)) {
        if (state.files.unsaved_prompt) resolve_unsaved(state, UnsavedChoice::cancel);
        ImGui::ClosePopupToLevel(0, true);
        return;
    }
    if (ImGui::IsAnyItemActive() || ImGui::GetIO().WantTextInput) return;
    request_quit(state);
}

// Where the image is this frame: the area it may use, where it is drawn
// (reaching past the area when zoomed in), its size in pixels.
struct ImagePlace {
    ScreenRect area;
    ScreenRect where;
    int width = 0, height = 0;
    float framebuffer_scale = 1.0f;
    // The window point is on the part of the image that shows.
    bool shows(float x, float y) const { return area.contains(x, y) && where.contains(x, y); }
};

ImagePlace place(const AppState& state, const FrameState& frame, ScreenRect area,
                 float framebuffer_scale) {
    const int w = frame.presenter.width(), h = frame.presenter.height();
    return {area, place_image(w, h, area, framebuffer_scale, state.view.image_view), w, h,
            framebuffer_scale};
}

// The mouse when it is over the image, else the area's centre: what +/- and
// 1:1 zoom about.
ImVec2 zoom_centre(const ImagePlace& image) {
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    if (ImGui::IsMousePosValid() && image.shows(mouse.x, mouse.y)) return mouse;
    return ImVec2((image.area.x0 + image.area.x1) * 0.5f, (image.area.y0 + image.area.y1) * 0.5f);
}

void zoom_step(AppState& state, const ImagePlace& image, int steps) {
    const ImVec2 at = zoom_centre(image);
    state.view.image_view = zoom_view_step(state.view.image_view, image.width, image.height,
                                           image.area, image.framebuffer_scale, steps, at.x, at.y);
}

void zoom_actual_pixels(AppState& state, const ImagePlace& image) {
    const ImVec2 at = zoom_centre(image);
    state.view.image_view = zoom_view_to(state.view.image_view, image.width, image.height,
                                         image.area, image.framebuffer_scale, 1.0f, at.x, at.y);
}

// Space toggles the pause when let go, unless it was held for a pan.
void handle_space(AppState& state) {
    if (pressed(keys::space)) state.view.space_panned = false;
    if (ImGui::IsKeyReleased(keys::space) && !state.view.space_panned) toggle_pause(state);
}

void handle_shortcuts(AppState& state, FrameState& frame, const ImagePlace& image) {
    const ImGuiIO& io = ImGui::GetIO();
    handle_escape(state);
    if (io.WantTextInput || state.files.unsaved_prompt)
        return;  // typing in a field: letters are text
    selection_keys(state);
    if (io.KeyCtrl) {
        if (pressed(keys::letter('S'))) save_scene(state);
        if (pressed(keys::letter('Z'))) io.KeyShift ? redo(state) : undo(state);
        if (pressed(keys::letter('Q'))) request_quit(state);
        return;
    }
    if (pressed(keys::letter('R'))) reload_scene(state);
    if (pressed(keys::letter('C'))) next_camera(state);
    if (pressed(keys::letter('S'))) save_image_numbered(state);
    if (pressed(keys::letter('F'))) state.view.image_view = ImageView{};
    if (pressed(keys::digit('1')) || pressed(keys::keypad_1)) zoom_actual_pixels(state, image);
    if (pressed(keys::equal) || pressed(keys::keypad_add)) zoom_step(state, image, 1);
    if (pressed(keys::minus) || pressed(keys::keypad_subtract)) zoom_step(state, image, -1);
    if (pressed(keys::letter('A')) && state.view.compare.a)
        state.view.compare.mode =
            state.view.compare.mode == CompareMode::a ? CompareMode::live : CompareMode::a;
    if (pressed(keys::letter('H'))) state.view.show_ui = !state.view.show_ui;
    if (pressed(keys::letter('T'))) frame.text_editor.open = !frame.text_editor.open;
    handle_space(state);
}

// How far (window units) a press may move and still be a click.
constexpr float kClickSlack = 3.0f;

// How near a light's marker a click must be to select it, in image pixels.
double marker_radius(const ImagePlace& image) {
    return light_marker_radius() * image.width / static_cast<double>(image.where.width());
}

// A click on the image selects what it shows (a light's marker first).
void click_image(AppState& state, const ImagePlace& image, float x, float y) {
    if (!image.shows(x, y)) return;
    const std::optional<ImagePoint> at =
        window_to_image(image.where, image.width, image.height, x, y);
    if (!at) return;
    select_at(state, at->x, at->y, marker_radius(image));
}

// Where window point (x, y) is on the image's plane, also past its edges.
ImagePoint image_point(const ImagePlace& image, float x, float y) {
    return window_to_image_plane(image.where, image.width, image.height, x, y);
}

ImageDrag::Mode drag_mode(int button) {
    if (button == ImGuiMouseButton_Middle) return ImageDrag::Mode::image_pan;
    if (button == ImGuiMouseButton_Right) return ImageDrag::Mode::camera_pan;
    if (ImGui::IsKeyDown(keys::space)) return ImageDrag::Mode::image_pan;
    if (ImGui::GetIO().KeyAlt) return ImageDrag::Mode::move_object;
    if (ImGui::GetIO().KeyCtrl) return ImageDrag::Mode::region;
    return ImageDrag::Mode::orbit;
}

// The region a Ctrl+drag from the press to (x, y) spans, as --region counts it.
std::optional<FrameRegion> dragged_region(const ImageDrag& drag, const ImagePlace& image, float x,
                                          float y) {
    const auto at = [&](float wx, float wy) {
        return window_to_image_clamped(image.where, image.width, image.height, wx, wy);
    };
    return region_spanning(at(drag.press_x, drag.press_y), at(x, y), image.width, image.height);
}

void end_drag(AppState& state, const ImagePlace& image) {
    const ImageDrag& drag = state.drags.image;
    if (drag.mode == ImageDrag::Mode::region) {
        if (!drag.moved) return;  // a Ctrl+click sets no region
        if (const auto region = dragged_region(drag, image, drag.last_x, drag.last_y))
            set_render_region(state, *region);
    } else if (drag.mode == ImageDrag::Mode::move_object && drag.moved) {
        finish_object_drag(state, image_point(image, drag.last_x, drag.last_y), drag.one_axis);
    } else if (!drag.moved && drag.button == ImGuiMouseButton_Left &&
               (drag.mode == ImageDrag::Mode::orbit || drag.mode == ImageDrag::Mode::move_object)) {
        click_image(state, image, drag.press_x, drag.press_y);
    }
}

void follow_drag(AppState& state, const ImagePlace& image, float dx, float dy) {
    switch (state.drags.image.mode) {
        case ImageDrag::Mode::image_pan:
            state.view.image_view = pan_view(state.view.image_view, image.width, image.height,
                                             image.area, image.framebuffer_scale, dx, dy);
            break;
        case ImageDrag::Mode::orbit:
            use_free_camera(state.view, state.doc.scene);
            orbit(state.view.free_camera, dx, dy, image.where.height());
            break;
        case ImageDrag::Mode::camera_pan:
            use_free_camera(state.view, state.doc.scene);
            pan(state.view.free_camera, dx, dy, image.where.height());
            break;
        case ImageDrag::Mode::region:       // drawn while dragging, set when let go
        case ImageDrag::Mode::move_object:  // follows the cursor every frame
            break;
    }
}

// Mouse on the image: a click selects, a drag moves the free camera (started
// from the scene camera) or pans the image view, an Alt+drag moves the
// selection, the wheel dollies the camera and Ctrl+wheel zooms the image
// about the mouse.
void handle_image_mouse(AppState& state, const ImagePlace& image) {
    const ImGuiIO& io = ImGui::GetIO();
    ImageDrag& drag = state.drags.image;
    const bool over = image.shows(io.MousePos.x, io.MousePos.y);
    const bool usable = !io.WantCaptureMouse && state.doc.loaded && image.where.height() > 0;
    if (drag.button >= 0 && !ImGui::IsMouseDown(drag.button)) {
        end_drag(state, image);
        drag.button = -1;
    }
    if (drag.button < 0 && usable && over) {
        for (int button : {ImGuiMouseButton_Left, ImGuiMouseButton_Right, ImGuiMouseButton_Middle})
            if (ImGui::IsMouseClicked(button)) {
                const ImVec2 at = io.MouseClickedPos[button];
                drag = {button, drag_mode(button), at.x, at.y, at.x, at.y, false};
                if (drag.mode == ImageDrag::Mode::image_pan && button == ImGuiMouseButton_Left)
                    state.view.space_panned = true;
                break;
            }
    }
    if (drag.button >= 0 && ImGui::IsMousePosValid()) {
        if (!drag.moved &&
            std::hypot(io.MousePos.x - drag.press_x, io.MousePos.y - drag.press_y) > kClickSlack) {
            drag.moved = true;
            if (drag.mode == ImageDrag::Mode::move_object)
                start_object_drag(state, image_point(image, drag.press_x, drag.press_y),
                                  marker_radius(image));
        }
        if (!drag.moved) return;
        const float dx = io.MousePos.x - drag.last_x, dy = io.MousePos.y - drag.last_y;
        drag.last_x = io.MousePos.x;
        drag.last_y = io.MousePos.y;
        // Every frame, moved or not: a position held back by the write interval is written.
        if (drag.mode == ImageDrag::Mode::move_object) {
            drag.one_axis = io.KeyShift;
            drag_object_to(state, image_point(image, drag.last_x, drag.last_y), drag.one_axis);
        } else if (dx != 0.0f || dy != 0.0f)
            follow_drag(state, image, dx, dy);
    } else if (io.MouseWheel != 0.0f && over && usable) {
        if (io.KeyCtrl) {
            const float zoom = shown_zoom(image.width, image.height, image.area,
                                          image.framebuffer_scale, state.view.image_view) *
                               std::pow(kWheelZoomFactor, io.MouseWheel);
            state.view.image_view =
                zoom_view_to(state.view.image_view, image.width, image.height, image.area,
                             image.framebuffer_scale, zoom, io.MousePos.x, io.MousePos.y);
        } else {
            use_free_camera(state.view, state.doc.scene);
            dolly(state.view.free_camera, io.MouseWheel);
        }
    }
}

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

// The render region over the image, and the one being dragged.
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

// Keeps the compare texture holding what the view shows: A, or the difference
// of A and the live image (again whenever the live image changed).
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

// The live image, or A and the difference as the compare mode asks.
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

void region_and_compare(AppState& state, const FrameState& frame);

void image_toolbar(AppState& state, const FrameState& frame, const ImagePlace& image) {
    const float pad = ImGui::GetStyle().WindowPadding.x;
    ImGui::SetNextWindowPos(ImVec2(image.area.x0 + pad, image.area.y0 + pad));
    ImGui::SetNextWindowBgAlpha(0.75f);
    ImGui::Begin("##image_view", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_AlwaysAutoResize |
                     ImGuiWindowFlags_NoFocusOnAppearing);
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
    ImGui::SameLine();
    // In a small image area the toolbar keeps to one short row, the rest in a
    // menu: it covered a third of the image at 700x450 on a 2x screen.
    if (image.area.width() < ImGui::GetFontSize() * 28.0f) {
        if (button("More", "Render region and A/B compare")) ImGui::OpenPopup("##view_more");
        if (ImGui::BeginPopup("##view_more")) {
            region_and_compare(state, frame);
            ImGui::EndPopup();
        }
    } else {
        region_and_compare(state, frame);
    }
    note_window("image toolbar");
    ImGui::End();
}

void region_and_compare(AppState& state, const FrameState& frame) {
    if (button("Clear region",
               "Render the whole image again. Ctrl+drag on the image renders only that "
               "rectangle (as jtracer-cli --region); the rest keeps what it showed",
               state.view.render_region ? std::string()
                                        : "No region: Ctrl+drag on the image to render only a "
                                          "rectangle of it (as jtracer-cli --region)"))
        clear_render_region(state);
    if (state.view.render_region) {
        ImGui::SameLine();
        ImGui::Text("region %s", format_frame_region(*state.view.render_region).c_str());
    }
    compare_controls(state, frame);
}

// Hovering the image (not dragging) shows what the pixel under the mouse holds.
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

// The sidebar's width: the user's (dragged at its right edge), kept within
// what leaves room for the image.
float sidebar_width(const AppState& state, float window_width) {
    const float font = ImGui::GetFontSize();
    const float least = 20.0f * font;
    const float most = std::max(least, window_width - 12.0f * font);
    return std::clamp(state.view.sidebar_width * font, std::min(least, window_width * 0.6f),
                      std::min(most, window_width * 0.75f));
}

float sidebar(AppState& state, FrameState& frame, float window_width, float height) {
    const float width = sidebar_width(state, window_width);
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(ImVec2(width, height));
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, height), ImVec2(window_width, height));
    ImGui::Begin("JTracer", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoTitleBar);
    // A drag on the right edge resized the window in Begin: remember it. Only
    // a drag: a window too small for the user's width squeezes the panel, and
    // that width is not the user's.
    if (ImGui::GetWindowWidth() != width && ImGui::IsMouseDown(ImGuiMouseButton_Left))
        state.view.sidebar_width = ImGui::GetWindowWidth() / ImGui::GetFontSize();
    ImGui::PushItemWidth(-ImGui::GetFontSize() * 7.5f);
    ImGui::Checkbox("Text editor", &frame.text_editor.open);
    note_item("Text editor", true);
    tooltip("The scene's text beside the image (T): typing re-renders once it parses");
    file_panel(state);
    // A draft with errors is the document now: the panels show the last good
    // scene, and edits to it would be lost when the draft parses.
    const bool draft = state.doc.draft.has_value();
    if (draft) {
        ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "The text is being edited:");
        ImGui::TextWrapped("the panels are read-only until it parses.");
        ImGui::BeginDisabled();
    }
    camera_panel(state);
    settings_panel(state);
    objects_panel(state);
    lights_panel(state);
    if (draft) ImGui::EndDisabled();
    diagnostics_panel(state);
    help_panel();
    ImGui::PopItemWidth();
    const float drawn = ImGui::GetWindowWidth();
    note_window("panel");
    ImGui::End();
    return drawn;
}

float status_height() {
    const ImGuiStyle& style = ImGui::GetStyle();
    return ImGui::GetFrameHeightWithSpacing() + ImGui::GetTextLineHeightWithSpacing() +
           style.WindowPadding.y * 2.0f;
}

void status_window(AppState& state, float y, float width) {
    ImGui::SetNextWindowPos(ImVec2(0, y));
    ImGui::SetNextWindowSize(ImVec2(width, status_height()));
    ImGui::Begin(
        "##status", nullptr,
        ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings);
    status_line(state);
    note_window("status");
    ImGui::End();
}

// Save / Discard / Cancel before a command that would drop unsaved edits.
void unsaved_prompt(AppState& state) {
    if (!state.files.unsaved_prompt) return;
    if (!ImGui::IsPopupOpen(unsaved_popup)) ImGui::OpenPopup(unsaved_popup);
    const ImVec2 centre(ImGui::GetIO().DisplaySize.x * 0.5f, ImGui::GetIO().DisplaySize.y * 0.5f);
    ImGui::SetNextWindowPos(centre, ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    if (!ImGui::BeginPopupModal(unsaved_popup, nullptr,
                                ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove))
        return;
    const bool quitting = state.files.unsaved_prompt->kind == GuardedCommand::Kind::quit;
    const std::string name = state.doc.path.filename().string();
    ImGui::Text("%s has unsaved edits.", name.c_str());
    ImGui::TextUnformatted(quitting ? "Save them before quitting?"
                                    : "Save them before opening another file?");
    std::optional<UnsavedChoice> choice;
    if (button("Save", "Write the edits into the file, then go on")) choice = UnsavedChoice::save;
    same_line_if_fits("Discard");
    if (button("Discard", "Throw the edits away and go on")) choice = UnsavedChoice::discard;
    same_line_if_fits("Cancel");
    if (button("Cancel", "Keep the edits and stay (Esc)")) choice = UnsavedChoice::cancel;
    if (choice) {
        resolve_unsaved(state, *choice);
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

}  // namespace

void viewer_frame(AppState& state, FrameState& frame, const FrameInfo& info) {
    collect_ui_items(&frame.ui_items);
    const ImGuiIO& io = ImGui::GetIO();
    const float w = io.DisplaySize.x, h = io.DisplaySize.y;
    reload_if_changed(state);
    take_finished_load(state);
    take_checked_text(state);
    const EditMark before = begin_edit_tracking(state.history, state.doc);
    // Keys zoom about the image as the last frame placed it.
    handle_shortcuts(state, frame, place(state, frame, frame.image_area, info.framebuffer_scale));

    // A reveal asked for by now is shown by the panels below; one a panel's
    // own button asks for (they act after the panel is drawn) is the next frame's.
    const bool revealing = state.view.reveal_selection;
    ScreenRect area{0, 0, w, h};
    if (state.view.show_ui) {
        const float status_h = std::min(status_height(), h);
        area.x0 = sidebar(state, frame, w, h - status_h);
        area.y1 = h - status_h;
        if (frame.text_editor.open) {
            const float editor_w = std::max((w - area.x0) * 0.45f,
                                            std::min(ImGui::GetFontSize() * 30.0f, w - area.x0));
            area.x1 = w - editor_w;
            text_editor(state, frame.text_editor, area.x1, 0.0f, w, area.y1);
        }
        area.y0 += reload_bar(state, frame.reload_bar, area);
        status_window(state, h - status_h, w);
        if (frame.presenter.has_image())
            image_toolbar(state, frame, place(state, frame, area, info.framebuffer_scale));
        // Once the panel edge is let go: a drag writes the file once, not every frame.
        if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) remember_settings(state.view, state.config);
    }
    if (revealing) state.view.reveal_selection = false;  // the panels have shown it
    unsaved_prompt(state);
    track_edits(state.history, state.doc, before, ImGui::IsAnyItemActive());
    check_edits(state.check, state.doc, state.files);
    update_render(state);
    const std::optional<PixelRect> changed = take_display_changes(state.render);
    if (changed) frame.presenter.upload(state.render.display, changed);
    update_compare_texture(state, frame, changed.has_value());
    const ImagePlace image = place(state, frame, area, info.framebuffer_scale);
    handle_image_mouse(state, image);
    // After the mouse: what is drawn is where this frame's zoom and pan put it.
    const ImagePlace drawn = place(state, frame, area, info.framebuffer_scale);
    inspect_hovered_pixel(state, drawn);
    frame.image_area = drawn.area;
    frame.image_rect = drawn.where;
    ImDrawList* draw_list = ImGui::GetBackgroundDrawList();
    draw_list->PushClipRect(ImVec2(area.x0, area.y0), ImVec2(area.x1, area.y1), true);
    draw_image(state, frame, draw_list, drawn);
    frame.overlay.draw(state, draw_list, drawn.where, drawn.width, drawn.height);
    draw_regions(state, draw_list, drawn);
    draw_list->PopClipRect();
    collect_ui_items(nullptr);
}

std::string window_title(const AppState& state) {
    std::string title = "JTracer";
    if (!state.doc.path.empty()) {
        title += " - " + state.doc.path.filename().string();
        if (has_unsaved_edits(state.doc)) title += " *";
    }
    if (const std::string status = render_title_status(state.render); !status.empty())
        title += " - " + status;
    return title;
}

}  // namespace jt::view
