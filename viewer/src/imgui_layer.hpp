#pragma once
// Dear ImGui's context and its OpenGL 3 renderer, for whatever GL context is
// current. The platform side (GLFW events, or a fixed size when headless) is
// fed by the caller before begin_frame().

#include "gl/gl_proc.hpp"

#include <string>

namespace jt::view {

class ImGuiLayer {
  public:
    // Loads the GL functions through `loader` and starts ImGui. ok() is false
    // (with error()) when the context is unusable.
    explicit ImGuiLayer(GlProcLoader loader);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    bool ok() const { return error_.empty(); }
    const std::string& error() const { return error_; }

    // For headless use: sets the display size, scale and time step that a
    // platform backend would otherwise set.
    static void set_display(int width, int height, float framebuffer_scale, float delta_seconds);

    void begin_frame();
    // Clears the framebuffer of `framebuffer_w` x `framebuffer_h` and draws the frame.
    void end_frame(int framebuffer_w, int framebuffer_h);

  private:
    bool started_ = false;
    std::string error_;
};

}  // namespace jt::view
