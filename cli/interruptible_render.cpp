#include "interruptible_render.hpp"

#include "jtracer/frontend/command_line.hpp"

#include <chrono>
#include <condition_variable>
#include <csignal>
#include <iostream>
#include <mutex>
#include <thread>

namespace jt::cli {

// Left to its default, a signal would end the process in the middle of a
// write, leaving the temporary file behind.
void catch_interrupts() {
    frontend::catch_stop_signals();
}

int interrupting_signal() {
    return frontend::stop_signal();
}

// The end of the render wakes this thread at once, so that a small render
// does not wait out a tick.
bool render_interruptibly(RenderJob& job, frontend::ProgressDisplay& display,
                          const ProgressView& view) {
    std::mutex mutex;
    std::condition_variable finished;
    bool done = false;
    std::thread worker([&] {
        job.run();
        {
            std::lock_guard<std::mutex> lock(mutex);
            done = true;
        }
        finished.notify_one();
    });
    std::unique_lock<std::mutex> lock(mutex);
    while (!done) {
        lock.unlock();
        if (interrupting_signal() != 0) job.cancel();
        display.update(view ? view(job.progress()) : job.progress());
        lock.lock();
        finished.wait_for(lock, std::chrono::milliseconds(100), [&] { return done; });
    }
    lock.unlock();
    worker.join();
    return job.progress().finished && interrupting_signal() == 0;
}

int report_interrupt(const char* what) {
    const int signal = interrupting_signal() != 0 ? interrupting_signal() : SIGINT;
    std::cerr << "jtracer-cli: interrupted by " << frontend::signal_name(signal) << "; " << what
              << "\n";
    return 128 + signal;
}

}  // namespace jt::cli
