#pragma once
// Dear ImGui's context and its OpenGL 3 renderer, for whatever GL context is
// current. The platform side (GLFW events, or a fixed size when headless) is
// fed by the caller before begin_frame().

#include "app/gl/gl_proc.hpp"

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

    // The screen's content scale (1 normally, 2 for Xft.dpi 192 or a Retina
    // display) and framebuffer pixels per window unit. Fonts are rasterised at
    // content_scale x their size in framebuffer pixels, so they stay sharp,
    // and every ImGui size is scaled to match. Rebuilds the fonts when changed.
    void set_scale(float content_scale, float framebuffer_scale);
    float content_scale() const { return content_scale_; }
    // False when the TTF fonts were missing and ImGui's bitmap font is used.
    bool using_ttf() const { return using_ttf_; }

    void begin_frame();
    // Clears the framebuffer of `framebuffer_w` x `framebuffer_h` and draws the frame.
    void end_frame(int framebuffer_w, int framebuffer_h);

  private:
    void build_fonts();

    bool started_ = false;
    bool using_ttf_ = false;
    bool frames_begun_ = false;
    float content_scale_ = 0.0f;
    float framebuffer_scale_ = 1.0f;
    std::string error_;
};

}  // namespace jt::view
