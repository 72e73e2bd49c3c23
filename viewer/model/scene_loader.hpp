#pragma once
// Reads and parses scene files on a thread of its own, so that a huge, slow
// or garbage file never stalls a frame: the UI asks for a load and picks the
// result up on a later frame. The newest request wins: a load that is
// overtaken by another request finishes, but its result is dropped.

#include "model/latest_wins_worker.hpp"
#include "model/prepared_ahead.hpp"
#include "model/scene_document.hpp"
#include "model/wakeup.hpp"

#include <chrono>
#include <filesystem>
#include <optional>

namespace jt::view {

enum class LoadPurpose { open, reload };

// An open's result is handed over once its preparation made ahead is done, up
// to this long after the scene was copied: the frame that takes it in then
// starts a render whose first pass comes within that frame's wait (a few ms),
// and no frame is drawn beside the preparation meanwhile (with software
// OpenGL a frame takes a core for 10-30 ms). The frame loop sleeps while the
// load is in flight, and input still wakes it. A longer preparation (a million
// objects) is handed over unfinished: the panels show, the preview follows.
inline constexpr std::chrono::milliseconds prepared_ahead_hold{150};
// How often that hold looks for a newer request, which ends it.
inline constexpr std::chrono::milliseconds prepared_ahead_hold_slice{5};

struct FinishedLoad {
    std::filesystem::path path;
    LoadPurpose purpose = LoadPurpose::open;
    LoadAttempt attempt;
    // An open without errors: its scene's preparation, under way (see
    // prepared_ahead.hpp) of attempt.scene, the same object.
    std::optional<PreparedAhead> ahead;
};

class SceneLoader {
  public:
    // `hold`: how long an open waits for its preparation (a test's may be long,
    // so that a loaded machine does not decide what it checks).
    explicit SceneLoader(std::chrono::milliseconds hold = prepared_ahead_hold);

    // Parsed with `options` (the document's --define and clock).
    void request(const std::filesystem::path& path, LoadPurpose purpose,
                 const ParseOptions& options = {});
    // The result of the newest request once it is done, handed out once.
    std::optional<FinishedLoad> take();
    // A request is waiting, loading, or done but not yet taken.
    bool busy() const { return worker_.busy(); }
    // The newest request is an open whose result is not taken yet.
    bool opening() const { return newest_is_open_ && worker_.busy(); }
    // A request is waiting or loading (its result is not ready yet).
    bool in_flight() const { return worker_.in_flight(); }
    // Notified whenever a result is ready to take. Set before the first request.
    void set_wakeup(Wakeup* wakeup) { worker_.set_wakeup(wakeup); }
    // Blocks until the newest request is done (for start-up and tests).
    void wait() const { worker_.wait(); }

  private:
    struct Request {
        std::filesystem::path path;
        LoadPurpose purpose;
        ParseOptions options;
        LoadTimes::Clock::time_point requested;
    };
    FinishedLoad load(Request request);
    // Waits for `ahead` up to hold_, unless a newer request comes.
    void hold_until_prepared(const PreparedAhead& ahead) const;

    std::chrono::milliseconds hold_;
    bool newest_is_open_ = false;  // UI thread only, as request()
    AheadPreparer preparer_;       // before worker_: used by its thread, joined after it
    LatestWinsWorker<Request, FinishedLoad> worker_;
};

}  // namespace jt::view
