// What a viewer frame costs when nothing happens: the render is finished, no
// input comes, nothing changes on disk. Dear ImGui's rule is that such a frame
// allocates nothing; this prints how far the viewer is from it.
//
//   viewer_idle_frame [--frames N] [--objects N[,N...]] [--where]
//
// For each scene size (default 10 and 100,000 spheres) the scene is opened in
// the viewer's own frame code (OSMesa, as the tests do) and rendered to the
// end; then N idle frames are timed, twice: the model's side alone
// (model_frame: loads, edits, render requests) and the whole frame (panels,
// ImGui, the texture, drawn by OSMesa in software). Figures: the main
// thread's CPU time per frame (median, min, max) and the heap allocations the
// frame made with operator new (C++ code: ours and the standard library;
// Mesa's and ImGui's malloc calls are not counted). --where prints the call
// stack of each allocation of the last frame measured, to find them
// (tests/common/counting_new.hpp counts them).
// Last, what the undo tracking keeps between edits: copies of the blocks the
// panels show (edit_commands.hpp: settle_block), next to the bytes one copy
// of the whole scene takes.

#include "app/headless.hpp"
#include "common/counting_new.hpp"
#include "model/app_actions.hpp"
#include "model/model_frame.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

using namespace jt;
using namespace jt::view;

double thread_cpu_ms() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

// A scene of `objects` small spheres in a grid, rendered small so that the
// render is soon finished: the figures are about the frames, not the render.
std::filesystem::path write_scene(int objects) {
    std::ostringstream text;
    text << "render_settings { width: 160; height: 90; filename: \"idle.bmp\"; }\n"
            "cameras { perspective_camera { position: <0, 0, 30>; look_at: <0, 0, 0>; "
            "aspect: 1.7777777777777777; fov: 60; } }\n"
            "scene {\n"
            "point_light { position: <10, 20, 40>; intensity: <1, 1, 1>; }\n";
    const int side = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(objects))));
    for (int i = 0; i < objects; ++i)
        text << "sphere { center: <" << (i % side) * 0.1 - side * 0.05 << ", "
             << (i / side) * 0.1 - side * 0.05 << ", 0>; radius: 0.04; }\n";
    text << "}\n";
    const auto path = std::filesystem::temp_directory_path() /
                      ("jtracer-idle-frame-" + std::to_string(::getpid()) + "-" +
                       std::to_string(objects) + ".jts");
    std::ofstream(path, std::ios::binary) << text.str();
    return path;
}

struct FrameCost {
    std::vector<double> cpu_ms;
    std::vector<long long> allocations, bytes;
};

template <typename Frame>
FrameCost measure(int frames, Frame&& frame, bool where) {
    FrameCost cost;
    for (int i = 0; i < frames; ++i) {
        const double t0 = thread_cpu_ms();
        const jt::test::Allocated allocated =
            jt::test::allocated_by(frame, where && i + 1 == frames);
        cost.cpu_ms.push_back(thread_cpu_ms() - t0);
        cost.allocations.push_back(allocated.count);
        cost.bytes.push_back(allocated.bytes);
    }
    return cost;
}

template <typename T>
T median(std::vector<T> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

void print(const char* what, int objects, const FrameCost& cost) {
    const auto [lo, hi] = std::minmax_element(cost.cpu_ms.begin(), cost.cpu_ms.end());
    std::printf(
        "  %-12s %7d objects   cpu median %8.3f ms  min %8.3f  max %8.3f   "
        "allocations median %7lld (%lld bytes)\n",
        what, objects, median(cost.cpu_ms), *lo, *hi, median(cost.allocations), median(cost.bytes));
}

}  // namespace

int main(int argc, char** argv) {
    int frames = 50;
    std::vector<int> sizes = {10, 100000};
    bool where = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--frames" && i + 1 < argc) {
            frames = std::max(1, std::atoi(argv[++i]));
        } else if (arg == "--objects" && i + 1 < argc) {
            sizes.clear();
            std::stringstream list(argv[++i]);
            for (std::string item; std::getline(list, item, ',');)
                sizes.push_back(std::max(1, std::atoi(item.c_str())));
        } else if (arg == "--where") {
            where = true;
        } else {
            std::fprintf(stderr,
                         "usage: viewer_idle_frame [--frames N] [--objects N[,N...]] [--where]\n");
            return 2;
        }
    }
    setenv("LP_NUM_THREADS", "1", 0);
    HeadlessViewer viewer(1280, 720);
    viewer.set_check_revisions(false);  // a test's check, not the viewer's cost
    if (!viewer.ok()) {
        std::fprintf(stderr, "viewer_idle_frame: no OSMesa context: %s\n", viewer.error().c_str());
        return 1;
    }
    ViewerConfig config;
    config.watch_interval = std::chrono::hours(1);  // the file watcher is not part of it
    std::printf("idle viewer frames, %d frames each, OSMesa 1280x720 (main thread only)\n", frames);
    for (const int objects : sizes) {
        const std::filesystem::path file = write_scene(objects);
        AppState state(config);
        open_scene(state, file);
        if (!viewer.run_until_complete(state, std::chrono::minutes(5), 10)) {
            std::fprintf(stderr, "viewer_idle_frame: the render of %d objects did not finish: %s\n",
                         objects, state.message.c_str());
            return 1;
        }
        print("model frame", objects,
              measure(
                  frames, [&] { model_frame(state); }, where));
        print("whole frame", objects,
              measure(
                  frames, [&] { viewer.frame(state); }, where));
        // What the undo tracking keeps between edits: copies of the blocks the
        // panels show, against what one copy of the whole scene would take.
        long long kept = 0;
        for (const BlockCopy& copy : state.history.settled)
            kept += static_cast<long long>(sizeof copy) +
                    jt::test::allocated_by([&] { BlockCopy again = copy; }).bytes;
        const long long scene_bytes =
            jt::test::allocated_by([&] { Scene again = state.doc.scene; }).bytes;
        std::printf(
            "  edit tracking %7d objects   %zu block copies kept (%lld bytes); a scene "
            "copy would take %lld bytes\n",
            objects, state.history.settled.size(), kept, scene_bytes);
        std::filesystem::remove(file);
    }
    return 0;
}
