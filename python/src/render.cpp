// Scene.render: the scene set up for its frame as jtracer-cli sets up a file
// (frontend's set_up_frame), prepared, and rendered by a RenderJob on a thread
// of its own while the calling thread, without the GIL, wakes every tick to
// report progress and to let Python see Ctrl+C (PyErr_CheckSignals runs the
// interpreter's SIGINT handler, which raises KeyboardInterrupt): then the job
// is cancelled, which stops it within a tile.

#include "bindings.hpp"

#include "jtracer/frontend/frame_setup.hpp"
#include "jtracer/frontend/memory_budget.hpp"
#include "jtracer/limits.hpp"

#include <chrono>
#include <condition_variable>
#include <thread>

namespace jt::python {

namespace {

// How often the calling thread looks at signals and reports progress: a
// Ctrl+C is answered within this (plus a tile), and a callback that redraws
// a bar is not called more often than it can show.
constexpr std::chrono::milliseconds kTick{50};

// The job on its own thread; the destructor cancels and joins it, so that no
// way out of render_scene (an exception from a callback, Ctrl+C) leaves it running.
class JobThread {
  public:
    explicit JobThread(RenderJob& job)
        : job_(job), thread_([this] {
              job_.run();
              {
                  std::lock_guard<std::mutex> lock(mutex_);
                  done_ = true;
              }
              finished_.notify_all();
          }) {}
    ~JobThread() {
        job_.cancel();
        thread_.join();
    }
    JobThread(const JobThread&) = delete;
    JobThread& operator=(const JobThread&) = delete;

    // Waits up to `timeout` for the job to end; true once it has.
    bool wait_for(std::chrono::milliseconds timeout) {
        std::unique_lock<std::mutex> lock(mutex_);
        return finished_.wait_for(lock, timeout, [this] { return done_; });
    }

  private:
    RenderJob& job_;
    std::mutex mutex_;
    std::condition_variable finished_;
    bool done_ = false;
    std::thread thread_;  // last: it starts once the rest is built
};

// The command line's ranges for the same flags (render_flags.cpp).
constexpr int kMaxThreads = 4096;

frontend::RenderFlags flags_for(const RenderArguments& a) {
    frontend::RenderFlags flags;
    flags.width = a.width;
    flags.height = a.height;
    flags.samples = a.samples;
    flags.camera = a.camera;
    flags.threads = a.threads;
    flags.names = python_names;
    return flags;
}

std::optional<FrameRegion> region_for(const RenderArguments& a) {
    if (!a.region) return std::nullopt;
    const auto& [x0, y0, x1, y1] = *a.region;
    Expected<FrameRegion> region =
        parse_frame_region(std::to_string(x0) + "," + std::to_string(y0) + "," +
                           std::to_string(x1) + "," + std::to_string(y1));
    if (!region) throw py::value_error("region: " + region.error().message);
    return *region;
}

// The message of set_up_frame's failure without its "jtracer: " and newline:
// "camera: ...", as flags.names named the argument.
std::string reason(const frontend::FrameSetup& setup, std::string_view program) {
    std::string text = setup.message;
    if (text.starts_with(program)) text.erase(0, program.size() + 2);
    if (!text.empty() && text.back() == '\n') text.pop_back();
    return text;
}

}  // namespace

RenderArguments render_arguments(const py::handle& width, const py::handle& height,
                                 const py::handle& samples, const py::handle& camera,
                                 const py::handle& threads, const py::handle& region,
                                 py::object progress) {
    return {.width = optional_int_argument(width, "width", 1, kMaxImageSide),
            .height = optional_int_argument(height, "height", 1, kMaxImageSide),
            .samples = optional_int_argument(samples, "samples", kMinSamples, kMaxSamples),
            .camera = optional_text_argument(camera, "camera"),
            .threads = int_argument(threads, "threads", 0, kMaxThreads),
            .region = region_argument(region),
            .progress = std::move(progress)};
}

py::array_t<std::uint8_t> render_scene(PythonScene& scene, const RenderArguments& arguments) {
    constexpr std::string_view program = "jtracer";
    const frontend::RenderFlags flags = flags_for(arguments);
    const std::optional<FrameRegion> region = region_for(arguments);
    if (!arguments.progress.is_none() && !PyCallable_Check(arguments.progress.ptr()))
        throw py::type_error("progress: a callable taking the fraction done, or None");

    frontend::FrameSetup setup;
    {
        py::gil_scoped_release unlocked;
        // A Scene is read-only: its primitives are as load() or parse() made them.
        setup = frontend::set_up_frame(program, flags, scene.loaded,
                                       frontend::LoadedPrimitives::as_parsed, region);
    }
    if (setup.exit_code == frontend::exit_scene_error) {
        raise_scene_error(format_diagnostics(setup.diagnostics, scene.loaded), setup.diagnostics,
                          scene.loaded);
    }
    if (setup.exit_code != frontend::exit_ok) throw py::value_error(reason(setup, program));
    // Before allocating: a frame larger than the memory left would otherwise
    // end in a bare "std::bad_alloc", or the kernel's out-of-memory killer
    // taking the interpreter with it.
    if (Expected<void> fits = frontend::check_render_memory(setup.render, false, python_names);
        !fits) {
        PyErr_SetString(PyExc_MemoryError, fits.error().message.c_str());
        throw py::error_already_set();
    }

    std::shared_ptr<const PreparedScene> prepared;
    {
        py::gil_scoped_release unlocked;
        std::lock_guard<std::mutex> lock(scene.prepared_mutex);
        Expected<std::shared_ptr<const PreparedScene>> made =
            prepare_scene(setup.scene, scene.prepared);
        if (!made) throw std::runtime_error(made.error().message);
        prepared = scene.prepared = *made;
    }

    RenderJob job(prepared, setup.render);
    double reported = -1.0;
    auto report = [&](double fraction) {
        if (arguments.progress.is_none() || fraction == reported) return;
        reported = fraction;
        arguments.progress(fraction);
    };
    {
        JobThread running(job);
        bool finished = false;
        while (!finished) {
            {
                py::gil_scoped_release unlocked;
                finished = running.wait_for(kTick);
            }
            if (PyErr_CheckSignals() != 0) throw py::error_already_set();
            report(job.progress().fraction);
        }
    }
    if (!job.progress().finished) throw std::runtime_error("the render was cancelled");
    report(1.0);
    return to_array(job.take_image());
}

}  // namespace jt::python
