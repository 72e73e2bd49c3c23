// jtracer-cli: scene file in, image file out. The work lives in the core; this
// file only orders the steps and maps failures to exit codes.

#include "memory_budget.hpp"
#include "options.hpp"
#include "progress.hpp"

#include "jtracer/image_file.hpp"
#include "jtracer/region.hpp"
#include "jtracer/region_file.hpp"
#include "jtracer/render_job.hpp"
#include "jtracer/scene_file.hpp"
#include "jtracer/validate.hpp"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <exception>
#include <iostream>
#include <new>
#include <thread>

namespace {

using namespace jt::cli;

// The signal that asked the render to stop (SIGINT, SIGTERM), 0 while none has.
std::atomic<int> interrupted{0};

extern "C" void on_interrupt(int signal) {
    interrupted.store(signal);
}

std::string camera_names(const jt::Scene& scene) {
    std::string names;
    for (const jt::Camera& c : scene.cameras) {
        if (!names.empty()) names += ", ";
        names += "\"" + c.name + "\"";
    }
    return names.empty() ? "none" : names;
}

// Command-line values replace the scene's before validation, so that the
// checks see what will render.
std::optional<int> apply_overrides(const Options& o, jt::Scene& scene) {
    if (o.width) scene.settings.width = *o.width;
    if (o.height) scene.settings.height = *o.height;
    if (o.samples) scene.settings.samples = *o.samples;
    if (o.camera) {
        if (jt::find_camera(scene, *o.camera) < 0) {
            std::cerr << "jtracer-cli: --camera: the scene has no camera named \"" << *o.camera
                      << "\" (its cameras: " << camera_names(scene) << ")\n";
            return exit_usage;
        }
        scene.settings.active_camera = *o.camera;
    }
    return std::nullopt;
}

// Runs the job on a thread of its own while this one draws progress and
// watches for Ctrl-C. Returns false when interrupted.
bool render(jt::RenderJob& job, bool quiet) {
    ProgressDisplay display(quiet, ::isatty(STDERR_FILENO) == 1);
    std::atomic<bool> done{false};
    std::thread worker([&] {
        job.run();
        done.store(true);
    });
    while (!done.load()) {
        if (interrupted.load() != 0) job.cancel();
        display.update(job.progress());
        for (int i = 0; i < 10 && !done.load(); ++i)
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    worker.join();
    display.finish();
    return job.progress().finished;
}

int run(const Options& o) {
    // Without the source map: check_scene builds it only if there is something to locate.
    jt::LoadedScene loaded = jt::load_scene_file(o.scene_path, {.source_map = false});
    if (!loaded.read_ok()) {
        std::cerr << "jtracer-cli: " << loaded.io_error << "\n";
        return exit_io_error;
    }
    if (auto code = apply_overrides(o, loaded.parsed.scene)) return *code;
    std::vector<jt::Diagnostic> diagnostics = jt::check_scene(loaded);
    const bool errors = jt::has_errors(diagnostics);
    if (o.quiet && !errors) diagnostics.clear();  // quiet drops warnings, never errors
    std::cerr << jt::format_diagnostics(diagnostics, loaded.path, loaded.text);
    if (errors) return exit_scene_error;
    if (o.check_only) {
        if (!o.quiet) std::cerr << loaded.path << ": no errors\n";
        return exit_ok;
    }
    // The text served the diagnostics only: give its memory back before the
    // renderer builds its own.
    std::string().swap(loaded.text);

    const jt::Scene& scene = loaded.parsed.scene;
    // The manual's rule: the scene's filename always yields a BMP; only a name
    // typed on the command line may ask for PNG.
    const std::string output = o.output.value_or(scene.settings.filename);
    const jt::ImageFormat format =
        o.output ? jt::format_from_extension(output) : jt::ImageFormat::bmp;

    jt::RenderOptions options;
    options.width = scene.settings.width;
    options.height = scene.settings.height;
    options.samples = scene.settings.samples;
    options.camera = jt::active_camera_index(scene);
    options.threads = o.threads;
    options.previews = false;
    if (o.region) {
        const std::string error =
            jt::check_region_in_frame(*o.region, options.width, options.height);
        if (!error.empty()) {
            std::cerr << "jtracer-cli: --region: " << error << "\n";
            return exit_usage;
        }
        options.region = jt::to_image_rect(*o.region, options.height);
    }

    if (std::string error = check_render_memory(options, o.region_output); !error.empty()) {
        std::cerr << "jtracer-cli: " << error << "; nothing was written\n";
        return exit_io_error;
    }
    // Until the job exists a signal ends the process at once (nothing is written
    // yet); from here on it cancels the render, which stops within a tile.
    jt::RenderJob job(jt::prepare_scene(scene), options);
    std::signal(SIGINT, on_interrupt);
    std::signal(SIGTERM, on_interrupt);
    if (!render(job, o.quiet) || interrupted.load() != 0) {
        const int signal = interrupted.load() != 0 ? interrupted.load() : SIGINT;
        std::cerr << "jtracer-cli: interrupted by " << (signal == SIGTERM ? "SIGTERM" : "SIGINT")
                  << "; nothing was written\n";
        return 128 + signal;
    }
    // A region file keeps only the region's pixels and records where they belong.
    const std::string error = o.region_output
                                  ? jt::write_region_bmp(output, job.region_image(),
                                                         {options.width, options.height, *o.region})
                                  : jt::write_image(output, job.image(), format);
    if (!error.empty()) {
        std::cerr << "jtracer-cli: " << error << "\n";
        return exit_io_error;
    }
    if (!o.quiet)
        std::cerr << "wrote " << output << ": "
                  << render_summary(options.width, options.height, options.samples, job.progress())
                  << "\n";
    return exit_ok;
}

}  // namespace

int main(int argc, char** argv) {
    ParsedOptions parsed = parse_options(argc, argv);
    if (parsed.exit_code) return *parsed.exit_code;
    try {
        return run(parsed.options);
    } catch (const std::bad_alloc&) {
        std::cerr << "jtracer-cli: out of memory (is the image too large?); nothing was written\n";
        return exit_io_error;
    } catch (const std::exception& e) {
        std::cerr << "jtracer-cli: " << e.what() << "; nothing was written\n";
        return exit_io_error;
    }
}
