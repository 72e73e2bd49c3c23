#pragma once
// The viewer's panels. Each draws its part of the sidebar (or the status line)
// for one frame and edits AppState through app_actions.hpp.

#include "model/app_state.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace jt::view {

void file_panel(AppState& state);
void camera_panel(AppState& state);
void settings_panel(AppState& state);
void objects_panel(AppState& state);  // every primitive: shape, material, transform
void lights_panel(AppState& state);
// The Diagnostics panel's text: each diagnostic as the CLI prints it, its
// first line and the source line quoted under it, made once per change of
// the document's diagnostics (SceneDocument::diagnostics_generation).
struct DiagnosticsText {
    std::uint64_t generation = 0;
    std::size_t count = 0;  // of the diagnostics it was made from
    struct Entry {
        bool error = false;
        std::string message;  // "file:line:col: error: ..."
        std::string quote;    // the source line and a caret under the column, or empty
    };
    std::vector<Entry> entries;
    // Whether the last frame showed the first diagnostic within the sidebar's
    // view: a small window leaves the panel far below it, where an error
    // found on reload goes unseen.
    bool first_in_view = false;
    // Asked for by the status line's link: the next frame scrolls the sidebar
    // to the panel. Never on its own: a sidebar that scrolled by itself moved
    // the controls under the mouse (and under clicks on their way).
    bool scroll_to = false;
};
void diagnostics_panel(AppState& state, DiagnosticsText& text);
void help_panel();
// The time slider and play button, when the scene uses `clock` (drawn in
// the image's toolbar, which stays in view while the panels scroll), ending
// at screen x `right`.
void time_panel(AppState& state, float right);
// The render's progress, then the last message, or `inspected` (the pixel
// inspector's text, when not empty) in its place. With errors the
// Diagnostics panel lists out of the sidebar's view (`diagnostics`, when
// given) and the text editor closed, the message starts with a link that
// scrolls the sidebar to them.
void status_line(AppState& state, const std::string& inspected = {},
                 DiagnosticsText* diagnostics = nullptr, bool text_editor_open = false);

// Parts of objects_panel, one primitive at a time.
// Each field that changes the scene makes the editor return true (or set
// `changed`): the caller announces it with note_scene_changed.
// Each field is marked by where its value comes from in `primitive`'s text
// (field_sources.hpp), when it has one.
bool material_editor(Material& material, const SceneDocument& doc, const BlockSource* primitive);
// What the transform editor's buttons ask for: run after the panel is drawn,
// since it replaces the scene the panel holds references into.
struct TransformCommand {
    enum class Kind { add, move, remove } kind = Kind::add;
    std::size_t index = 0;                        // the operation moved or removed
    std::size_t to = 0;                           // where it moves
    TransformKind op = TransformKind::translate;  // the kind added
};
// `why_not` (why_not_rewrite_block) disables the buttons that add, move
// and remove operations.
std::optional<TransformCommand> transform_editor(std::vector<TransformOp>& transforms,
                                                 bool& changed, const SceneDocument& doc,
                                                 const BlockSource* primitive,
                                                 const std::string& why_not);

// "sample 4 of 16 | 1.2 s elapsed, about 3.0 s left | 3.4 Mrays/s",
// "paused at preview 1/4 | edit waiting: Space renders it", "done: ...",
// "done: 4 samples, paused | edits wait for Space"
std::string render_status(const AppState& state);
// The same, written into `text` (its storage kept: the status line's every frame).
void render_status(const AppState& state, std::string& text);

// The monospaced font (for source lines with a caret), when one is loaded.
void push_monospace_font();
void pop_monospace_font();

}  // namespace jt::view
