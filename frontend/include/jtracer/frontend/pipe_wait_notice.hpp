#pragma once
// A scene named by a pipe (mkfifo, bash's <(...)) is read once its writer
// sends it: opening a named pipe waits, for good, until something opens it
// for writing, and a farm job given a pipe nobody writes to would look hung.
// While a PipeWaitNotice lives, a read that waits longer than
// kPipeWaitNoticeDelay says on stderr what it waits for.

#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>

namespace jt::frontend {

// Long enough that a generator feeding <(...) at once goes unremarked.
inline constexpr std::chrono::milliseconds kPipeWaitNoticeDelay{1000};

class PipeWaitNotice {
  public:
    // Does nothing unless `path` is a pipe.
    PipeWaitNotice(std::string_view program, const std::filesystem::path& path);
    ~PipeWaitNotice();
    PipeWaitNotice(const PipeWaitNotice&) = delete;
    PipeWaitNotice& operator=(const PipeWaitNotice&) = delete;

  private:
    std::mutex mutex_;
    std::condition_variable done_changed_;
    bool done_ = false;
    std::thread watcher_;
};

}  // namespace jt::frontend
