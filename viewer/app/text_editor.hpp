#pragma once
// The text editor: the scene's text beside the image, in the monospaced
// font, with line numbers, the cursor's line highlighted, and each error
// marked on its line with its message and listed below, where a click puts
// the cursor at its line:col. What is typed goes to the document
// (document_edits.hpp: type_text); what the panels change shows in the text
// at once. Ctrl+Z / Ctrl+Shift+Z (or Ctrl+Y) in it walk the viewer's one
// undo history.
// An object or light picked in the image scrolls the text to its block, and
// a click in a block selects its object or light.
// Above the text, when the scene includes files, one button a file (the
// scene file first, then each included file once): choosing one shows its
// text (model/editor_files.hpp). What is typed in an included file is its
// draft, kept when another file is shown, written by Save scene (Ctrl+S);
// Ctrl+Z and Ctrl+Shift+Z (or Ctrl+Y) there undo and redo the typing in that
// file alone (model/editor_files.hpp).

#include "jtracer/scene.hpp"
#include "model/app_state.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace jt::view {

struct TextEditorState {
    bool open = false;
    std::string buffer;  // what the widget edits
    std::string shown;   // the document text `buffer` was last set from
    // The first byte of `shown` the widget cannot hold as it is (not UTF-8,
    // or a character past ImGui's 16-bit ones, U+FFFF), or npos. The widget
    // would write such a text back changed: it is not put in the widget.
    std::size_t unshowable = std::string::npos;
    // The document the shown text was made from (document_text is not free).
    std::string shown_base;
    std::uint64_t shown_revision = 0;  // SceneDocument::revision
    std::optional<std::string> shown_draft;
    // The included file the buffer holds (SourceFile::canonical; empty: the
    // scene file), and what its text was made from.
    std::string shown_file;
    std::uint64_t shown_generation = 0;  // SceneDocument::file_generation
    bool shown_file_draft = false;       // the file had a draft
    std::uint64_t shown_steps = 0;       // EditorFiles::steps_taken
    // The file buttons: the indexes of the first readings of each included
    // file (latest_readings), found again only when the document changed.
    std::vector<std::size_t> listed;
    std::uint64_t listed_revision = 0, listed_generation = 0;
    bool listed_failed = false;
    bool listed_once = false;
    bool push = false;              // the buffer changed under an active widget
    int cursor = 0;                 // byte offset of the cursor, while the widget is active
    std::optional<int> jump;        // put the cursor here (a click on an error)
    std::optional<int> scroll_to;   // line to bring into view
    bool select_at_cursor = false;  // a click in the text: select the block at the cursor
    // Where the last frame drew the text: the top left of line 1 (scrolled)
    // and the height of a line, in window units.
    float line1_x = 0.0f, line1_y = 0.0f, line_height = 0.0f;
    float cursor_x = 0.0f;  // the cursor's x, while the widget is active
    // The scene file and shown file the view's scroll is of: another starts
    // at its top left.
    std::string scrolled_path, scrolled_file;
    // An error's line as drawn, its storage kept so that a frame like the
    // last one allocates nothing.
    std::string label;
};

// Texts larger than this are not put in the widget (it keeps a copy per character).
inline constexpr std::size_t kMaxEditableText = 4u << 20;

// Under an included file's typed text, which is read with the scene only when
// saved: no list of errors can describe it before.
inline constexpr const char* kCheckedWhenSaved =
    "Not checked yet: Save (Ctrl+S) reads the scene with this text first";

// Draws the editor as a window filling `x0..x1` x `y0..y1`.
void text_editor(AppState& state, TextEditorState& editor, float x0, float y0, float x1, float y1);

// The byte offset of line:column (both from 1) in `text`, clamped to the text.
int offset_of(const std::string& text, int line, int column);

}  // namespace jt::view
