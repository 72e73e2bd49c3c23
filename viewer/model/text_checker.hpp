#pragma once
// Parses and validates the text being typed in the text editor on a thread of
// its own, once the typing has paused, so that neither a keystroke nor a big
// scene ever waits for the parser. The newest text wins: a check overtaken by
// a newer text is dropped, and a newer text restarts the pause.

#include "jtracer/diagnostics.hpp"
#include "jtracer/parser.hpp"
#include "model/latest_wins_worker.hpp"
#include "model/wakeup.hpp"

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace jt::view {

struct CheckedText {
    std::uint64_t id = 0;  // as given to TextChecker::check
    std::string text;
    ParseResult parsed;                   // the scene's asset_folder set to the file's folder
    std::vector<Diagnostic> diagnostics;  // parsing's, then validation's (check_scene)
    bool ok = false;                      // no errors
    double clock = 0.0;                   // the clock it was parsed at
};

// Parses and validates `text` as jtracer-cli --check would a file at `path`.
CheckedText check_text(std::uint64_t id, std::string text, const std::filesystem::path& path,
                       const ParseOptions& options = {});

class TextChecker {
  public:
    TextChecker();

    // Checks `text` once `pause` has passed without a newer call.
    void check(std::uint64_t id, std::string text, const std::filesystem::path& path,
               std::chrono::milliseconds pause, const ParseOptions& options = {});
    // Drops the waiting text and any result not yet taken.
    void cancel() { worker_.cancel(); }
    // The newest check's result once it is done, handed out once.
    std::optional<CheckedText> take() { return worker_.take(); }
    // A text is waiting or being checked.
    bool in_flight() const { return worker_.in_flight(); }
    // Notified whenever a result is ready. Set before the first check.
    void set_wakeup(Wakeup* wakeup) { worker_.set_wakeup(wakeup); }
    // Blocks until the newest text is checked (tests).
    void wait() const { worker_.wait(); }

  private:
    struct Request {
        std::uint64_t id;
        std::string text;
        std::filesystem::path path;
        ParseOptions options;
    };
    static CheckedText run_check(Request request);

    LatestWinsWorker<Request, CheckedText> worker_;
};

}  // namespace jt::view
