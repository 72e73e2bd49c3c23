#include "scene_loader.hpp"

#include <exception>

namespace jt::view {

SceneLoader::SceneLoader() : worker_([this] { work(); }) {}

SceneLoader::~SceneLoader() {
    {
        std::lock_guard lock(mutex_);
        quit_ = true;
    }
    changed_.notify_all();
    worker_.join();  // a load in progress runs to its end: the parser cannot be interrupted
}

void SceneLoader::request(const std::filesystem::path& path, LoadPurpose purpose) {
    {
        std::lock_guard lock(mutex_);
        next_ = Request{path, purpose, LoadTimes::Clock::now()};
        result_.reset();  // overtaken
    }
    changed_.notify_all();
}

std::optional<FinishedLoad> SceneLoader::take() {
    std::lock_guard lock(mutex_);
    std::optional<FinishedLoad> result = std::move(result_);
    result_.reset();
    if (result) result->attempt.times.taken = LoadTimes::Clock::now();
    return result;
}

bool SceneLoader::in_flight() const {
    std::lock_guard lock(mutex_);
    return next_ || loading_;
}

void SceneLoader::set_wakeup(Wakeup* wakeup) {
    std::lock_guard lock(mutex_);
    wakeup_ = wakeup;
}

bool SceneLoader::busy() const {
    std::lock_guard lock(mutex_);
    return next_ || loading_ || result_;
}

void SceneLoader::wait() const {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [this] { return !next_ && !loading_; });
}

void SceneLoader::work() {
    std::unique_lock lock(mutex_);
    for (;;) {
        changed_.wait(lock, [this] { return quit_ || next_; });
        if (quit_) return;
        const Request request = std::move(*next_);
        next_.reset();
        loading_ = true;
        lock.unlock();
        LoadAttempt attempt;
        try {
            attempt = attempt_load(request.path);
        } catch (const std::exception& e) {  // out of memory, say
            attempt = LoadAttempt{};
            attempt.diagnostics.push_back(Diagnostic{
                Severity::error, SourcePos{}, std::string("cannot load the file: ") + e.what()});
        }
        attempt.times.requested = request.requested;
        lock.lock();
        loading_ = false;
        const bool ready = !next_;
        if (ready) result_ = FinishedLoad{request.path, request.purpose, std::move(attempt)};
        changed_.notify_all();
        if (ready && wakeup_) {
            Wakeup* wakeup = wakeup_;
            lock.unlock();
            wakeup->notify();
            lock.lock();
        }
    }
}

}  // namespace jt::view
