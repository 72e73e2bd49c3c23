#include "viewer_frame.hpp"

#include "app_actions.hpp"
#include "keys.hpp"
#include "panels/panels.hpp"

#include <imgui.h>

#include <cstdio>

namespace jt::view {

namespace {

constexpr float sidebar_width = 390.0f;
constexpr float status_height = 52.0f;

bool pressed(int key) {
    return ImGui::IsKeyPressed(key, false);
}

void handle_shortcuts(AppState& state) {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantTextInput) return;  // typing in a field: letters are text
    if (io.KeyCtrl) {
        if (pressed(keys::letter('S'))) save_scene(state);
        if (pressed(keys::letter('Z'))) io.KeyShift ? redo(state) : undo(state);
        return;
    }
    if (pressed(keys::letter('R'))) reload_scene(state);
    if (pressed(keys::letter('C'))) next_camera(state);
    if (pressed(keys::letter('S'))) save_image(state, state.save_image_path);
    if (pressed(keys::letter('F')))
        state.fit = state.fit == FitMode::fit ? FitMode::actual_pixels : FitMode::fit;
    if (pressed(keys::letter('H'))) state.show_ui = !state.show_ui;
    if (pressed(keys::space)) toggle_pause(state);
    if (pressed(keys::escape)) state.quit = true;
}

// Mouse on the image moves the free camera, starting it from the scene camera.
void handle_camera_mouse(AppState& state, const ScreenRect& image) {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantCaptureMouse || !state.doc.loaded || image.height() <= 0) return;
    const bool over = io.MousePos.x >= image.x0 && io.MousePos.x < image.x1 &&
                      io.MousePos.y >= image.y0 && io.MousePos.y < image.y1;
    const float dx = io.MouseDelta.x, dy = io.MouseDelta.y;
    const bool moved = dx != 0.0f || dy != 0.0f;
    if (ImGui::IsMouseDown(ImGuiMouseButton_Left) && moved && over) {
        use_free_camera(state);
        orbit(state.free_camera, dx, dy, image.height());
    } else if ((ImGui::IsMouseDown(ImGuiMouseButton_Right) ||
                ImGui::IsMouseDown(ImGuiMouseButton_Middle)) &&
               moved && over) {
        use_free_camera(state);
        pan(state.free_camera, dx, dy, image.height());
    } else if (io.MouseWheel != 0.0f && over) {
        use_free_camera(state);
        dolly(state.free_camera, io.MouseWheel);
    }
}

void sidebar(AppState& state, float height) {
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(ImVec2(sidebar_width, height));
    ImGui::Begin("JTracer", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                     ImGuiWindowFlags_NoSavedSettings);
    ImGui::PushItemWidth(-110);
    file_panel(state);
    camera_panel(state);
    settings_panel(state);
    objects_panel(state);
    lights_panel(state);
    diagnostics_panel(state);
    help_panel();
    ImGui::PopItemWidth();
    ImGui::End();
}

void status_window(AppState& state, float y, float width) {
    ImGui::SetNextWindowPos(ImVec2(0, y));
    ImGui::SetNextWindowSize(ImVec2(width, status_height));
    ImGui::Begin(
        "##status", nullptr,
        ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings);
    status_line(state);
    ImGui::End();
}

}  // namespace

void viewer_frame(AppState& state, const FrameInfo& info) {
    const ImGuiIO& io = ImGui::GetIO();
    const float w = io.DisplaySize.x, h = io.DisplaySize.y;
    reload_if_changed(state);
    take_finished_load(state);
    const Scene before = state.doc.scene;
    const std::uint64_t generation = state.scene_generation;
    handle_shortcuts(state);

    ScreenRect area{0, 0, w, h};
    if (state.show_ui) {
        area.x0 = sidebar_width;
        area.y1 = h - status_height;
        sidebar(state, h - status_height);
        status_window(state, h - status_height, w);
    }
    track_edits(state, before, generation, ImGui::IsAnyItemActive());
    update_render(state);
    const ScreenRect image = place_image(state.presenter.width(), state.presenter.height(), area,
                                         info.framebuffer_scale, state.fit);
    handle_camera_mouse(state, image);
    state.presenter.draw(ImGui::GetBackgroundDrawList(), image);
}

std::string window_title(const AppState& state) {
    std::string title = "JTracer";
    if (!state.doc.path.empty()) {
        title += " - " + state.doc.path.filename().string();
        if (has_unsaved_edits(state.doc)) title += " *";
    }
    if (state.started) {
        const RenderProgress p = state.renderer.progress();
        char text[96];
        if (render_complete(state))
            std::snprintf(text, sizeof text, " - done, %d samples, %.1f s", p.samples_done,
                          p.seconds);
        else
            std::snprintf(text, sizeof text, " - %s %d%%", p.pass_name.c_str(),
                          static_cast<int>(p.fraction * 100.0));
        title += text;
    }
    return title;
}

}  // namespace jt::view
