// How long the viewer takes to show something after the user acts: from an
// open (in a new viewer: nothing prepared yet), a reload, a material edit or a
// camera change being requested to the first preview pass (1/16 or 1/8
// resolution) of the new render being in the texture.
//
//   viewer_latency [--runs N] [--pace HZ] [--no-wait] [--render-priority-normal]
//                  [--first-pass-wait MS] [--opened-pass-wait MS] [--steps]
//                  [--scene file.jts] [--size WxH] [--open-only]
//
// Runs the viewer's own code (loader thread, AppState, frame loop, render
// controller, presenter) in an OSMesa context, as the tests do. Each event is
// timed at three points: the render started (the frame that took the load or
// the edit in), the first pass rendered by the core (on the render thread), and
// the first pass in the texture (the frame that fetched and uploaded it, after
// glFinish: AppState::passes_shown). Frames are
// paced at 60 per second, as the window's vsync paces them (--pace 0: back to
// back), so the last figure includes up to one frame interval. Between frames
// the loop sleeps while the window's loop would (waiting_for_workers: a load or
// a first pass under way) until the loader or the render wakes it, as the
// window does with glfwPostEmptyEvent (--no-wait: a frame every tick, as the
// window did before). The render runs below the frames' priority, as in the
// viewer (--render-priority-normal: at the same), and the frame that starts a
// render waits up to 6 ms for its first pass, as the viewer's does
// (--first-pass-wait MS to change it, 0: not at all), and up to 50 ms when it
// renders an open's preparation made ahead (--opened-pass-wait MS; 0: as any
// other render). --steps adds when each step
// inside was reached. OSMesa draws in software what a GPU draws in a window:
// it gets one thread (LP_NUM_THREADS=1 unless set), so that it takes as little
// as possible from the render. --open-only times the opens alone (for a
// profile of them, or a quicker run on a large scene).

#include "app/gl/gl.hpp"
#include "app/headless.hpp"
#include "jtracer/parser.hpp"
#include "jtracer/source_edit.hpp"
#include "model/app_actions.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <unistd.h>

