#pragma once
// Parses and validates the text being typed in the text editor on a thread of
// its own, once the typing has paused, so that neither a keystroke nor a big
// scene ever waits for the parser. The newest text wins: a check overtaken by
// a newer text is dropped, and a newer text restarts the pause.

#include "jtracer/diagnostics.hpp"
#include "jtracer/parser.hpp"
#include "wakeup.hpp"

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace jt::view {

struct CheckedText {
    std::uint64_t id = 0;  // as given to TextChecker::check
    std::string text;
    ParseResult parsed;                   // the scene's asset_folder set to the file's folder
    std::vector<Diagnostic> diagnostics;  // parsing's, then validation's (check_scene)
    bool ok = false;                      // no errors
};

// Parses and validates `text` as jtracer-cli --check would a file at `path`.
CheckedText check_text(std::uint64_t id, std::string text, const std::filesystem::path& path);

class TextChecker {
  public:
    TextChecker();
    ~TextChecker();
    TextChecker(const TextChecker&) = delete;
    TextChecker& operator=(const TextChecker&) = delete;

    // Checks `text` once `pause` has passed without a newer call.
    void check(std::uint64_t id, std::string text, const std::filesystem::path& path,
               std::chrono::milliseconds pause);
    // Drops the waiting text and any result not yet taken.
    void cancel();
    // The newest check's result once it is done, handed out once.
    std::optional<CheckedText> take();
    // A text is waiting or being checked.
    bool in_flight() const;
    // Notified whenever a result is ready. Set before the first check.
    void set_wakeup(Wakeup* wakeup);
    // Blocks until the newest text is checked (tests).
    void wait() const;

  private:
    struct Request {
        std::uint64_t id;
        std::string text;
        std::filesystem::path path;
        std::chrono::steady_clock::time_point due;
    };
    void work();

    mutable std::mutex mutex_;
    mutable std::condition_variable changed_;
    std::optional<Request> next_;
    bool checking_ = false;
    std::optional<CheckedText> result_;
    bool quit_ = false;
    Wakeup* wakeup_ = nullptr;
    std::thread worker_;  // last: starts once the members above exist
};

}  // namespace jt::view
