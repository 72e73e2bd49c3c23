#include "gl/gl_context_glfw.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

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
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window_) {
        error_ = "cannot create an OpenGL 3.3 window (" + last_glfw_error + ")";
        glfwTerminate();
        return;
    }
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
void GlfwWindow::set_title(const std::string& title) {
    glfwSetWindowTitle(window_, title.c_str());
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