namespace {

using namespace jt;
using namespace jt::view;
using Clock = std::chrono::steady_clock;

// Milliseconds from the user's action; NaN for a step the event does not have.
struct Timing {
    // Loads only: the loader thread's steps.
    double load_started_ms = NAN, read_ms = NAN, parsed_ms = NAN, validated_ms = NAN,
           taken_ms = NAN;     // taken: the frame took the finished load in
    double started_ms = 0;     // the frame that started the render ended
    double start_call_ms = 0;  // inside that frame, the render was started
    double prepared_ms = 0;    // the render thread prepared the scene and made the job
    double rendered_ms = 0;    // the render thread finished the first pass
    double shown_ms = 0;       // the first pass is in the texture
};

double ms_since(Clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

double ms_between(Clock::time_point t0, Clock::time_point t) {
    return std::chrono::duration<double, std::milli>(t - t0).count();
}

// The steps the viewer recorded, for the render (and load) that answered.
void add_steps(Timing& timing, const AppState& state, Clock::time_point t0, bool load) {
    const RunTimeline run = state.render.renderer.timeline();
    timing.start_call_ms = ms_between(t0, run.started);
    if (run.prepared) timing.prepared_ms = ms_between(t0, *run.prepared);
    if (run.first_pass) timing.rendered_ms = ms_between(t0, *run.first_pass);
    if (!load) return;
    const LoadTimes& l = state.files.last_load_times;
    timing.load_started_ms = ms_between(t0, l.started);
    timing.read_ms = ms_between(t0, l.read);
    timing.parsed_ms = ms_between(t0, l.parsed);
    timing.validated_ms = ms_between(t0, l.validated);
    timing.taken_ms = ms_between(t0, l.taken);
}

// Draws frames from `t0` until the first pass of the render answering the
// current scene is in the texture.
double frame_interval_ms = 1000.0 / 60.0;

bool wait_for_workers = true;
bool render_in_background = true;  // ViewerConfig's default
std::chrono::milliseconds first_pass_wait = ViewerConfig{}.first_pass_wait;
std::chrono::milliseconds opened_first_pass_wait = ViewerConfig{}.opened_first_pass_wait;

// Waits for the next frame: as a swap with vsync would, then as the window's
// event loop does (main.cpp) while a load or a first pass is under way.
void pace(const AppState& state, Clock::time_point frame_start) {
    if (frame_interval_ms > 0)
        std::this_thread::sleep_until(
            frame_start + std::chrono::microseconds(static_cast<long>(frame_interval_ms * 1000)));
    const std::uint64_t seen = state.wakeup.count();
    if (wait_for_workers && waiting_for_workers(state.files, state.render))
        state.wakeup.wait(seen, Clock::now() + workers_frame_wait(state));
}

Timing frames_until_first_pass(HeadlessViewer& viewer, AppState& state, Clock::time_point t0,
                               std::uint64_t jobs_before, bool load = false) {
    Timing timing;
    const auto deadline = t0 + std::chrono::seconds(60);
    for (auto frame_start = t0;; frame_start = Clock::now()) {
        viewer.frame(state);
        glFinish();
        const bool new_job = state.render.renderer.jobs_started() > jobs_before;
        if (timing.started_ms == 0 && new_job) timing.started_ms = ms_since(t0);  // this frame
        // The frame fetched the first pass (in the frame that started the
        // render, when it came within the wait; else in a later one).
        if (new_job && state.render.passes_shown >= 1) {
            timing.shown_ms = ms_since(t0);
            add_steps(timing, state, t0, load);
            return timing;
        }
        pace(state, frame_start);
        if (Clock::now() > deadline) {
            std::fprintf(stderr, "viewer_latency: no first pass within 60 s (%s)\n",
                         state.message.c_str());
            std::exit(1);
        }
    }
}

struct Series {
    std::string name;
    std::vector<Timing> runs;
};

void print(const Series& s, bool steps) {
    auto stats = [&](double Timing::*field, const char* label) {
        std::vector<double> v;
        for (const Timing& t : s.runs)
            if (!std::isnan(t.*field)) v.push_back(t.*field);
        if (v.empty()) return;
        std::sort(v.begin(), v.end());
        const double median =
            v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
        std::printf("  %-16s %-26s median %7.1f ms   min %7.1f   max %7.1f\n", s.name.c_str(),
                    label, median, v.front(), v.back());
    };
    if (steps) {
        stats(&Timing::load_started_ms, "  loader: started");
        stats(&Timing::read_ms, "  loader: file read");
        stats(&Timing::parsed_ms, "  loader: parsed");
        stats(&Timing::validated_ms, "  loader: validated");
        stats(&Timing::taken_ms, "  frame took the load");
        stats(&Timing::start_call_ms, "  render start()");
        stats(&Timing::prepared_ms, "  scene prepared");
    }
    stats(&Timing::started_ms, "render started");
    stats(&Timing::rendered_ms, "first pass rendered");
    stats(&Timing::shown_ms, "first pass in the texture");
}

std::string read(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

// The scene at another size, written to a temporary file to load.
std::filesystem::path resized_copy(const std::filesystem::path& scene, int width, int height) {
    const std::string text = read(scene);
    const ParseResult parsed = parse_scene(text);
    Scene resized = parsed.scene;
    resized.settings.width = width;
    resized.settings.height = height;
    const SourceEditResult edit = apply_scene_edits(text, parsed.source, parsed.scene, resized);
    if (!parsed.ok() || !edit.ok()) {
        std::fprintf(stderr, "viewer_latency: cannot use %s\n", scene.c_str());
        std::exit(1);
    }
    const auto path = std::filesystem::temp_directory_path() /
                      ("jtracer-viewer-latency-" + std::to_string(::getpid()) + ".jts");
    std::ofstream(path, std::ios::binary) << edit.text;
    return path;
}

}  // namespace

int main(int argc, char** argv) {
    int runs = 20, width = 1280, height = 720;
    bool steps = false, open_only = false;
    std::filesystem::path scene = JT_SHOWCASE;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--runs" && i + 1 < argc) {
            runs = std::max(1, std::atoi(argv[++i]));
        } else if (arg == "--pace" && i + 1 < argc) {
            const double hz = std::atof(argv[++i]);
            frame_interval_ms = hz > 0 ? 1000.0 / hz : 0.0;
        } else if (arg == "--no-wait") {
            wait_for_workers = false;
        } else if (arg == "--render-priority-normal") {
            render_in_background = false;
        } else if (arg == "--first-pass-wait" && i + 1 < argc) {
            first_pass_wait = std::chrono::milliseconds(std::max(0, std::atoi(argv[++i])));
        } else if (arg == "--opened-pass-wait" && i + 1 < argc) {
            opened_first_pass_wait = std::chrono::milliseconds(std::max(0, std::atoi(argv[++i])));
        } else if (arg == "--steps") {
            steps = true;
        } else if (arg == "--open-only") {
            open_only = true;
        } else if (arg == "--scene" && i + 1 < argc) {
            scene = argv[++i];
        } else if (arg == "--size" && i + 1 < argc &&
                   std::sscanf(argv[++i], "%dx%d", &width, &height) == 2 && width > 0 &&
                   height > 0) {
        } else {
            std::fprintf(stderr,
                         "usage: viewer_latency [--runs N] [--pace HZ] [--no-wait] "
                         "[--render-priority-normal] [--first-pass-wait MS] "
                         "[--opened-pass-wait MS] [--steps] [--scene file.jts] [--size WxH] "
                         "[--open-only]\n");
            return 2;
        }
    }
    setenv("LP_NUM_THREADS", "1", 0);
    HeadlessViewer viewer(1680, 800);   // the sidebar plus a 1280-wide image area
    viewer.set_check_revisions(false);  // a test's check, not the viewer's cost
    if (!viewer.ok()) {
        std::fprintf(stderr, "viewer_latency: no OSMesa context: %s\n", viewer.error().c_str());
        return 1;
    }
    const std::filesystem::path file = resized_copy(scene, width, height);
    const std::string text = read(file);
    const std::string recoloured = [&] {
        const ParseResult parsed = parse_scene(text);
        Scene changed = parsed.scene;
        changed.primitives[0].material.pigment = Colour(0.3, 0.6, 0.3);
        return apply_scene_edits(text, parsed.source, parsed.scene, changed).text;
    }();
    ViewerConfig config;
    config.watch_interval = std::chrono::hours(1);  // no reloads behind our back
    config.render_in_background = render_in_background;
    config.first_pass_wait = first_pass_wait;
    config.opened_first_pass_wait = opened_first_pass_wait;

