#include "model/scene_loader.hpp"

#include <exception>

namespace jt::view {

SceneLoader::SceneLoader() : worker_(&SceneLoader::load) {}

void SceneLoader::request(const std::filesystem::path& path, LoadPurpose purpose,
                          const ParseOptions& options) {
    worker_.submit(Request{path, purpose, options, LoadTimes::Clock::now()});
}

std::optional<FinishedLoad> SceneLoader::take() {
    std::optional<FinishedLoad> result = worker_.take();
    if (result) result->attempt.times.taken = LoadTimes::Clock::now();
    return result;
}

FinishedLoad SceneLoader::load(Request request) {
    LoadAttempt attempt;
    try {
        attempt = attempt_load(request.path, request.options);
    } catch (const std::exception& e) {  // out of memory, say
        attempt = LoadAttempt{};
        attempt.diagnostics.push_back(Diagnostic{Severity::error, SourcePos{},
                                                 std::string("cannot load the file: ") + e.what()});
    }
    attempt.times.requested = request.requested;
    return FinishedLoad{request.path, request.purpose, std::move(attempt)};
}

}  // namespace jt::view
