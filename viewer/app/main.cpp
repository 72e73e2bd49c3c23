// jtracer-view: the interactive progressive viewer.
//
//   jtracer-view [scene.jts]                      a window (GLFW)
//   jtracer-view scene.jts --screenshot out.png   headless (OSMesa), no display needed

#include "app/gl/gl_context_glfw.hpp"
#include "app/headless.hpp"
#include "app/imgui_layer.hpp"
#include "app/key_taps.hpp"
#include "app/viewer_frame.hpp"
#include "model/app_actions.hpp"
#include "model/app_state.hpp"
#include "model/image_files.hpp"

#include "jtracer/frontend/command_line.hpp"
#include "jtracer/frontend/render_flags.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

namespace {

using namespace jt::view;

struct Arguments {
    std::string scene;
    std::string screenshot;
    std::string save_render;
    std::string size = "1280x800";
    bool exit_when_done = false;
    double timeout_seconds = 600;
    int width = 1280, height = 800;
    // --define NAME=VALUE and --clock V, as jtracer-cli reads them; applied
    // to every load and reload.
    std::vector<std::string> defines;
    std::optional<double> clock;
    jt::ParseOptions options() const { return jt::frontend::scene_value_options(defines, clock); }
};

// The showcase installed with the viewer: PREFIX/share/jtracer/scenes beside
// PREFIX/bin. The build tree links share/jtracer/scenes to the sources'
// scenes (viewer/CMakeLists.txt), so an uninstalled viewer finds it the same way.
std::filesystem::path default_scene() {
    std::error_code ec;
    const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", ec);
    const auto showcase = program.parent_path().parent_path() / "share/jtracer/scenes/showcase.jts";
    // Through the build tree's link, the file that an edit changes: the source's.
    const std::filesystem::path real = std::filesystem::weakly_canonical(showcase, ec);
    return ec ? showcase : real;
}

// Seconds > 0 and at most a day; the message quotes the text as typed.
CLI::Validator timeout_check() {
    return CLI::Validator(
        [](std::string& text) -> std::string {
            double seconds = 0;
            const char* end = text.data() + text.size();
            const auto r = std::from_chars(text.data(), end, seconds);
            if (r.ec != std::errc() || r.ptr != end || !(seconds > 0) || seconds > 86400)
                return "takes a number of seconds above 0 and at most 86400, got '" + text + "'";
            return {};
        },
        "SECONDS");
}

// The window's keys and mouse buttons reach ImGui through this, so that a
// quick tap is seen and a click never overtakes the typing before it.
KeyTaps key_taps{GLFW_PRESS, GLFW_RELEASE};

// The mouse buttons as KeyTaps passes them on. The GLFW backend reads the
// buttons' state when a frame starts; these replace it, with the mouse
// where a button changed or the wheel turned (held_mouse_to_imgui).
struct HeldMouse {
    bool down[ImGuiMouseButton_COUNT] = {};
    bool pressed[ImGuiMouseButton_COUNT] = {};  // since the last frame: seen down once at least
    bool moved = false;                         // a button changed since the last frame, at:
    ImVec2 at;
    ImVec2 cursor;  // the cursor as the window's events last placed it
};
HeldMouse held_mouse;

void key_to_imgui(GLFWwindow* window, const KeyEvent& e) {
    if (e.wheel) {
        ImGui_ImplGlfw_ScrollCallback(window, e.scroll_x, e.scroll_y);
        held_mouse.moved = true;
        held_mouse.at = ImVec2(e.x, e.y);
    } else if (e.mouse_button >= 0) {
        if (e.mouse_button >= ImGuiMouseButton_COUNT) return;
        held_mouse.down[e.mouse_button] = e.action == GLFW_PRESS;
        if (e.action == GLFW_PRESS) held_mouse.pressed[e.mouse_button] = true;
        held_mouse.moved = true;
        held_mouse.at = ImVec2(e.x, e.y);
    } else if (e.codepoint != 0) {
        ImGui_ImplGlfw_CharCallback(window, e.codepoint);
    } else {
        ImGui_ImplGlfw_KeyCallback(window, e.key, e.scancode, e.action, e.mods);
    }
}

// After ImGui_ImplGlfw_NewFrame: the buttons as passed on, and in the frame
// that takes a button's change or a wheel turn the mouse where it was made.
void held_mouse_to_imgui() {
    ImGuiIO& io = ImGui::GetIO();
    for (int b = 0; b < ImGuiMouseButton_COUNT; ++b) {
        io.MouseDown[b] = held_mouse.pressed[b] || held_mouse.down[b];
        held_mouse.pressed[b] = false;
    }
    if (held_mouse.moved) io.MousePos = held_mouse.at;
    held_mouse.moved = false;
}

void on_key(GLFWwindow* window, int key, int scancode, int action, int mods) {
    key_taps.event({key, scancode, action, mods, 0},
                   [window](const KeyEvent& e) { key_to_imgui(window, e); });
}

void on_char(GLFWwindow* window, unsigned codepoint) {
    key_taps.event(typed_character(codepoint),
                   [window](const KeyEvent& e) { key_to_imgui(window, e); });
}

// The cursor in event order (glfwGetCursorPos asks where it is now, which
// for an event taken in late is not where the button changed).
void on_cursor(GLFWwindow*, double x, double y) {
    held_mouse.cursor = ImVec2(static_cast<float>(x), static_cast<float>(y));
}

void on_mouse_button(GLFWwindow* window, int button, int action, int) {
    key_taps.event(mouse_button_event(button, action, held_mouse.cursor.x, held_mouse.cursor.y),
                   [window](const KeyEvent& e) { key_to_imgui(window, e); });
}

void on_scroll(GLFWwindow* window, double x, double y) {
    key_taps.event(wheel_event(static_cast<float>(x), static_cast<float>(y), held_mouse.cursor.x,
                               held_mouse.cursor.y),
                   [window](const KeyEvent& e) { key_to_imgui(window, e); });
}

bool parse_size(const std::string& text, int& width, int& height) {
    const char* end = text.data() + text.size();
    const auto w = std::from_chars(text.data(), end, width);
    if (w.ec != std::errc() || w.ptr == end || *w.ptr != 'x') return false;
    const auto h = std::from_chars(w.ptr + 1, end, height);
    if (h.ec != std::errc() || h.ptr != end) return false;
    return width >= 64 && height >= 64 && width <= 8192 && height <= 8192;
}

void print_diagnostics(const AppState& state) {
    const std::string text = format_diagnostics(state.doc);
    if (!text.empty()) std::cerr << text;
}

int run_screenshot(const Arguments& args) {
    HeadlessViewer viewer(args.width, args.height);
    viewer.set_check_revisions(false);  // the tests' check: the user's run never aborts
    if (!viewer.ok()) {
        std::cerr << "jtracer-view: cannot render offscreen: " << viewer.error() << "\n";
        return 1;
    }
    AppState state;
    state.doc.options = args.options();
    open_scene(state, args.scene);
    print_diagnostics(state);
    const auto timeout =
        std::chrono::milliseconds(static_cast<long long>(args.timeout_seconds * 1000));
    const bool complete = viewer.run_until_complete(state, timeout);
    if (const jt::Expected<void> saved = jt::view::save_image(args.screenshot, viewer.screenshot());
        !saved) {
        std::cerr << "jtracer-view: " << saved.error().message << "\n";
        return 1;
    }
    if (!complete) {
        std::cerr << "jtracer-view: the render did not complete ("
                  << (state.render.render_note.empty() ? "timed out" : state.render.render_note)
                  << "); wrote the screenshot as it stands to " << args.screenshot << "\n";
        return 1;
    }
    if (!args.save_render.empty())
        if (const jt::Expected<void> saved =
                jt::view::save_image(args.save_render, state.render.display);
            !saved) {
            std::cerr << "jtracer-view: " << saved.error().message << "\n";
            return 1;
        }
    std::cerr << "jtracer-view: wrote " << args.screenshot << " (" << args.width << "x"
              << args.height << ")\n";
    return 0;
}

int run_window(const Arguments& args) {
    GlfwWindow window(args.width, args.height, "JTracer");
    if (!window.ok()) {
        std::cerr << "jtracer-view: " << window.error() << "\n";
        return 1;
    }
    ImGuiLayer layer(GlfwWindow::proc_loader());
    if (!layer.ok()) {
        std::cerr << "jtracer-view: " << layer.error() << "\n";
        return 1;
    }
    ImGui_ImplGlfw_InitForOpenGL(window.handle(), true);
    // In place of the backend's, which they call.
    glfwSetKeyCallback(window.handle(), on_key);
    glfwSetCharCallback(window.handle(), on_char);
    glfwSetMouseButtonCallback(window.handle(), on_mouse_button);
    glfwSetCursorPosCallback(window.handle(), on_cursor);
    glfwSetScrollCallback(window.handle(), on_scroll);
    {
        double x = 0, y = 0;
        glfwGetCursorPos(window.handle(), &x, &y);
        on_cursor(window.handle(), x, y);
    }
    ImGui::GetIO().BackendFlags |= ImGuiBackendFlags_HasMouseCursors;  // the panel edge resizes
    std::optional<std::string> dropped;
    window.on_drop([&](const std::string& path) { dropped = path; });

    int exit_code = 0;
    {
        // Scoped so the texture and the render thread go before the GL context.
        FrameState frame;
        ViewerConfig config;
        config.settings_file = default_settings_path();
        AppState app(config);
        app.wakeup.set_callback(GlfwWindow::wake);
        app.files.recent.load(default_recent_files_path());
        app.doc.options = args.options();
        open_scene(app, args.scene);
        print_diagnostics(app);
        const auto started = std::chrono::steady_clock::now();
        std::string title;
        int frames_after_done = 0;
        // UI responsiveness while the render runs: frames drawn and the slowest one.
        int busy_frames = 0;
        double busy_seconds = 0.0, slowest_frame = 0.0;
        auto frame_start = std::chrono::steady_clock::now();
        int frames_drawn = 0;
        while (!app.quit) {
            // Idle when the render is done: wake for input or to poll the file.
            // While a load or a render's first pass is under way, sleep until
            // the loader or the render wakes the loop (or input arrives), so
            // that the frame showing it starts at once, not at the next tick.
            // An object drag writes the cursor's last position once its interval
            // passes: frames go on while the mouse holds still.
            // Keys held back for the next frame (key_taps.hpp) need it now.
            if (key_taps.holding())
                window.poll_events();
            else if (render_complete(app.render) && !app.files.loader.busy() && !app.drags.object &&
                     !app.time.playing && !args.exit_when_done)
                window.wait_events(std::chrono::duration<double>(idle_frame_wait).count());
            else if (waiting_for_workers(app.files, app.render))
                window.wait_events(std::chrono::duration<double>(workers_frame_wait(app)).count());
            else
                window.poll_events();
            // The window's close button asks like Esc does when edits are unsaved.
            if (window.should_close()) {
                window.cancel_close();
                request_quit(app);
            }
            if (dropped) {
                request_open_guarded(app, *dropped);
                dropped.reset();
            }
            int ww = 0, wh = 0, fw = 0, fh = 0;
            window.sizes(ww, wh, fw, fh);
            const float scale = ww > 0 ? static_cast<float>(fw) / static_cast<float>(ww) : 1.0f;
            layer.set_scale(window.content_scale(), scale);
            ImGui_ImplGlfw_NewFrame();
            held_mouse_to_imgui();
            layer.begin_frame();
            viewer_frame(app, frame, FrameInfo{scale});
            layer.end_frame(fw, fh);
            key_taps.frame_done([&](const KeyEvent& e) { key_to_imgui(window.handle(), e); });
            window.swap_buffers();
            if (const std::string t = window_title(app); t != title) window.set_title(title = t);
            const auto now = std::chrono::steady_clock::now();
            // Frame 1 compiles shaders and uploads the font: startup, not responsiveness.
            if (!render_complete(app.render) && app.render.started && ++frames_drawn > 2) {
                const double seconds = std::chrono::duration<double>(now - frame_start).count();
                ++busy_frames;
                busy_seconds += seconds;
                slowest_frame = std::max(slowest_frame, seconds);
            }
            frame_start = now;
            if (args.exit_when_done) {
                if (render_complete(app.render) && ++frames_after_done > 2) break;
                if (!app.render.started && !app.render.render_note.empty()) {
                    std::cerr << "jtracer-view: nothing to render: " << app.render.render_note
                              << "\n";
                    exit_code = 1;
                    break;
                }
                if (std::chrono::steady_clock::now() - started >
                    std::chrono::duration<double>(args.timeout_seconds)) {
                    std::cerr << "jtracer-view: the render did not complete in time\n";
                    exit_code = 1;
                    break;
                }
            }
        }
        // Quitting: the window goes at once, then the render's threads stop
        // and the rest is torn down (which can take a moment mid-render).
        window.hide();
        if (args.exit_when_done && exit_code == 0) {
            std::cerr << "jtracer-view: " << window_title(app) << "\n";
            if (busy_frames > 0)
                std::fprintf(stderr,
                             "jtracer-view: UI while rendering: %d frames, %.0f frames/s, "
                             "slowest %.1f ms\n",
                             busy_frames, busy_frames / busy_seconds, slowest_frame * 1000.0);
        }
        app.render.renderer.stop();
    }
    ImGui_ImplGlfw_Shutdown();
    return exit_code;
}

}  // namespace