    // A render still running when the user acts is the usual case: let it run
    // a little, so the cancel is part of the figure. Each frame is finished
    // as the timed ones are (a window's swap waits likewise): OSMesa draws
    // what a frame queued when it is flushed, so unfinished frames would be
    // drawn inside the next event's time, beside its parse (up to 100 ms of
    // a core).
    auto settle = [&](AppState& state) {
        const auto until = Clock::now() + std::chrono::milliseconds(60);
        while (Clock::now() < until) {
            const auto frame_start = Clock::now();
            viewer.frame(state);
            glFinish();
            pace(state, frame_start);
        }
    };

    Series load{"open (new)", {}}, reload{"reload", {}}, material{"material edit", {}},
        camera{"camera change", {}};
    {
        AppState warm(config);  // first use of the context compiles shaders, uploads fonts
        open_scene(warm, file);
        viewer.run_until_complete(warm, std::chrono::minutes(2));
        glFinish();
    }
    for (int i = 0; i < runs; ++i) {
        // A fresh viewer state each time: nothing prepared to reuse.
        AppState state(config);
        auto t0 = Clock::now();
        request_open(state, file);
        load.runs.push_back(frames_until_first_pass(viewer, state, t0, 0, true));
        settle(state);
    }
    if (open_only) {
        std::filesystem::remove(file);
        std::printf("viewer latency, %s at %dx%d, %d opens\n", scene.filename().c_str(), width,
                    height, runs);
        print(load, steps);
        return 0;
    }
    AppState state(config);
    open_scene(state, file);
    frames_until_first_pass(viewer, state, Clock::now(), 0);
    for (int i = 0; i < runs; ++i) {
        // The file read and parsed again in a running viewer (R, or the watcher).
        settle(state);
        // Saved by an editor: every other time with the floor recoloured.
        std::ofstream(file, std::ios::binary) << (i % 2 ? text : recoloured);
        const auto jobs = state.render.renderer.jobs_started();
        const auto t0 = Clock::now();
        reload_scene(state);
        reload.runs.push_back(frames_until_first_pass(viewer, state, t0, jobs, true));
    }
    for (int i = 0; i < runs; ++i) {
        settle(state);
        const auto jobs = state.render.renderer.jobs_started();
        const auto t0 = Clock::now();
        edit_scene(state, [&](Scene& s) {
            s.primitives[0].material.pigment = Colour(0.2 + 0.03 * (i % 20), 0.4, 0.6);
        });
        material.runs.push_back(frames_until_first_pass(viewer, state, t0, jobs));
    }
    use_free_camera(state.view, state.doc.scene);
    for (int i = 0; i < runs; ++i) {
        settle(state);
        const auto jobs = state.render.renderer.jobs_started();
        const auto t0 = Clock::now();
        orbit(state.view.free_camera, i % 2 ? -15.0f : 15.0f, 0.0f, 720.0f);
        camera.runs.push_back(frames_until_first_pass(viewer, state, t0, jobs));
    }
    std::filesystem::remove(file);

    // What one frame costs with nothing to do: the render finished.
    viewer.run_until_complete(state, std::chrono::minutes(2));
    std::vector<double> idle;
    for (int i = 0; i < std::max(runs, 5); ++i) {
        const auto t0 = Clock::now();
        viewer.frame(state);
        glFinish();
        idle.push_back(ms_since(t0));
    }
    std::sort(idle.begin(), idle.end());

    std::printf(
        "viewer latency, %s at %dx%d, %d runs each, frames at %s%s%s, first pass wait %d ms "
        "(%d ms after an open), %u hardware threads\n",
        scene.filename().c_str(), width, height, runs,
        frame_interval_ms > 0 ? (std::to_string(1000.0 / frame_interval_ms) + " Hz").c_str()
                              : "full speed",
        wait_for_workers ? ", waits for the workers" : ", no waiting",
        render_in_background ? ", render in the background" : ", render at normal priority",
        static_cast<int>(first_pass_wait.count()), static_cast<int>(opened_first_pass_wait.count()),
        std::thread::hardware_concurrency());
    std::printf("  %-16s %-26s median %7.1f ms   min %7.1f   max %7.1f\n", "idle frame",
                "OSMesa 1680x800, UI + image", idle[idle.size() / 2], idle.front(), idle.back());
    print(load, steps);
    print(reload, steps);
    print(material, steps);
    print(camera, steps);
    return 0;
}
