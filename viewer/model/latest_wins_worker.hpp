#pragma once
// One background thread that runs the newest of the requests given to it, so
// that the frame loop never waits for slow work (reading a file, parsing the
// text being typed). A request that is overtaken before it starts is dropped;
// one overtaken while it runs finishes, but its result is dropped. A request
// may be given a time before which it does not start: a newer request then
// moves that time (the text editor waits for typing to pause).

#include "model/wakeup.hpp"

#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

namespace jt::view {

template <class Request, class Result>
class LatestWinsWorker {
  public:
    using Clock = std::chrono::steady_clock;
    // `run` is called on the worker thread and must not throw.
    explicit LatestWinsWorker(std::function<Result(Request)> run)
        : run_(std::move(run)), worker_([this] { work(); }) {}

    ~LatestWinsWorker() {
        {
            std::lock_guard lock(mutex_);
            quit_ = true;
        }
        changed_.notify_all();
        worker_.join();  // a request in progress runs to its end: the parser cannot be interrupted
    }
    LatestWinsWorker(const LatestWinsWorker&) = delete;
    LatestWinsWorker& operator=(const LatestWinsWorker&) = delete;

    // Replaces any waiting request and drops any result not yet taken.
    void submit(Request request, Clock::time_point not_before = {}) {
        {
            std::lock_guard lock(mutex_);
            next_ = Waiting{std::move(request), not_before};
            result_.reset();
        }
        changed_.notify_all();
    }
    // Drops the waiting request and any result not yet taken.
    void cancel() {
        std::lock_guard lock(mutex_);
        next_.reset();
        result_.reset();
    }
    // The newest request's result once it is done, handed out once.
    std::optional<Result> take() {
        std::lock_guard lock(mutex_);
        return std::exchange(result_, std::nullopt);
    }
    // A request is waiting or running (its result is not ready yet).
    bool in_flight() const {
        std::lock_guard lock(mutex_);
        return next_ || running_;
    }
    // A newer request waits: the result of the one running now will be
    // dropped (for `run`, to skip work only that result needs).
    bool superseded() const {
        std::lock_guard lock(mutex_);
        return next_.has_value();
    }
    // A request is waiting, running, or done but not yet taken.
    bool busy() const {
        std::lock_guard lock(mutex_);
        return next_ || running_ || result_;
    }
    // Notified whenever a result is ready to take. Set before the first request.
    void set_wakeup(Wakeup* wakeup) {
        std::lock_guard lock(mutex_);
        wakeup_ = wakeup;
    }
    // Blocks until the newest request is done (start-up and tests).
    void wait() const {
        std::unique_lock lock(mutex_);
        changed_.wait(lock, [this] { return !next_ && !running_; });
    }

  private:
    struct Waiting {
        Request request;
        Clock::time_point not_before;
    };

    void work() {
        std::unique_lock lock(mutex_);
        for (;;) {
            changed_.wait(lock, [this] { return quit_ || next_; });
            if (quit_) return;
            if (Clock::now() < next_->not_before) {
                changed_.wait_until(lock, next_->not_before);
                continue;  // the request may have been replaced or cancelled meanwhile
            }
            Request request = std::move(next_->request);
            next_.reset();
            running_ = true;
            lock.unlock();
            Result result = run_(std::move(request));
            lock.lock();
            running_ = false;
            const bool newest = !next_;
            if (newest) result_ = std::move(result);
            changed_.notify_all();
            if (newest && wakeup_) {
                Wakeup* wakeup = wakeup_;
                lock.unlock();
                wakeup->notify();
                lock.lock();
            }
        }
    }

    const std::function<Result(Request)> run_;
    mutable std::mutex mutex_;
    mutable std::condition_variable changed_;
    std::optional<Waiting> next_;
    bool running_ = false;
    std::optional<Result> result_;
    bool quit_ = false;
    Wakeup* wakeup_ = nullptr;
    std::thread worker_;  // last: starts once the members above exist
};

}  // namespace jt::view
