#include "model/wakeup.hpp"

#include <utility>

namespace jt::view {

void Wakeup::set_callback(std::function<void()> callback) {
    std::lock_guard lock(mutex_);
    callback_ = std::move(callback);
}

void Wakeup::notify() {
    std::function<void()> callback;
    {
        std::lock_guard lock(mutex_);
        ++count_;
        callback = callback_;
    }
    changed_.notify_all();
    if (callback) callback();
}

std::uint64_t Wakeup::count() const {
    std::lock_guard lock(mutex_);
    return count_;
}

bool Wakeup::wait(std::uint64_t seen, std::chrono::steady_clock::time_point deadline) const {
    std::unique_lock lock(mutex_);
    return changed_.wait_until(lock, deadline, [&] { return count_ != seen; });
}

}  // namespace jt::view
