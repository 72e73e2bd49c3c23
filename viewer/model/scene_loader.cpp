#include "model/scene_loader.hpp"

#include "model/scene_time.hpp"

#include <exception>
#include <future>
#include <memory>
#include <system_error>
#include <utility>

namespace jt::view {

SceneLoader::SceneLoader(std::chrono::milliseconds hold)
    : hold_(hold), worker_([this](Request request) { return load(std::move(request)); }) {}

void SceneLoader::request(const std::filesystem::path& path, LoadPurpose purpose,
                          const ParseOptions& options) {
    newest_is_open_ = purpose == LoadPurpose::open;
    worker_.submit(Request{path, purpose, options, LoadTimes::Clock::now()});
}

std::optional<FinishedLoad> SceneLoader::take() {
    std::optional<FinishedLoad> result = worker_.take();
    if (result) result->attempt.times.taken = LoadTimes::Clock::now();
    return result;
}

FinishedLoad SceneLoader::load(Request request) {
    LoadAttempt attempt;
    // The document's copy of an opened scene, made beside its validation and
    // then its preparation (the copy of 100,000 objects takes as long as the
    // preparation; the validation leaves a core free).
    std::future<Scene> copy;
    const auto start_copy = [&](const std::shared_ptr<const Scene>& scene) {
        if (request.purpose != LoadPurpose::open || worker_.superseded()) return;
        try {
            copy = std::async(std::launch::async, [scene] { return Scene(*scene); });
        } catch (const std::system_error&) {  // no thread to spare: copied below
        }
    };
    try {
        attempt = attempt_load(request.path, request.options, start_copy);
    } catch (const std::exception& e) {  // out of memory, say
        attempt = LoadAttempt{};
        attempt.diagnostics.push_back(Diagnostic{Severity::error, SourcePos{},
                                                 std::string("cannot load the file: ") + e.what()});
    }
    attempt.times.requested = request.requested;
    std::optional<PreparedAhead> ahead;
    // Only an open: a reload of the same objects reuses the geometry already
    // prepared (the render controller's prepare_scene_edit), which a fresh
    // preparation here would only delay. Nor an open already overtaken: its
    // result is dropped, and the next open would wait for its preparation.
    if (attempt.ok && request.purpose == LoadPurpose::open && !worker_.superseded()) {
        try {
            ahead = preparer_.start(attempt.scene);
            attempt.scene_copy = copy.valid() ? copy.get() : Scene(*attempt.scene);
            attempt.text_copies = LoadAttempt::TextCopies{
                attempt.text, attempt.text, text_uses_clock(attempt.text, attempt.source)};
        } catch (const std::exception& e) {  // out of memory
            const LoadTimes times = attempt.times;
            attempt = LoadAttempt{};
            attempt.times = times;
            attempt.diagnostics.push_back(Diagnostic{
                Severity::error, SourcePos{}, std::string("cannot load the file: ") + e.what()});
            ahead.reset();
        }
    }
    if (ahead) hold_until_prepared(*ahead);
    return FinishedLoad{request.path, request.purpose, std::move(attempt), std::move(ahead)};
}

void SceneLoader::hold_until_prepared(const PreparedAhead& ahead) const {
    const auto until = LoadTimes::Clock::now() + hold_;
    while (!worker_.superseded() && LoadTimes::Clock::now() < until)
        if (ahead.prepared.wait_for(prepared_ahead_hold_slice) == std::future_status::ready) return;
}

}  // namespace jt::view