int main(int argc, char** argv) {
    Arguments args;
    CLI::App cli{"jtracer-view: the interactive progressive viewer of JTracer"};
    cli.add_option("scene", args.scene,
                   "the .jts scene to open (default: the showcase installed with JTracer, "
                   "PREFIX/share/jtracer/scenes/showcase.jts)");
    cli.footer(
        "Examples:\n"
        "  jtracer-view                                  opens the showcase installed with "
        "JTracer\n"
        "  jtracer-view scene.jts\n"
        "  jtracer-view scene.jts --screenshot shot.png --size 1600x1000   no display needed\n"
        "  jtracer-view scene.jts --define r=2 --define 'c=<1, 0, 0>'      set names it defines\n"
        "\n"
        "Exit codes: 0 ok, 1 no window or GL context, a screenshot not written or a render\n"
        "not complete in time, 2 bad command line.\n");
    jt::frontend::add_version_flag(cli, "jtracer-view");
    cli.add_option("--screenshot", args.screenshot,
                   "render headless (OSMesa, no display), write the whole window to this PNG "
                   "once the render completes, and exit")
        ->type_name("FILE");
    cli.add_option("--save-render", args.save_render,
                   "with --screenshot: also write the rendered image itself (not the window) "
                   "to this BMP or PNG, the pixels jtracer-cli writes for the scene")
        ->type_name("FILE");
    jt::frontend::add_scene_value_flags(cli, args.defines, args.clock);
    cli.add_option("--size", args.size, "window or screenshot size, WxH")
        ->capture_default_str()
        ->type_name("WxH");
    cli.add_flag("--exit-when-done", args.exit_when_done,
                 "quit once the render completes (for tests)");
    cli.add_option("--timeout", args.timeout_seconds,
                   "with --screenshot or --exit-when-done: give up after this many seconds")
        ->capture_default_str()
        ->check(timeout_check())
        ->type_name("SECONDS");
    const auto checks = [&] {
        if (!parse_size(args.size, args.width, args.height))
            throw CLI::ValidationError(
                "--size", "takes WxH between 64x64 and 8192x8192, got '" + args.size + "'");
        if (!args.screenshot.empty() &&
            jt::format_named_by(args.screenshot) != jt::ImageFormat::png)
            throw CLI::ValidationError("--screenshot", "writes a PNG: name it .png");
        if (!args.save_render.empty() &&
            (args.screenshot.empty() || !jt::format_named_by(args.save_render)))
            throw CLI::ValidationError("--save-render",
                                       "goes with --screenshot and writes a .bmp or .png");
    };
    if (const std::optional<int> code =
            jt::frontend::parse_command_line(cli, argc, argv, "jtracer-view", checks))
        return *code;
    if (args.scene.empty()) args.scene = default_scene().string();
    if (!args.screenshot.empty()) return run_screenshot(args);
    return run_window(args);
}
