#include "model/scene_time.hpp"

#include "jtracer/source_edit.hpp"
#include "jtracer/value_text.hpp"
#include "model/app_actions.hpp"
#include "model/app_state.hpp"

#include <cmath>

namespace jt::view {

namespace {

bool is_name_char(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

// `clock` as a whole word of `value` (a value holds no comment; a string
// value is a literal, which is not looked at).
bool names_clock(std::string_view value) {
    constexpr std::string_view word = "clock";
    for (std::size_t at = value.find(word); at != std::string_view::npos;
         at = value.find(word, at + 1)) {
        const bool starts = at == 0 || !is_name_char(value[at - 1]);
        const std::size_t end = at + word.size();
        const bool ends = end == value.size() || !is_name_char(value[end]);
        if (starts && ends) return true;
    }
    return false;
}

// The span's text, in the main text or in the included file it is in.
std::string_view span_text(std::string_view text, const SceneSource& source, const TextSpan& span) {
    const std::string_view file = file_text(source.files, text, span.pos.file);
    if (span.offset > file.size()) return {};
    return file.substr(span.offset, span.length);
}

}  // namespace

bool text_uses_clock(std::string_view text, const SceneSource& source) {
    for (const PropertySource& p : source.properties)
        if (p.origin != ValueOrigin::literal && names_clock(span_text(text, source, p.value_span)))
            return true;
    for (const DefinitionSource& d : source.definitions)
        if (d.origin != ValueOrigin::literal && names_clock(span_text(text, source, d.value_span)))
            return true;
    return false;
}

bool set_clock(AppState& state, double clock) {
    SceneDocument& doc = state.doc;
    if (!std::isfinite(clock)) return false;
    if (clock == doc.options.clock) return true;
    // The undo step of a field being dragged holds the block at this clock.
    if (state.history.edit_base || state.drags.object) return false;
    if (!doc.loaded) {
        doc.options.clock = clock;
        return true;
    }
    ParseOptions at = document_options(doc);
    at.clock = clock;
    ParseResult original = parse_scene(doc.text, at);
    if (!original.ok()) {
        for (const Diagnostic& d : original.diagnostics)
            if (d.severity == Severity::error) {
                state.message = "At clock " + number_text(clock) + " the scene has an error (" +
                                std::to_string(d.pos.line) + ":" + std::to_string(d.pos.column) +
                                ": " + d.message + "); the image stays at clock " +
                                number_text(doc.options.clock);
                break;
            }
        return false;
    }
    original.scene.asset_folder = doc.original->asset_folder;
    Scene edited = original.scene;
    if (scene_edited(doc)) {
        // The panels' edits are literal values: written into the text, they
        // read back the same at any clock.
        const SourceEditResult edit =
            apply_scene_edits(doc.text, doc.source, *doc.original, doc.scene);
        if (!edit.ok()) {
            state.message = "Cannot compute the scene at another clock: " + edit.error;
            return false;
        }
        ParseOptions with_files = document_options(doc, edit);
        with_files.clock = clock;
        ParseResult with_edits = parse_scene(edit.text, with_files);
        if (!with_edits.ok()) return false;
        edited = std::move(with_edits.scene);
        edited.asset_folder = doc.original->asset_folder;
    }
    doc.options.clock = clock;
    doc.original = std::make_shared<const Scene>(std::move(original.scene));
    doc.source = std::move(original.source);
    doc.parse_diagnostics = std::move(original.diagnostics);
    doc.scene = std::move(edited);
    note_command_edit(state.history, doc);
    return true;
}

void toggle_play(AppState& state, std::chrono::steady_clock::time_point now) {
    TimeState& time = state.time;
    time.playing = !time.playing;
    time.last_step = now;
    if (time.playing && state.doc.options.clock >= 1.0) set_clock(state, 0.0);
}

void step_play(AppState& state, std::chrono::steady_clock::time_point now) {
    TimeState& time = state.time;
    if (!time.playing) return;
    if (!state.doc.uses_clock) {
        time.playing = false;
        return;
    }
    const double seconds = std::chrono::duration<double>(now - time.last_step).count();
    const double loop = std::chrono::duration<double>(kPlayLoop).count();
    double next = state.doc.options.clock + seconds / loop;
    if (next > 1.0) next = std::fmod(next, 1.0);
    if (!(next >= 0.0)) next = 0.0;
    // A step refused (a field held, an error at that clock) is tried again
    // from the same place next frame: the time it covered is not lost.
    if (set_clock(state, next)) time.last_step = now;
}

}  // namespace jt::view
