#include "interruptible_render.hpp"

#include "jtracer/atomic_file.hpp"

#include <signal.h>

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
    if (interrupted.exchange(signal) != 0) {
        jt::remove_unfinished_file();
        std::signal(signal, SIG_DFL);
        std::raise(signal);
    }
}

}  // namespace

// SIGHUP is how a closed terminal or a dropped ssh connection (a farm's
// `ssh host jtracer-cli ...`) ends a process: left to its default it would end
// this one in the middle of a write, leaving the temporary file behind. A
// signal ignored on entry (nohup, a shell's background job) stays ignored:
// whoever started the process asked for that.
void catch_interrupts() {
    for (const int signal : {SIGINT, SIGTERM, SIGHUP}) {
        struct sigaction current {};
        if (::sigaction(signal, nullptr, &current) == 0 && current.sa_handler == SIG_IGN) continue;
        std::signal(signal, on_interrupt);
    }
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
