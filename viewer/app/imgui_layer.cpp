#include "app/imgui_layer.hpp"

#include "app/gl/gl.hpp"
#include "app/keys.hpp"

#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <filesystem>

namespace jt::view {

namespace {

// Debian's fonts-dejavu-core (installed by scripts/install-deps.sh).
constexpr const char* ui_font = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
constexpr const char* mono_font = "/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf";
constexpr float ui_font_size = 15.0f;  // in window units at content scale 1

ImFont* monospace = nullptr;  // the second font of the atlas, when loaded

}  // namespace

void push_monospace_font() {
    if (monospace) ImGui::PushFont(monospace);
}
void pop_monospace_font() {
    if (monospace) ImGui::PopFont();
}

void ImGuiLayer::build_fonts() {
    ImGuiIO& io = ImGui::GetIO();
    io.Fonts->Clear();
    monospace = nullptr;
    const float pixels = ui_font_size * content_scale_ * framebuffer_scale_;
    std::error_code ec;
    using_ttf_ = std::filesystem::exists(ui_font, ec) && std::filesystem::exists(mono_font, ec) &&
                 io.Fonts->AddFontFromFileTTF(ui_font, pixels) != nullptr;
    if (using_ttf_) {
        monospace = io.Fonts->AddFontFromFileTTF(mono_font, pixels);
    } else {
        // ImGui's own 13 px bitmap font, scaled: blurry at 2x but readable.
        ImFontConfig config;
        config.SizePixels = 13.0f * content_scale_ * framebuffer_scale_;
        io.Fonts->AddFontDefault(&config);
    }
    io.FontGlobalScale = 1.0f / framebuffer_scale_;  // atlas pixels -> window units
    // The backend makes the font texture with its other GL objects in its first
    // NewFrame; after that a new atlas needs a new texture here.
    ImGui_ImplOpenGL3_DestroyFontsTexture();
    if (frames_begun_) ImGui_ImplOpenGL3_CreateFontsTexture();
    ImGuiStyle style;
    ImGui::StyleColorsDark(&style);
    style.ScaleAllSizes(content_scale_);
    ImGui::GetStyle() = style;
}

void ImGuiLayer::set_scale(float content_scale, float framebuffer_scale) {
    content_scale = content_scale > 0.0f ? content_scale : 1.0f;
    framebuffer_scale = framebuffer_scale > 0.0f ? framebuffer_scale : 1.0f;
    // With window units already scaled (a framebuffer larger than the window),
    // the content scale that is left for ImGui is the rest.
    const float units = std::max(content_scale / framebuffer_scale, 1.0f);
    if (!started_ || (units == content_scale_ && framebuffer_scale == framebuffer_scale_)) return;
    content_scale_ = units;
    framebuffer_scale_ = framebuffer_scale;
    build_fonts();
}

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
    set_scale(1.0f, 1.0f);
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
    frames_begun_ = true;
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
