#include "app/image_input.hpp"

#include "app/keys.hpp"
#include "app/panels/widgets.hpp"
#include "app/viewer_frame.hpp"
#include "model/app_actions.hpp"
#include "model/object_drag.hpp"
#include "model/picking.hpp"
#include "model/render_region.hpp"
#include "model/selection_commands.hpp"

#include <imgui.h>
#include <imgui_internal.h>

#include <cmath>
#include <utility>

namespace jt::view {

namespace {

// How much one step of Ctrl+wheel zooms the image.
constexpr float kWheelZoomFactor = 1.25f;

bool pressed(int key) {
    return ImGui::IsKeyPressed(key, false);
}

// The mouse when it is over the image, else the area's centre: what +/- and
// 1:1 zoom about.
ImVec2 zoom_centre(const ImagePlace& image) {
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    if (ImGui::IsMousePosValid() && image.shows(mouse.x, mouse.y)) return mouse;
    return ImVec2((image.area.x0 + image.area.x1) * 0.5f, (image.area.y0 + image.area.y1) * 0.5f);
}

// The keys that act on the selected object or light, as in Blender and most
// editors: Delete or X deletes it, Ctrl+D or Shift+D duplicates it, the
// period key (or the keypad's) frames it (selection_commands.hpp). Once a
// frame, when no text field has the keyboard.
void selection_keys(AppState& state) {
    const ImGuiIO& io = ImGui::GetIO();
    const bool d = pressed(keys::letter('D'));
    if (io.KeyCtrl) {
        if (d) duplicate_selection(state);
        return;
    }
    if (io.KeyAlt) return;
    if (pressed(keys::del) || pressed(keys::letter('X'))) delete_selection(state);
    if (io.KeyShift && d) duplicate_selection(state);
    if (pressed(keys::period) || pressed(keys::keypad_decimal)) frame_selection(state);
}

// How soon after the first Esc (nothing open, nothing unsaved) a second quits.
constexpr double kEscapeAgainSeconds = 2.0;

// Esc cancels a drag that moves an object, else closes whatever is open first
// (a popup, a colour picker, a combo; a text field or a widget being dragged
// handles Esc itself) and asks to quit only when nothing is. Without unsaved
// work it quits on a second Esc: one Esc more than what was open (pressed
// twice to be sure) would close the window, and the render, view and A
// snapshot with it.
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
    const double now = ImGui::GetTime();
    std::optional<double>& asked = state.view.escape_to_quit_at;
    if (!has_unsaved_work(state) && !(asked && now - *asked <= kEscapeAgainSeconds)) {
        asked = now;
        state.message = "Esc again quits (Ctrl+Q quits at once)";
        return;
    }
    asked.reset();
    request_quit(state);  // asks first about unsaved work
}

// Space toggles the pause when let go, unless it was held for a pan.
void handle_space(AppState& state) {
    if (pressed(keys::space)) state.view.space_panned = false;
    if (ImGui::IsKeyReleased(keys::space) && !state.view.space_panned) toggle_pause(state);
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

// A Ctrl+click on the image focuses the shown camera on what it shows.
void focus_click(AppState& state, const ImagePlace& image, float x, float y) {
    if (!image.shows(x, y)) return;
    const std::optional<ImagePoint> at =
        window_to_image(image.where, image.width, image.height, x, y);
    if (!at) return;
    focus_camera_at(state, static_cast<int>(std::floor(at->x)),
                    static_cast<int>(std::floor(at->y)));
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

void end_drag(AppState& state, const ImagePlace& image) {
    const ImageDrag& drag = state.drags.image;
    if (drag.mode == ImageDrag::Mode::region) {
        if (!drag.moved) {  // a Ctrl+click sets no region: it focuses
            if (drag.button == ImGuiMouseButton_Left)
                focus_click(state, image, drag.press_x, drag.press_y);
            return;
        }
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

}  // namespace

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

std::optional<FrameRegion> dragged_region(const ImageDrag& drag, const ImagePlace& image, float x,
                                          float y) {
    const auto at = [&](float wx, float wy) {
        return window_to_image_clamped(image.where, image.width, image.height, wx, wy);
    };
    return region_spanning(at(drag.press_x, drag.press_y), at(x, y), image.width, image.height);
}

void handle_shortcuts(AppState& state, FrameState& frame, const ImagePlace& image) {
    const ImGuiIO& io = ImGui::GetIO();
    handle_escape(state);
    if (const int key = std::exchange(frame.key_after_typing, 0); key != 0) {
        if (key == keys::letter('Q'))
            request_quit(state);
        else
            save_scene(state);
        return;
    }
    if (state.files.unsaved_prompt) return;
    // A value typed into a field and not taken yet would be lost by a quit
    // and left out of a save: Ctrl+Q and Ctrl+S end the typing first.
    if (io.KeyCtrl && typing_a_value())
        for (const int key : {keys::letter('Q'), keys::letter('S')})
            if (pressed(key)) {
                ImGui::ClearActiveID();
                frame.key_after_typing = key;
                return;
            }
    // Ctrl+Q types nothing: it quits (asking first) from a text field too.
    if (io.KeyCtrl && pressed(keys::letter('Q'))) {
        request_quit(state);
        return;
    }
    if (io.WantTextInput) return;  // typing in a field: letters are text
    selection_keys(state);
    if (io.KeyCtrl) {
        if (pressed(keys::letter('S'))) save_scene(state);
        if (pressed(keys::letter('Z'))) io.KeyShift ? redo(state) : undo(state);
        // Ctrl+Y redoes as in the text editor, where many users' hands expect it.
        if (pressed(keys::letter('Y'))) redo(state);
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

// Mouse on the image: a click selects, a Ctrl+click focuses the camera, a
// drag moves the free camera (started from the scene camera) or pans the
// image view, an Alt+drag moves the selection, the wheel dollies the camera and Ctrl+wheel zooms
// the image about the mouse.
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

}  // namespace jt::view
