#pragma once
// The files the text editor opens (docs/language.md §15.6): the scene file
// first, then each file the scene includes, once, named as diagnostics name
// it. The scene file's text is the document's (document_text, type_text). An
// included file's typed text is a draft of its own, kept per file until it
// is saved or reverted, so that switching files never loses any. Save scene
// writes the drafts too: each atomically into its file, once the scene reads
// without errors in it, then the scene reloads.

#include "jtracer/error.hpp"
#include "jtracer/source_files.hpp"
#include "model/scene_document.hpp"
#include "model/undo_stack.hpp"

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace jt::view {

// An included file's text as typed in the editor, not saved yet.
struct IncludedDraft {
    std::string canonical;  // SourceFile::canonical: which file
    std::string path;       // where it is written (SourceFile::path)
    std::string name;       // as the editor shows it (short_file_name)
    std::string base;       // the text shown when typing began (included_text)
    std::string disk;       // the file's text as read then
    std::string text;       // as typed
    // Why the last Save did not write it (an error in it), or empty.
    std::string problem;
};

// How long typing must pause before the text is parsed again; a keystroke
// after such a pause begins a new undo step, in the scene file and in an
// included one alike.
inline constexpr std::chrono::milliseconds kTypingPause{250};

// The typing in one included file as undo steps, kept apart from the
// scene's history (whose steps are the scene file's texts): the texts the
// file showed before each run of keystrokes.
struct IncludedHistory {
    std::string canonical;
    std::string base;  // the text shown without a draft when the steps were typed
    SnapshotStack<std::string> steps;
    // The last keystroke's time; none when the next begins a step of its own.
    std::optional<std::chrono::steady_clock::time_point> last_typed;
};

struct EditorFiles {
    // The included file the editor shows (SourceFile::canonical); empty: the scene file.
    std::string shown;
    std::vector<IncludedDraft> drafts;
    std::vector<IncludedHistory> histories;
    // Counts the undos and redos of that typing: the editor shows the text
    // again when it changed.
    std::uint64_t steps_taken = 0;
};

// The readings of included files the editor lists: those of the latest load
// (a file with errors is listed with its text as read, to be mended), else
// those of the document's text.
std::span<const SourceFile> latest_readings(const SceneDocument& doc);

// Whether readings[index] is the first reading of its file (the list names
// each file once).
bool first_reading(std::span<const SourceFile> readings, std::size_t index);

// How many times the scene reads the file `canonical`.
int reading_count(std::span<const SourceFile> readings, std::string_view canonical);

// The latest reading of `canonical`, or null when the scene no longer reads it.
const SourceFile* reading_of(const SceneDocument& doc, std::string_view canonical);

// The included file's text as the editor shows it without a draft: as read,
// with the panels' edits of its values written in (as Save scene would write it).
std::string included_text(const SceneDocument& doc, std::string_view canonical);

// The draft of `canonical`, or null.
const IncludedDraft* draft_of(const EditorFiles& files, std::string_view canonical);
bool has_included_drafts(const EditorFiles& files);

// Shows `canonical` in the editor (empty: the scene file); a file the scene
// does not read and no draft holds shows the scene file.
void show_file(EditorFiles& files, const SceneDocument& doc, std::string_view canonical);

// The shown included file's text changed to `text` in the editor: it becomes
// its draft (or the draft goes, when `text` is the file's text again). The
// first keystroke after a pause of kTypingPause records one undo step.
void type_included_text(
    EditorFiles& files, const SceneDocument& doc, std::string text,
    std::chrono::steady_clock::time_point now = std::chrono::steady_clock::now());

// Ctrl+Z and Ctrl+Shift+Z in the shown included file: its text before the
// last run of typing, or after the run undone last. False when there is none
// (or the file's text changed under the steps, which then go).
bool undo_included_typing(EditorFiles& files, const SceneDocument& doc);
bool redo_included_typing(EditorFiles& files, const SceneDocument& doc);

// Drops the draft of `canonical`, and its undo steps: the editor shows the
// file's text again.
void revert_included_draft(EditorFiles& files, std::string_view canonical);

// Drops every draft and every included file's undo steps (another scene opened).
void forget_included_drafts(EditorFiles& files);

// Why saving the drafts would replace text not seen when typing began: the
// file changed on disk, or a panel edit changed its values since; empty
// when nothing would be lost.
std::string included_draft_conflict(const SceneDocument& doc, const EditorFiles& files);
// The files (SourceFile::canonical) whose drafts included_draft_conflict
// finds such a change under.
std::vector<std::string> conflicting_drafts(const SceneDocument& doc, const EditorFiles& files);

// Checks that the scene, with each draft read in place of its file, has no
// error in a drafted text; the error quotes the first (and the draft keeps
// it as its problem).
Expected<void> check_included_drafts(const SceneDocument& doc, EditorFiles& files);

// Writes every draft into its file, atomically, and drops it with its undo
// steps; the names written, as diagnostics name them. On an error the drafts
// not written stay.
Expected<std::vector<std::string>> write_included_drafts(EditorFiles& files);

// "a", "a and b", "a, b and c": the files a save wrote, for the status line.
std::string listed_names(const std::vector<std::string>& names);

}  // namespace jt::view
