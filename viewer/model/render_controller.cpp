#include "model/render_controller.hpp"

#include <atomic>
#include <exception>
#include <thread>
#include <utility>

namespace jt::view {

struct RenderController::Run {
    RenderOptions options;
    std::thread thread;
    std::atomic<bool> stop{false};
    std::atomic<bool> done{false};
    std::atomic<int> passes{0};
    bool adopted = false;  // renders the preparation adopted when it started (set before launch)
    mutable std::mutex mutex;                       // guards job and error
    std::shared_ptr<RenderJob> job;                 // set once the scene is prepared
    std::shared_ptr<const PreparedScene> prepared;  // the scene of `job`
    std::string error;
    RunTimeline timeline;

    std::shared_ptr<RenderJob> current_job() const {
        std::lock_guard lock(mutex);
        return job;
    }
    void cancel() {
        stop = true;
        if (auto j = current_job()) j->cancel();
    }
    void fail(std::string message) {
        std::lock_guard lock(mutex);
        error = std::move(message);
    }
    void join() {
        if (thread.joinable()) thread.join();
    }
};

RenderController::~RenderController() {
    stop();
    for (const auto& run : retired_) run->cancel();
    join_retired(true);
}

void RenderController::join_retired(bool all) {
    std::erase_if(retired_, [all](const std::shared_ptr<Run>& run) {
        if (!all && !run->done) return false;
        run->join();
        return true;
    });
}

std::shared_ptr<RenderJob> RenderController::current_job() const {
    std::lock_guard lock(mutex_);
    return current_ ? current_->current_job() : nullptr;
}

void RenderController::stop() {
    std::shared_ptr<Run> run;
    {
        std::lock_guard lock(mutex_);
        run = current_;
    }
    if (!run) return;
    run->cancel();
    run->join();
}

void RenderController::forget_prepared() {
    std::lock_guard lock(mutex_);
    prepared_.reset();
    prepared_from_.reset();
    ahead_.reset();
}

void RenderController::adopt_prepared(PreparedAhead ahead) {
    std::lock_guard lock(mutex_);
    ahead_ = std::move(ahead);
    ahead_as_is_ = true;
}

void RenderController::files_changed() {
    std::lock_guard lock(mutex_);
    ahead_as_is_ = false;
}

std::shared_ptr<const Scene> RenderController::finish_adopted() {
    std::optional<PreparedAhead> ahead;
    {
        std::lock_guard lock(mutex_);
        ahead = ahead_;
    }
    if (!ahead) return nullptr;
    ahead->prepared.wait();
    std::lock_guard lock(mutex_);
    // Another run may have taken it meanwhile, or forget_prepared dropped it.
    if (!ahead_ || ahead_->scene != ahead->scene) return nullptr;
    ahead_.reset();
    const auto& prepared = ahead->prepared.get();
    if (!prepared) return nullptr;
    prepared_ = *prepared;
    prepared_from_ = ahead->scene;
    return ahead_as_is_ ? ahead->scene : nullptr;
}

bool RenderController::renders_adopted() const {
    std::lock_guard lock(mutex_);
    return current_ && current_->adopted;
}

void RenderController::pause() {
    std::lock_guard lock(mutex_);
    if (current_) current_->cancel();
}

// Runs `run` on a new thread: prepares `scene` first when given, else
// continues the run's job, once the thread of `paused` (the run it continues,
// which may still be winding down) has ended.
void RenderController::launch(const std::shared_ptr<Run>& run, std::shared_ptr<const Scene> scene,
                              std::shared_ptr<Run> paused) {
    std::shared_ptr<const Scene> to_prepare = std::move(scene);
    run->thread =
        std::thread([this, run, to_prepare = std::move(to_prepare), paused = std::move(paused)] {
            try {
                std::shared_ptr<RenderJob> job = run->current_job();
                if (paused) {
                    paused->join();  // its last pass has returned: the job is ours alone
                    if (!run->stop) job->resume();
                }
                if (to_prepare) {
                    const std::shared_ptr<const Scene> adopted = finish_adopted();
                    std::shared_ptr<const PreparedScene> previous;
                    std::shared_ptr<const Scene> previous_scene;
                    {
                        std::lock_guard lock(mutex_);
                        previous = prepared_;
                        previous_scene = prepared_from_;
                    }
                    // A material edit patches the previous scene in place of
                    // preparing every object again; the very scene prepared
                    // ahead, just now, needs nothing more. (Later runs of it
                    // go through prepare_scene_edit, which notices a changed
                    // image map or model file.)
                    Expected<std::shared_ptr<const PreparedScene>> prepared =
                        adopted && adopted == to_prepare && previous ? Expected(previous)
                        : previous_scene ? prepare_scene_edit(*previous_scene, to_prepare, previous)
                                         : prepare_scene(to_prepare, previous);
                    if (!prepared) {
                        run->fail("the render failed: " + prepared.error().message);
                        run->done = true;
                        if (wakeup_) wakeup_->notify();
                        return;
                    }
                    job = std::make_shared<RenderJob>(*prepared, run->options);
                    {
                        std::lock_guard lock(mutex_);
                        if (current_ == run) {  // a newer run's stays
                            prepared_ = *prepared;
                            prepared_from_ = to_prepare;
                        }
                    }
                    std::lock_guard lock(run->mutex);
                    run->job = job;
                    run->prepared = *prepared;
                    run->timeline.prepared = RunTimeline::Clock::now();
                }
                while (!run->stop && job->run_pass()) {
                    if (++run->passes == 1 && to_prepare) {
                        std::lock_guard lock(run->mutex);
                        run->timeline.first_pass = RunTimeline::Clock::now();
                    }
                    if (wakeup_) wakeup_->notify();
                }
            } catch (const std::exception& e) {
                run->fail(std::string("the render failed: ") + e.what());
            } catch (...) {
                run->fail("the render failed");
            }
            run->done = true;
            if (wakeup_) wakeup_->notify();
        });
}

void RenderController::start(Scene scene, const RenderOptions& options) {
    start(std::make_shared<const Scene>(std::move(scene)), options);
}

void RenderController::start(std::shared_ptr<const Scene> scene, const RenderOptions& options) {
    join_retired(false);
    auto run = std::make_shared<Run>();
    run->options = options;
    run->timeline.started = RunTimeline::Clock::now();
    std::shared_ptr<Run> old;
    {
        std::lock_guard lock(mutex_);
        run->adopted = ahead_ && ahead_as_is_ && ahead_->scene == scene;
        old = std::exchange(current_, run);
    }
    if (old) {
        old->cancel();  // not joined: it stops on its own while the new job starts
        retired_.push_back(std::move(old));
    }
    ++jobs_started_;
    launch(run, std::move(scene));
}

bool RenderController::resume() {
    std::shared_ptr<Run> paused;
    {
        std::lock_guard lock(mutex_);
        paused = current_;
    }
    if (!paused) return false;
    std::shared_ptr<RenderJob> job = paused->current_job();
    if (!job) return false;
    // A new run continues the job: the paused one's thread may not have
    // returned yet, and the UI thread does not wait for it.
    auto run = std::make_shared<Run>();
    run->options = paused->options;
    run->job = job;
    {
        std::lock_guard lock(paused->mutex);
        run->timeline = paused->timeline;
        run->prepared = paused->prepared;
    }
    {
        std::lock_guard lock(mutex_);
        current_ = run;
    }
    launch(run, nullptr, std::move(paused));
    return true;
}

std::optional<PixelRect> RenderController::fetch(Image8& display) {
    std::shared_ptr<RenderJob> job = current_job();
    if (!job) return std::nullopt;
    return job->fetch_updates(display);
}

RenderProgress RenderController::progress() const {
    std::shared_ptr<RenderJob> job = current_job();
    return job ? job->progress() : RenderProgress{};
}

bool RenderController::active() const {
    std::lock_guard lock(mutex_);
    return current_ && !current_->done && !current_->stop;
}

bool RenderController::settled() const {
    std::lock_guard lock(mutex_);
    return !current_ || current_->done;
}

bool RenderController::finished() const {
    std::shared_ptr<Run> run;
    {
        std::lock_guard lock(mutex_);
        run = current_;
    }
    if (!run || !run->done) return false;
    std::shared_ptr<RenderJob> job = run->current_job();
    return job && job->progress().finished;
}

std::string RenderController::error() const {
    std::lock_guard lock(mutex_);
    if (!current_) return {};
    std::lock_guard run_lock(current_->mutex);
    return current_->error;
}

int RenderController::passes_since_start() const {
    std::lock_guard lock(mutex_);
    return current_ ? current_->passes.load() : 0;
}

std::shared_ptr<const PreparedScene> RenderController::prepared() const {
    std::lock_guard lock(mutex_);
    return prepared_;
}

std::shared_ptr<const PreparedScene> RenderController::current_prepared() const {
    std::lock_guard lock(mutex_);
    if (!current_) return nullptr;
    std::lock_guard run_lock(current_->mutex);
    return current_->prepared;
}

RunTimeline RenderController::timeline() const {
    std::lock_guard lock(mutex_);
    if (!current_) return {};
    std::lock_guard run_lock(current_->mutex);
    return current_->timeline;
}

}  // namespace jt::view
