#pragma once
// The scene file the viewer has open. One document, whichever way it is
// edited: its text (the base), the parse of that text (scene + spans, the base
// for saving in place), the scene as edited in the panels since, and a draft
// typed in the text editor that has not parsed yet. A panel edit changes the
// scene; an edit of the structure (adding, deleting a block) or a draft that
// parses replaces the base; document_text is what Save scene writes.

#include "jtracer/diagnostics.hpp"
#include "jtracer/error.hpp"
#include "jtracer/parser.hpp"
#include "jtracer/scene.hpp"
#include "jtracer/source_edit.hpp"
#include "jtracer/source_map.hpp"
#include "model/text_diff.hpp"

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace jt::view {

struct SceneDocument {
    std::filesystem::path path;
    bool loaded = false;    // a good scene is held (from this file or an earlier one)
    std::string text;       // the text `original` and `source` were parsed from
    std::string disk_text;  // the file's bytes as last loaded or saved
    // The scene as in `text`; shared (never changed in place) so that a
    // render of the unedited scene and its preparation ahead use it as it is,
    // without copying 100,000 objects.
    std::shared_ptr<const Scene> original = std::make_shared<const Scene>();
    SceneSource source;
    Scene scene;                                // as edited in the viewer
    std::vector<Diagnostic> parse_diagnostics;  // the parser's warnings about `text`
    // Of the latest load attempt, or of the edited scene (check_edits).
    std::vector<Diagnostic> diagnostics;
    std::string diagnostics_source;             // the text they point into (to quote lines)
    std::filesystem::path diagnostics_path;     // the file they are about
    std::vector<SourceFile> diagnostics_files;  // the included files they may be in
    // Moved by every change of the four above (note_diagnostics_changed), so
    // that what formats them (quoting a line walks the text) does so once a
    // change, not every frame. No two documents share a value but 0 (none set).
    std::uint64_t diagnostics_generation = 0;
    // Every file the latest load read or tried to read through `include`, or
    // the text taken in since (typed, undone to) read: watched like the scene
    // file, so that a change, or a missing file appearing, reloads
    // (docs/language.md §15.6), or, for a text not saved yet, reads the text
    // again (reload_if_changed). After a load whose text parsed but failed
    // on a file it names, the model and image files its scene names too.
    std::vector<std::filesystem::path> included_files;
    // Counts the loads taken in (good or not) and the saves: either may
    // change the texts read (the included files' too) without a new revision.
    std::uint64_t file_generation = 0;
    bool load_failed = false;   // the latest load attempt had errors: `scene` is older
    bool file_unread = false;   // the latest load could not read the file at all
    bool file_deleted = false;  // ... because it is not there
    // Text typed in the text editor, not yet taken in: waiting for its check,
    // or with errors (`diagnostics` then describe it and `scene` is the last
    // good one).
    std::optional<std::string> draft;
    // Counts the changes of `scene`, whoever makes them (a load, a panel
    // field, a drag, undo): a frame compares this number instead of the
    // scenes, so that a frame with nothing to do copies and compares nothing.
    std::uint64_t revision = 0;
    // Whether `scene` differs from `original`, as found at a revision: asked
    // every frame (the title's "*"), it is worked out once per change.
    mutable std::optional<std::pair<std::uint64_t, bool>> edited_at;
    // Whether `text` differs from `disk_text`, as found at a revision and
    // file generation (every change of either text moves one of them): asked
    // every frame too, and the texts of 100,000 objects are 14 MB.
    mutable std::optional<std::pair<std::pair<std::uint64_t, std::uint64_t>, bool>> text_changed_at;
    // What every text of the document is parsed with: the command line's
    // --define, and the clock the time slider stands at (docs/language.md
    // §15.2, §15.4). Always with the source map: saving writes at its spans.
    ParseOptions options;
    // The word `clock` stands in a value of `text` (a property or a define):
    // the time slider shows. Worked out once per text taken in.
    bool uses_clock = false;
};

// Every change of doc.scene is announced with this.
inline void note_scene_changed(SceneDocument& doc) {
    ++doc.revision;
}

// Every change of doc.diagnostics or the texts they quote is announced with this.
void note_diagnostics_changed(SceneDocument& doc);

// What undo brings back: the document's base text, its scene as edited, its draft.
struct DocumentVersion {
    std::string text;
    Scene scene;
    std::optional<std::string> draft;
    double clock = 0.0;  // the clock `scene`'s values were computed at
    bool operator==(const DocumentVersion&) const = default;
};

DocumentVersion version_of(const SceneDocument& doc);
// Brings the document back to `version`, parsing its text when the base differs.
void restore_version(SceneDocument& doc, const DocumentVersion& version);

// The document's text as Save scene would write it: the draft, or the base
// with the panel edits written in (see source_edit.hpp); the base when they
// cannot be. Before any good load, the file's text (an empty file, one with
// errors), which the text editor can then mend.
std::string document_text(const SceneDocument& doc);

// Makes `parsed` (of `text`, without errors) the document's base, its scene
// the edited one; the draft goes.
void take_text(SceneDocument& doc, std::string text, ParseResult parsed);

// Parses `text` and takes it in when it has no errors; otherwise nothing
// changes and the error says where the first one is.
Expected<void> replace_text(SceneDocument& doc, std::string text);

// When a load reached each step (for the latency benchmark).
struct LoadTimes {
    using Clock = std::chrono::steady_clock;
    Clock::time_point requested, started, read, parsed, validated, taken;
};

struct LoadAttempt {
    bool ok = false;
    bool read = false;     // the file's bytes were read (ok or not, they are `text`)
    bool missing = false;  // not read because the file is not there
    std::string text;
    std::shared_ptr<const Scene> scene = std::make_shared<const Scene>();
    // A copy of `scene` made beside the validation and the preparation for
    // the document's edited scene, so that the frame taking the load in
    // copies nothing; when empty accept_load copies `scene`.
    std::optional<Scene> scene_copy;
    // What accept_load derives from `text`, made by the loader while an
    // open's preparation runs (scene_loader.hpp: prepared_ahead_hold) so that
    // the frame taking the load in neither copies nor scans the text (14 MB
    // for 100,000 objects: 3-4 ms); when empty accept_load makes them.
    struct TextCopies {
        std::string diagnostics_source;  // SceneDocument's
        std::string disk_text;           // SceneDocument's
        bool uses_clock = false;         // text_uses_clock(text, source)
    };
    std::optional<TextCopies> text_copies;
    SceneSource source;
    std::vector<Diagnostic> diagnostics;        // parsing's and validation's (check_scene)
    std::vector<Diagnostic> parse_diagnostics;  // parsing's alone
    LoadTimes times;
};

// Called with the scene a load parsed without errors, before it is
// validated: work that reads it (the document's copy of it) can start there
// and run beside the validation. The scene is the attempt's, never changed.
using ParsedScene = std::function<void(const std::shared_ptr<const Scene>&)>;

// Reads, parses and validates `path` through the core (scene_file.hpp). A
// missing, unreadable or garbage file comes back as diagnostics.
LoadAttempt attempt_load(const std::filesystem::path& path, const ParseOptions& options = {},
                         const ParsedScene& parsed = {});

// What the document's texts are parsed with: doc.options, with the source
// map and the file's path for its includes.
ParseOptions document_options(const SceneDocument& doc);
// The same, reading each included file `edit` changes as it would be
// written (`edit` must outlive the options).
ParseOptions document_options(const SceneDocument& doc, const SourceEditResult& edit);
// `text` parsed as the document parses every text.
ParseResult parse_document_text(const SceneDocument& doc, std::string_view text);

// Takes `attempt` into `doc`: on success the scene is replaced, on failure
// the last good scene stays and only the diagnostics change. A failed open
// of a file other than the document's changes nothing else: the document is
// not that file's last good scene (diagnostics_of_another_file).
void accept_load(SceneDocument& doc, const std::filesystem::path& path, LoadAttempt attempt);

// The open file was read again and has errors: the document shows its text
// as a draft, with its diagnostics, so that it can be fixed in place (the
// scene and image stay the last good ones). That draft is the file as it is,
// no unsaved edit, and, having errors, is never saved over the file.
void accept_broken_file(SceneDocument& doc, LoadAttempt attempt);

// An included file's name as diagnostics print it (SourceFile::name), short:
// relative to the scene file's folder when it is inside it ("parts/ball.jts"
// for "/home/me/scenes/parts/ball.jts" of "/home/me/scenes/main.jts").
// A view into `name`: asked every frame, it allocates nothing.
std::string_view short_file_name(const SceneDocument& doc, std::string_view name);

// "file:line:col: error: message" lines, as the CLI prints them.
std::string format_diagnostics(const SceneDocument& doc);

// The diagnostics are of another file than the document's, one that failed
// to open while this one stayed.
bool diagnostics_of_another_file(const SceneDocument& doc);

bool has_unsaved_edits(const SceneDocument& doc);
// The scene differs from the one its text holds (panel edits not yet saved).
bool scene_edited(const SceneDocument& doc);

// A file with nothing in it (its text blank): one to start a scene in
// (start_new_scene).
bool document_is_blank(const SceneDocument& doc);

// Writes the edits into the file in place (see source_edit.hpp), atomically,
// then takes the new text as the document's base. Values read from included
// files are written into those. The files written come back for the status
// line: the scene file's path (left out when it already holds its text, only
// included values having changed), then the included files' names as
// diagnostics name them, each once.
// Does not look at what is on disk now: see file_changed_on_disk.
Expected<std::vector<std::string>> save_scene_in_place(SceneDocument& doc);
// The same into another file, which becomes the document's file.
Expected<std::vector<std::string>> save_scene_copy(SceneDocument& doc,
                                                   const std::filesystem::path& path);

// True when the file no longer holds the text the document was loaded from
// (edited by someone else, broken, deleted), so that saving over it would
// lose what is there; `what` then says how it differs.
bool file_changed_on_disk(const SceneDocument& doc, std::string& what);

// The edits made to `doc` (its scene against its original) applied to a newer
// text of the file, where the edited items still exist; the error says why
// they cannot be (items added or removed in the file).
Expected<Scene> reapply_edits(const SceneDocument& doc, const LoadAttempt& newer);

// The file that `newer`, a reading of the document's file, reads differently
// from the document: the scene file's name when its text differs from the
// one on disk before, else the first included file whose text differs or
// that one of them no longer reads (short_file_name); empty when every file
// reads the same, and reloading would only drop the unsaved edits.
std::string changed_on_disk(const SceneDocument& doc, const LoadAttempt& newer);

// What reloading would change, file by file: the scene file's text as Save
// would write it (document_text) and each included file's (as read, with the
// panels' edits of its values written in) against `newer`'s. Each file that
// differs is one line of kind `file` with its name (short_file_name) and then
// its differences; the counts are the sums.
TextDiff reload_differences(const SceneDocument& doc, const LoadAttempt& newer);

// The first file that both the document and a newer reading of its text
// (`files`, its SourceScene::files) include, but with another text: an
// included file changed on disk since the document read it (short_file_name).
// Empty when there is none; a file only one of them includes is no change of
// a file (an include typed or taken out).
std::string changed_include(const SceneDocument& doc, const std::vector<SourceFile>& files);

}  // namespace jt::view
