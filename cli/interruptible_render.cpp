#include "interruptible_render.hpp"

#include "jtracer/frontend/command_line.hpp"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <csignal>
#include <iostream>
#include <mutex>
#include <thread>

namespace jt::cli {

namespace {

std::atomic<int> interrupted{0};

// A second signal ends the process at once (an impatient Ctrl-C during a long
// write), without leaving the write's temporary file behind.
extern "C" void on_interrupt(int signal) {
    if (interrupted.exchange(signal) != 0) frontend::end_by_signal(signal);
}

}  // namespace

// Left to its default, a signal would end the process in the middle of a
// write, leaving the temporary file behind.
void catch_interrupts() {
    frontend::handle_stop_signals(on_interrupt);
}

int interrupting_signal() {
    return interrupted.load();
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
        if (interrupted.load() != 0) job.cancel();
        display.update(view ? view(job.progress()) : job.progress());
        lock.lock();
        finished.wait_for(lock, std::chrono::milliseconds(100), [&] { return done; });
    }
    lock.unlock();
    worker.join();
    return job.progress().finished && interrupted.load() == 0;
}

int report_interrupt(const char* what) {
    const int signal = interrupted.load() != 0 ? interrupted.load() : SIGINT;
    const char* name = signal == SIGTERM ? "SIGTERM" : signal == SIGHUP ? "SIGHUP" : "SIGINT";
    std::cerr << "jtracer-cli: interrupted by " << name << "; " << what << "\n";
    return 128 + signal;
}

}  // namespace jt::cli
