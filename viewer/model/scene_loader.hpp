#pragma once
// Reads and parses scene files on a thread of its own, so that a huge, slow
// or garbage file never stalls a frame: the UI asks for a load and picks the
// result up on a later frame. The newest request wins: a load that is
// overtaken by another request finishes, but its result is dropped.

#include "scene_document.hpp"
#include "wakeup.hpp"

#include <condition_variable>
#include <filesystem>
#include <mutex>
#include <optional>
#include <thread>

namespace jt::view {

enum class LoadPurpose { open, reload };

struct FinishedLoad {
    std::filesystem::path path;
    LoadPurpose purpose = LoadPurpose::open;
    LoadAttempt attempt;
};

class SceneLoader {
  public:
    SceneLoader();
    ~SceneLoader();
    SceneLoader(const SceneLoader&) = delete;
    SceneLoader& operator=(const SceneLoader&) = delete;

    void request(const std::filesystem::path& path, LoadPurpose purpose);
    // The result of the newest request once it is done, handed out once.
    std::optional<FinishedLoad> take();
    // A request is waiting, loading, or done but not yet taken.
    bool busy() const;
    // A request is waiting or loading (its result is not ready yet).
    bool in_flight() const;
    // Notified whenever a result is ready to take. Set before the first request.
    void set_wakeup(Wakeup* wakeup);
    // Blocks until the newest request is done (for start-up and tests).
    void wait() const;

  private:
    struct Request {
        std::filesystem::path path;
        LoadPurpose purpose;
        LoadTimes::Clock::time_point requested;
    };
    void work();

    mutable std::mutex mutex_;
    mutable std::condition_variable changed_;
    std::optional<Request> next_;         // waiting to start
    bool loading_ = false;                // the worker is reading or parsing
    std::optional<FinishedLoad> result_;  // done, not yet taken
    bool quit_ = false;
    Wakeup* wakeup_ = nullptr;
    std::thread worker_;  // last: starts once the members above exist
};

}  // namespace jt::view
