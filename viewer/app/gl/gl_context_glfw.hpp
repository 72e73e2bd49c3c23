#pragma once
// A desktop window with an OpenGL 3.3 core context, through GLFW. A thin shell:
// it owns the window and forwards events; the viewer's frame code does not know
// it exists.

#include "app/gl/gl_proc.hpp"

#include <functional>
#include <string>

struct GLFWwindow;

namespace jt::view {

// The smallest window, in screen units: below it the panel, the text editor
// and the image's toolbar leave no image to see.
inline constexpr int kMinWindowWidth = 800;
inline constexpr int kMinWindowHeight = 520;

class GlfwWindow {
  public:
    // Opens a window and makes its context current. On failure, ok() is false
    // and error() says why (e.g. no DISPLAY).
    GlfwWindow(int width, int height, const std::string& title);
    ~GlfwWindow();
    GlfwWindow(const GlfwWindow&) = delete;
    GlfwWindow& operator=(const GlfwWindow&) = delete;

    bool ok() const { return window_ != nullptr; }
    const std::string& error() const { return error_; }
    GLFWwindow* handle() const { return window_; }

    bool should_close() const;
    void request_close();
    // Takes back a close request (the window manager's close button), so that
    // the viewer can ask about unsaved edits first.
    void cancel_close();
    // The monitor's content scale (2 for Xft.dpi 192 or a Retina screen).
    float content_scale() const;
    void set_title(const std::string& title);
    void hide();
    // Window size in screen units and framebuffer size in pixels; they differ
    // on HiDPI screens.
    void sizes(int& window_w, int& window_h, int& framebuffer_w, int& framebuffer_h) const;
    void swap_buffers();
    void poll_events();
    // Sleeps until an event arrives or `seconds` pass.
    void wait_events(double seconds);
    // Ends a wait_events early; callable from any thread while the window lives.
    static void wake();

    // Called with each path dropped onto the window.
    void on_drop(std::function<void(const std::string&)> callback);
    static GlProcLoader proc_loader();

  private:
    static void drop_callback(GLFWwindow* window, int count, const char** paths);
    void fit_to_work_area();
    GLFWwindow* window_ = nullptr;
    std::function<void(const std::string&)> drop_;
    std::string error_;
};

}  // namespace jt::view
