#pragma once
// Runs the core's progressive RenderJob on a background thread so the UI never
// waits for it. Any change starts a new job: the old one is cancelled (the core
// stops within milliseconds) and joined first, so at most one job runs.

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

    // Copies pixels that changed into `display`; returns the changed rectangle.
    std::optional<PixelRect> fetch(Image8& display);
    // Progress of the current job (all zero while its scene is being prepared).
    RenderProgress progress() const;
    bool active() const;    // a job was started and has not finished or been stopped
    bool finished() const;  // the current job rendered every pass
    // Why the last job could not run, or empty.
    std::string error() const;
    std::uint64_t jobs_started() const { return jobs_started_; }

  private:
    void join();

    std::thread worker_;
    mutable std::mutex mutex_;
    std::shared_ptr<RenderJob> job_;                 // guarded by mutex_
    std::shared_ptr<const PreparedScene> prepared_;  // guarded by mutex_
    std::string error_;                              // guarded by mutex_
    std::atomic<bool> stop_requested_{false};
    std::atomic<bool> worker_done_{true};
    std::uint64_t jobs_started_ = 0;
};

}  // namespace jt::view
