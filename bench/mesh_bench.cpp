// The million-triangle benchmark (docs/benchmarks.md §5): a model file is read,
// its BVH built and a 1920x1080 frame rendered, each timed on its own, with the
// CPU seconds of the whole process (every thread) beside the wall time, as a
// shared machine stretches wall times, and the process's resident memory after
// each step and at its peak; then the same
// model placed 100 times, to show that instances cost no model memory.
//
//   bench/generate_model.py --triangles 1000000 /tmp/knot1m.ply
//   build/release/bench/mesh-bench /tmp/knot1m.ply [--threads N] [--smooth-angle A]
//
// --smooth-angle gives the mesh that smooth_angle, so that a model without
// normals shows what generating them costs (docs/language.md §14.4).

#include "jtracer/model_cache.hpp"
#include "jtracer/render_job.hpp"
#include "jtracer/scene.hpp"

#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <string>

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// User and system time of every thread of the process so far.
double cpu_seconds() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    auto seconds = [](const timeval& t) { return t.tv_sec + t.tv_usec * 1e-6; };
    return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

// A line of /proc/self/status in MiB: "VmRSS" now, "VmHWM" the peak.
double status_mib(const std::string& key) {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind(key + ":", 0) == 0)
            return std::strtod(line.c_str() + key.size() + 1, nullptr) / 1024.0;
    return 0.0;
}

jt::Scene scene_of(const std::string& file, int copies, std::optional<double> smooth_angle) {
    jt::Scene scene;
    scene.settings.width = 1920;
    scene.settings.height = 1080;
    scene.settings.ambient_light = jt::Colour(0.3);
    jt::Camera camera;
    camera.position = {0.0, 6.0, 14.0};
    camera.look_at = {0.0, 0.0, 0.0};
    camera.aspect = 1920.0 / 1080.0;
    scene.cameras.push_back(camera);
    for (int i = 0; i < copies; ++i) {
        jt::Mesh mesh;
        mesh.file = file;
        mesh.smooth_angle = smooth_angle;
        jt::Primitive p{mesh, {}, {}};
        p.material.pigment = {0.9, 0.6, 0.2};
        p.material.finish.edit().ambient = jt::Colour(0.3);
        p.material.finish.edit().diffuse = jt::Colour(0.9);
        p.material.finish.edit().specular = jt::Colour(0.5);
        if (copies > 1) {
            const double x = (i % 10 - 4.5) * 2.2, z = (i / 10 - 4.5) * 2.2;
            p.transforms = {{jt::TransformKind::scale, jt::Vec3(0.3), 0.0},
                            {jt::TransformKind::yrotate, jt::Vec3(0.0), 36.0 * i},
                            {jt::TransformKind::translate, {x, 0.0, z}, 0.0}};
        }
        scene.primitives.push_back(p);
    }
    scene.lights.push_back({{-10.0, 20.0, 15.0}, jt::Colour(0.8)});
    return scene;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: mesh-bench MODEL.ply [--threads N] [--smooth-angle A]\n");
        return 2;
    }
    const std::string file = argv[1];
    int threads = 0;
    std::optional<double> smooth_angle;
    for (int i = 2; i + 1 < argc; i += 2) {
        if (std::string(argv[i]) == "--threads") threads = std::atoi(argv[i + 1]);
        if (std::string(argv[i]) == "--smooth-angle") smooth_angle = std::atof(argv[i + 1]);
    }

    auto start = Clock::now();
    double cpu_start = cpu_seconds();
    auto model = jt::shared_model(file, ".");
    if (!model) {
        std::fprintf(stderr, "mesh-bench: %s\n", model.error().message.c_str());
        return 1;
    }
    std::printf("model      %zu triangles, %zu vertices\n", (*model)->triangles.size(),
                (*model)->positions.size());
    std::printf("load       %7.3f s   cpu %7.3f s   rss %7.1f MiB\n", seconds_since(start),
                cpu_seconds() - cpu_start, status_mib("VmRSS"));

    for (int copies : {1, 100}) {
        const jt::Scene scene = scene_of(file, copies, smooth_angle);
        start = Clock::now();
        cpu_start = cpu_seconds();
        auto prepared = jt::prepare_scene(scene);
        if (!prepared) {
            std::fprintf(stderr, "mesh-bench: %s\n", prepared.error().message.c_str());
            return 1;
        }
        std::printf("%3d x build %7.3f s   cpu %7.3f s   rss %7.1f MiB\n", copies,
                    seconds_since(start), cpu_seconds() - cpu_start, status_mib("VmRSS"));
        jt::RenderOptions options = jt::render_options_for(scene);
        options.threads = threads;
        start = Clock::now();
        cpu_start = cpu_seconds();
        const jt::Image8 image = jt::render_image(*prepared, options);
        std::printf("%3d x render %6.3f s   cpu %7.3f s   rss %7.1f MiB   (%dx%d)\n", copies,
                    seconds_since(start), cpu_seconds() - cpu_start, status_mib("VmRSS"),
                    image.width, image.height);
    }
    std::printf("peak rss   %7.1f MiB\n", status_mib("VmHWM"));
    return 0;
}
