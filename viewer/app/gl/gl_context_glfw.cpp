#include "app/gl/gl_context_glfw.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cstdio>

namespace jt::view {

namespace {
std::string last_glfw_error;
void record_error(int code, const char* description) {
    last_glfw_error = "GLFW error " + std::to_string(code) + ": " + description;
}
}  // namespace

GlfwWindow::GlfwWindow(int width, int height, const std::string& title) {
    glfwSetErrorCallback(record_error);
    if (!glfwInit()) {
        error_ = "cannot open a window (" + last_glfw_error +
                 "); without a display, use --screenshot for headless output";
        return;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);  // shown once it fits the screen
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window_) {
        error_ = "cannot create an OpenGL 3.3 window (" + last_glfw_error + ")";
        glfwTerminate();
        return;
    }
    glfwSetWindowSizeLimits(window_, kMinWindowWidth, kMinWindowHeight, GLFW_DONT_CARE,
                            GLFW_DONT_CARE);
    fit_to_work_area();
    glfwShowWindow(window_);
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(1);
    glfwSetWindowUserPointer(window_, this);
    glfwSetDropCallback(window_, drop_callback);
}

GlfwWindow::~GlfwWindow() {
    if (!window_) return;
    glfwDestroyWindow(window_);
    glfwTerminate();
}

bool GlfwWindow::should_close() const {
    return glfwWindowShouldClose(window_);
}
void GlfwWindow::request_close() {
    glfwSetWindowShouldClose(window_, GLFW_TRUE);
}
void GlfwWindow::cancel_close() {
    glfwSetWindowShouldClose(window_, GLFW_FALSE);
}

float GlfwWindow::content_scale() const {
    float x = 1.0f, y = 1.0f;
    glfwGetWindowContentScale(window_, &x, &y);
    return std::max(x, y);
}

// Scaled to the monitor (GLFW_SCALE_TO_MONITOR) a window can be larger than
// the screen: shrink it to the work area (the screen less panels and docks),
// with room for the title bar, and put it inside.
void GlfwWindow::fit_to_work_area() {
    GLFWmonitor* monitor = glfwGetPrimaryMonitor();
    if (!monitor) return;
    int x = 0, y = 0, w = 0, h = 0;
    glfwGetMonitorWorkarea(monitor, &x, &y, &w, &h);
    if (w <= 0 || h <= 0) return;
    int left = 0, top = 0, right = 0, bottom = 0;
    glfwGetWindowFrameSize(window_, &left, &top, &right, &bottom);
    int width = 0, height = 0;
    glfwGetWindowSize(window_, &width, &height);
    const int fit_w = std::max(w - left - right, 64), fit_h = std::max(h - top - bottom, 64);
    width = std::min(width, fit_w);
    height = std::min(height, fit_h);
    glfwSetWindowSize(window_, width, height);
    glfwSetWindowPos(window_, x + left + (fit_w - width) / 2, y + top + (fit_h - height) / 2);
}

void GlfwWindow::set_title(const std::string& title) {
    glfwSetWindowTitle(window_, title.c_str());
}

void GlfwWindow::hide() {
    glfwHideWindow(window_);
    glfwPollEvents();  // so that the server unmaps it now
}

void GlfwWindow::sizes(int& window_w, int& window_h, int& framebuffer_w, int& framebuffer_h) const {
    glfwGetWindowSize(window_, &window_w, &window_h);
    glfwGetFramebufferSize(window_, &framebuffer_w, &framebuffer_h);
}

void GlfwWindow::swap_buffers() {
    glfwSwapBuffers(window_);
}
void GlfwWindow::poll_events() {
    glfwPollEvents();
}
void GlfwWindow::wait_events(double seconds) {
    glfwWaitEventsTimeout(seconds);
}
void GlfwWindow::wake() {
    glfwPostEmptyEvent();
}

void GlfwWindow::on_drop(std::function<void(const std::string&)> callback) {
    drop_ = std::move(callback);
}

void GlfwWindow::drop_callback(GLFWwindow* window, int count, const char** paths) {
    auto* self = static_cast<GlfwWindow*>(glfwGetWindowUserPointer(window));
    if (!self || !self->drop_) return;
    for (int i = 0; i < count; ++i) self->drop_(paths[i]);
}

GlProcLoader GlfwWindow::proc_loader() {
    return [](const char* name) -> GlProc { return glfwGetProcAddress(name); };
}

}  // namespace jt::view
