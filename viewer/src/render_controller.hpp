#pragma once
// Runs the core's progressive RenderJob on a background thread so the UI never
// waits for it. Any change starts a new job: the old one is cancelled (the core
// stops within milliseconds) and joined first, so at most one job runs. A
// paused job is kept, and resuming it renders only what it had not finished.

#include "jtracer/render_job.hpp"
#include "jtracer/scene.hpp"

#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace jt::view {

class RenderController {
  public:
    RenderController() = default;
    ~RenderController();
    RenderController(const RenderController&) = delete;
    RenderController& operator=(const RenderController&) = delete;

    // Cancels any job and renders `scene` through `options` (camera index, size,
    // samples). The acceleration structure of the previous scene is reused when
    // only materials, lights, cameras or settings changed.
    void start(const Scene& scene, const RenderOptions& options);
    // Stops the running job; the pixels fetched so far stay.
    void stop();
    // Stops the running job so that resume() can continue it.
    void pause() { stop(); }
    // Continues the stopped job from where it stopped: finished passes and
    // accumulated samples are kept. False when there is no job to continue
    // (none was started, or its scene could not be prepared).
    bool resume();

    // Copies pixels that changed into `display`; returns the changed rectangle.
    std::optional<PixelRect> fetch(Image8& display);
    // Progress of the current job (all zero while its scene is being prepared).
    RenderProgress progress() const;
    bool active() const;    // a job was started and has not finished or been stopped
    bool finished() const;  // the current job rendered every pass
    // Why the last job could not run, or empty.
    std::string error() const;
    std::uint64_t jobs_started() const { return jobs_started_; }
    // Passes the current job has completed on this controller's thread since
    // it was started or last resumed.
    int passes_since_start() const { return passes_run_; }

  private:
    void join();
    void run_passes(RenderJob& job);

    std::thread worker_;
    mutable std::mutex mutex_;
    std::shared_ptr<RenderJob> job_;                 // guarded by mutex_
    std::shared_ptr<const PreparedScene> prepared_;  // guarded by mutex_
    std::string error_;                              // guarded by mutex_
    std::atomic<bool> stop_requested_{false};
    std::atomic<bool> worker_done_{true};
    std::atomic<int> passes_run_{0};
    std::uint64_t jobs_started_ = 0;
};

}  // namespace jt::view
