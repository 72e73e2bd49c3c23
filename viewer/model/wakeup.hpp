#pragma once
// Lets the worker threads (the loader, the render) tell the frame loop that
// they have something new for it, so that the loop can sleep until then
// instead of drawing frames that show nothing new and take cores from the
// render. A window wakes its event loop (glfwPostEmptyEvent) through the
// callback; the headless loop of the benchmark waits on the count.

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>

namespace jt::view {

class Wakeup {
  public:
    // Called by every notify(), on the notifying thread.
    void set_callback(std::function<void()> callback);
    // Thread-safe.
    void notify();
    // How many times notify() was called.
    std::uint64_t count() const;
    // Returns once count() differs from `seen` (true) or at `deadline` (false).
    // Taking `seen` before deciding to wait means no notify is ever missed.
    bool wait(std::uint64_t seen, std::chrono::steady_clock::time_point deadline) const;

  private:
    mutable std::mutex mutex_;
    mutable std::condition_variable changed_;
    std::uint64_t count_ = 0;
    std::function<void()> callback_;
};

}  // namespace jt::view
