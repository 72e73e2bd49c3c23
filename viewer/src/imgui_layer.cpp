#include "imgui_layer.hpp"

#include "gl/gl.hpp"
#include "keys.hpp"

#include <imgui.h>
#include <imgui_impl_opengl3.h>

namespace jt::view {

ImGuiLayer::ImGuiLayer(GlProcLoader loader) {
    if (!load_gl_functions(loader, error_)) return;
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // the layout is fixed; no imgui.ini litter in the user's folder
    io.LogFilename = nullptr;
    ImGui::StyleColorsDark();
    use_glfw_key_codes(io);
    if (!ImGui_ImplOpenGL3_Init("#version 330")) {
        error_ = "the ImGui OpenGL 3 renderer could not start";
        ImGui::DestroyContext();
        return;
    }
    started_ = true;
}

ImGuiLayer::~ImGuiLayer() {
    if (!started_) return;
    ImGui_ImplOpenGL3_Shutdown();
    ImGui::DestroyContext();
}

void ImGuiLayer::set_display(int width, int height, float framebuffer_scale, float delta_seconds) {
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
    io.DisplayFramebufferScale = ImVec2(framebuffer_scale, framebuffer_scale);
    io.DeltaTime = delta_seconds > 0.0f ? delta_seconds : 1.0f / 60.0f;
}

void ImGuiLayer::begin_frame() {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
}

void ImGuiLayer::end_frame(int framebuffer_w, int framebuffer_h) {
    ImGui::Render();
    glViewport(0, 0, framebuffer_w, framebuffer_h);
    glClearColor(0.10f, 0.10f, 0.11f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace jt::view
