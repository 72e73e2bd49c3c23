#include "render_controller.hpp"

#include <exception>

namespace jt::view {

RenderController::~RenderController() {
    stop();
}

void RenderController::join() {
    if (worker_.joinable()) worker_.join();
}

void RenderController::stop() {
    stop_requested_ = true;
    std::shared_ptr<RenderJob> job;
    {
        std::lock_guard lock(mutex_);
        job = job_;
    }
    if (job) job->cancel();
    join();
}

void RenderController::run_passes(RenderJob& job) {
    while (!stop_requested_ && job.run_pass()) ++passes_run_;
}

void RenderController::start(const Scene& scene, const RenderOptions& options) {
    stop();
    std::shared_ptr<const PreparedScene> previous;
    {
        std::lock_guard lock(mutex_);
        job_.reset();
        error_.clear();
        previous = prepared_;
    }
    stop_requested_ = false;
    worker_done_ = false;
    passes_run_ = 0;
    ++jobs_started_;
    worker_ = std::thread([this, scene, options, previous] {
        try {
            auto prepared = prepare_scene(scene, previous);
            auto job = std::make_shared<RenderJob>(prepared, options);
            {
                std::lock_guard lock(mutex_);
                prepared_ = prepared;
                job_ = job;
            }
            if (!stop_requested_) run_passes(*job);
        } catch (const std::exception& e) {
            std::lock_guard lock(mutex_);
            error_ = std::string("the render failed: ") + e.what();
        } catch (...) {
            std::lock_guard lock(mutex_);
            error_ = "the render failed";
        }
        worker_done_ = true;
    });
}

bool RenderController::resume() {
    stop();
    std::shared_ptr<RenderJob> job;
    {
        std::lock_guard lock(mutex_);
        job = job_;
    }
    if (!job) return false;
    job->resume();
    stop_requested_ = false;
    worker_done_ = false;
    passes_run_ = 0;
    worker_ = std::thread([this, job] {
        try {
            run_passes(*job);
        } catch (const std::exception& e) {
            std::lock_guard lock(mutex_);
            error_ = std::string("the render failed: ") + e.what();
        }
        worker_done_ = true;
    });
    return true;
}

std::optional<PixelRect> RenderController::fetch(Image8& display) {
    std::shared_ptr<RenderJob> job;
    {
        std::lock_guard lock(mutex_);
        job = job_;
    }
    if (!job) return std::nullopt;
    return job->fetch_updates(display);
}

RenderProgress RenderController::progress() const {
    std::lock_guard lock(mutex_);
    return job_ ? job_->progress() : RenderProgress{};
}

bool RenderController::active() const {
    return !worker_done_ && !stop_requested_;
}

bool RenderController::finished() const {
    std::lock_guard lock(mutex_);
    return job_ && worker_done_ && job_->progress().finished;
}

std::string RenderController::error() const {
    std::lock_guard lock(mutex_);
    return error_;
}

}  // namespace jt::view
