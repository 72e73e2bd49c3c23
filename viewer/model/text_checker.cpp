#include "model/text_checker.hpp"

#include "jtracer/parallel_chunks.hpp"
#include "jtracer/scene_file.hpp"

#include <exception>

namespace jt::view {

CheckedText check_text(std::uint64_t id, std::string text, const std::filesystem::path& path,
                       const ParseOptions& options) {
    LoadedScene loaded;
    loaded.path = path.string();
    loaded.options = options;
    loaded.options.source_map = true;
    loaded.options.main_file = loaded.path;
    loaded.parsed = parse_scene(text, loaded.options);
    loaded.parsed.scene.asset_folder = path.parent_path().string();
    loaded.text = std::move(text);
    CheckedText checked;
    checked.id = id;
    // Straight from the parser: its primitives' ranges need no second check.
    checked.diagnostics = check_scene(
        loaded, {.validation = {.run_chunks = parallel_chunks(), .primitives_as_parsed = true}});
    checked.ok = !has_errors(checked.diagnostics);
    checked.clock = options.clock;
    checked.text = std::move(loaded.text);
    checked.parsed = std::move(loaded.parsed);
    return checked;
}

TextChecker::TextChecker() : worker_(&TextChecker::run_check) {}

void TextChecker::check(std::uint64_t id, std::string text, const std::filesystem::path& path,
                        std::chrono::milliseconds pause, const ParseOptions& options) {
    worker_.submit(Request{id, std::move(text), path, options},
                   std::chrono::steady_clock::now() + pause);
}

CheckedText TextChecker::run_check(Request request) {
    try {
        return check_text(request.id, std::move(request.text), request.path, request.options);
    } catch (const std::exception& e) {  // out of memory, say
        CheckedText checked;
        checked.id = request.id;
        checked.diagnostics.push_back(Diagnostic{
            Severity::error, SourcePos{}, std::string("cannot check the text: ") + e.what()});
        return checked;
    }
}

}  // namespace jt::view
