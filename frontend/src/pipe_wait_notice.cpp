#include "jtracer/frontend/pipe_wait_notice.hpp"

#include <cstdio>

namespace jt::frontend {

PipeWaitNotice::PipeWaitNotice(std::string_view program, const std::filesystem::path& path) {
    std::error_code error;
    if (!std::filesystem::is_fifo(std::filesystem::status(path, error))) return;
    const std::string notice = std::string(program) + ": waiting for the scene from the pipe '" +
                               path.string() +
                               "': it is read once something writes it and closes it\n";
    watcher_ = std::thread([this, notice] {
        std::unique_lock lock(mutex_);
        if (!done_changed_.wait_for(lock, kPipeWaitNoticeDelay, [this] { return done_; })) {
            std::fputs(notice.c_str(), stderr);
            std::fflush(stderr);
        }
    });
}

PipeWaitNotice::~PipeWaitNotice() {
    if (!watcher_.joinable()) return;
    {
        std::lock_guard lock(mutex_);
        done_ = true;
    }
    done_changed_.notify_all();
    watcher_.join();
}

}  // namespace jt::frontend
