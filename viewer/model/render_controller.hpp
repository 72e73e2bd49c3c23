#pragma once
// Runs the core's progressive RenderJob on a background thread so the UI never
// waits for it. Any change starts a new job at once: the old one is cancelled
// and winds down on its own thread (the core stops within milliseconds), so a
// frame never waits for it either. A paused job is kept, and resuming it
// renders only what it had not finished.

#include "jtracer/render_job.hpp"
#include "jtracer/scene.hpp"
#include "model/prepared_ahead.hpp"
#include "model/wakeup.hpp"

#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace jt::view {

// When the current run reached each step (for the latency benchmark).
struct RunTimeline {
    using Clock = std::chrono::steady_clock;
    Clock::time_point started;                    // start() was called
    std::optional<Clock::time_point> prepared;    // the scene was prepared, the job made
    std::optional<Clock::time_point> first_pass;  // the job's first pass was rendered
};

class RenderController {
  public:
    RenderController() = default;
    ~RenderController();
    RenderController(const RenderController&) = delete;
    RenderController& operator=(const RenderController&) = delete;

    // Cancels any job and renders `scene` through `options` (camera index, size,
    // samples). The acceleration structure of the previous scene is reused when
    // only materials, lights, cameras or settings changed, and an edit of
    // materials only patches the previous scene (prepare_scene_edit).
    void start(Scene scene, const RenderOptions& options);
    // The same for a scene shared with its owner, without a copy. The very
    // scene of an adopted preparation (adopt_prepared), started next, renders
    // with that preparation.
    void start(std::shared_ptr<const Scene> scene, const RenderOptions& options);
    // Takes a preparation started ahead (prepared_ahead.hpp) as the latest
    // prepared scene: the next run waits for it to finish and then reuses
    // it as it would reuse its own.
    void adopt_prepared(PreparedAhead ahead);
    // The next start() builds the scene from scratch: geometry and image maps
    // are read again rather than reused, even from files that look unchanged.
    void forget_prepared();
    // Image maps or model files may have changed: an adopted preparation not
    // yet used was made from the files as they were, so the next run only
    // reuses it through prepare_scene_edit, which reads them again.
    void files_changed();
    // Stops the current job and waits for its thread; the pixels fetched so far stay.
    void stop();
    // Stops the current job so that resume() can continue it. Does not wait
    // for its thread (see resume).
    void pause();
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
    // No thread of the current run still renders: it finished, failed, or was
    // paused and its passes under way have returned (pause() does not wait).
    bool settled() const;
    // Why the current job could not run, or empty.
    std::string error() const;
    std::uint64_t jobs_started() const { return jobs_started_; }
    // The current run renders the preparation adopted (adopt_prepared) when
    // it started: its first pass follows that preparation, not one of its own.
    bool renders_adopted() const;
    // Passes the current job has completed since it was started or last resumed.
    int passes_since_start() const;
    RunTimeline timeline() const;
    // The scene the latest run prepared (its geometry is what the next start()
    // reuses when only materials, lights, cameras or settings changed).
    std::shared_ptr<const PreparedScene> prepared() const;
    // The scene the current job renders, once prepared (null while it is
    // being prepared, or when it could not be): what the image shows.
    std::shared_ptr<const PreparedScene> current_prepared() const;
    // Notified (on the render thread) whenever a pass is done and when a run
    // ends. Set before the first start().
    void set_wakeup(Wakeup* wakeup) { wakeup_ = wakeup; }

  private:
    struct Run;  // one worker thread and the job it renders

    void launch(const std::shared_ptr<Run>& run, std::shared_ptr<const Scene> scene,
                std::shared_ptr<Run> paused = nullptr);
    std::shared_ptr<RenderJob> current_job() const;
    // On a run's thread: waits for an adopted preparation, if any, and makes
    // it the latest prepared scene; returns its scene when that may render
    // with it as it is (null: none adopted, or files changed since).
    std::shared_ptr<const Scene> finish_adopted();
    void join_retired(bool all);

    mutable std::mutex mutex_;
    std::shared_ptr<Run> current_;                   // guarded by mutex_
    std::shared_ptr<const PreparedScene> prepared_;  // guarded by mutex_
    std::shared_ptr<const Scene> prepared_from_;     // what prepared_ was prepared from; mutex_
    std::optional<PreparedAhead> ahead_;             // adopted, not yet waited for; mutex_
    bool ahead_as_is_ = false;  // ahead_ renders its scene with no look at its files; mutex_
    std::vector<std::shared_ptr<Run>> retired_;  // cancelled, winding down (UI thread only)
    std::uint64_t jobs_started_ = 0;
    Wakeup* wakeup_ = nullptr;
};

}  // namespace jt::view
