#include "model/editor_files.hpp"

#include "jtracer/scene_file.hpp"
#include "jtracer/source_edit.hpp"
#include "model/image_files.hpp"
#include "model/text_checker.hpp"

#include <algorithm>
#include <optional>
#include <utility>

namespace jt::view {

std::span<const SourceFile> latest_readings(const SceneDocument& doc) {
    // A load that failed left the scene (and its readings) of the last good
    // one; the files it read are what is on disk now.
    if (doc.load_failed && !doc.diagnostics_files.empty()) return doc.diagnostics_files;
    return doc.source.files;
}

bool first_reading(std::span<const SourceFile> readings, std::size_t index) {
    for (std::size_t i = 0; i < index; ++i)
        if (readings[i].canonical == readings[index].canonical) return false;
    return true;
}

int reading_count(std::span<const SourceFile> readings, std::string_view canonical) {
    return static_cast<int>(
        std::count_if(readings.begin(), readings.end(),
                      [&](const SourceFile& f) { return f.canonical == canonical; }));
}

const SourceFile* reading_of(const SceneDocument& doc, std::string_view canonical) {
    for (const SourceFile& f : latest_readings(doc))
        if (f.canonical == canonical) return &f;
    return nullptr;
}

std::string included_text(const SceneDocument& doc, std::string_view canonical) {
    const SourceFile* read = reading_of(doc, canonical);
    if (!read) return {};
    // The panels' edits apply to the document's own readings.
    if (latest_readings(doc).data() == doc.source.files.data() && doc.loaded && !doc.draft &&
        scene_edited(doc)) {
        SourceEditResult edit = apply_scene_edits(doc.text, doc.source, *doc.original, doc.scene);
        if (edit.ok())
            for (EditedFile& edited : edit.files)
                if (doc.source.files[edited.file - 1].canonical == canonical)
                    return std::move(edited.text);
    }
    return read->text;
}

namespace {

IncludedDraft* find_draft(EditorFiles& files, std::string_view canonical) {
    for (IncludedDraft& d : files.drafts)
        if (d.canonical == canonical) return &d;
    return nullptr;
}

// The first line of a formatted diagnostic ("file:line:col: error: message").
std::string first_line(const std::string& text) {
    return text.substr(0, text.find('\n'));
}

}  // namespace

const IncludedDraft* draft_of(const EditorFiles& files, std::string_view canonical) {
    for (const IncludedDraft& d : files.drafts)
        if (d.canonical == canonical) return &d;
    return nullptr;
}

bool has_included_drafts(const EditorFiles& files) {
    return !files.drafts.empty();
}

void show_file(EditorFiles& files, const SceneDocument& doc, std::string_view canonical) {
    if (!canonical.empty() && !reading_of(doc, canonical) && !draft_of(files, canonical))
        canonical = {};
    files.shown = std::string(canonical);
}

namespace {

// What the editor shows for `canonical`: its draft, else its text.
std::string shown_text(const EditorFiles& files, const SceneDocument& doc,
                       std::string_view canonical) {
    const IncludedDraft* draft = draft_of(files, canonical);
    return draft ? draft->text : included_text(doc, canonical);
}

// Whether `base` is the text the shown file's typing starts from: its
// draft's base, else the file's text as the editor shows it.
bool typed_over(const EditorFiles& files, const SceneDocument& doc, const std::string& base) {
    const IncludedDraft* draft = draft_of(files, files.shown);
    return draft ? draft->base == base : included_text(doc, files.shown) == base;
}

void forget_history(EditorFiles& files, std::string_view canonical) {
    std::erase_if(files.histories,
                  [&](const IncludedHistory& h) { return h.canonical == canonical; });
}

// The shown file's undo steps; null when it has none. Steps typed over a
// text the file no longer shows (it changed on disk, or a panel edit
// changed its values, with nothing typed since) would put that text back
// unasked: they go.
IncludedHistory* shown_history(EditorFiles& files, const SceneDocument& doc) {
    for (IncludedHistory& h : files.histories)
        if (h.canonical == files.shown) {
            if (typed_over(files, doc, h.base)) return &h;
            forget_history(files, files.shown);
            return nullptr;
        }
    return nullptr;
}

// The text typed or stepped to: the shown file's draft, or none when it is
// the file's text again.
void set_included_text(EditorFiles& files, const SceneDocument& doc, std::string text) {
    IncludedDraft* draft = find_draft(files, files.shown);
    if (!draft) {
        const SourceFile* read = reading_of(doc, files.shown);
        if (!read) return;
        std::string base = included_text(doc, files.shown);
        if (text == base) return;
        files.drafts.push_back({read->canonical,
                                read->path,
                                std::string(short_file_name(doc, read->name)),
                                std::move(base),
                                read->text,
                                {},
                                {}});
        draft = &files.drafts.back();
    }
    draft->problem.clear();
    // Typed back to the text the file shows now: nothing to save, but the
    // steps that led here stay. Back to the text typing began over, when the
    // file changed since, is a draft still: dropped, the editor would show
    // the file's new text instead, and the steps (typed over the old one)
    // would go with the typed text.
    const bool read = reading_of(doc, files.shown) != nullptr;
    if (text == (read ? included_text(doc, files.shown) : draft->base)) {
        std::erase_if(files.drafts,
                      [&](const IncludedDraft& d) { return d.canonical == files.shown; });
        return;
    }
    draft->text = std::move(text);
}

// Moves the shown file's text one step along `step` (undo or redo).
template <class Step>
bool step_included_typing(EditorFiles& files, const SceneDocument& doc, Step step) {
    if (files.shown.empty()) return false;
    IncludedHistory* history = shown_history(files, doc);
    if (!history) return false;
    std::optional<std::string> text = step(history->steps, shown_text(files, doc, files.shown));
    if (!text) return false;
    history->last_typed.reset();  // the next keystroke begins a step of its own
    set_included_text(files, doc, std::move(*text));
    ++files.steps_taken;
    return true;
}

}  // namespace

void type_included_text(EditorFiles& files, const SceneDocument& doc, std::string text,
                        std::chrono::steady_clock::time_point now) {
    if (files.shown.empty() || (!reading_of(doc, files.shown) && !draft_of(files, files.shown)))
        return;
    std::string before = shown_text(files, doc, files.shown);
    if (text == before) return;
    IncludedHistory* history = shown_history(files, doc);
    if (!history) {
        const IncludedDraft* draft = draft_of(files, files.shown);
        IncludedHistory& added = files.histories.emplace_back();
        added.canonical = files.shown;
        added.base = draft ? draft->base : included_text(doc, files.shown);
        history = &added;
    }
    if (!history->last_typed || now - *history->last_typed >= kTypingPause)
        history->steps.record(std::move(before));
    history->last_typed = now;
    set_included_text(files, doc, std::move(text));
}

bool undo_included_typing(EditorFiles& files, const SceneDocument& doc) {
    return step_included_typing(files, doc, [](SnapshotStack<std::string>& steps, std::string now) {
        return steps.undo(std::move(now));
    });
}

bool redo_included_typing(EditorFiles& files, const SceneDocument& doc) {
    return step_included_typing(files, doc, [](SnapshotStack<std::string>& steps, std::string now) {
        return steps.redo(std::move(now));
    });
}

void revert_included_draft(EditorFiles& files, std::string_view canonical) {
    std::erase_if(files.drafts, [&](const IncludedDraft& d) { return d.canonical == canonical; });
    forget_history(files, canonical);
}

void forget_included_drafts(EditorFiles& files) {
    files.drafts.clear();
    files.histories.clear();
}

namespace {

// Why saving the draft would replace text not seen when typing began, or empty.
std::string draft_conflict(const SceneDocument& doc, const IncludedDraft& d) {
    const Expected<std::string> disk = read_text_file(d.path);
    if (!disk || *disk != d.disk)
        return d.name + " was changed by another program since you began typing in it";
    if (reading_of(doc, d.canonical) && included_text(doc, d.canonical) != d.base)
        return d.name +
               " changed (reloaded, or a panel edit of its values) since you began "
               "typing in it";
    return {};
}

}  // namespace

std::string included_draft_conflict(const SceneDocument& doc, const EditorFiles& files) {
    for (const IncludedDraft& d : files.drafts)
        if (std::string conflict = draft_conflict(doc, d); !conflict.empty()) return conflict;
    return {};
}

std::vector<std::string> conflicting_drafts(const SceneDocument& doc, const EditorFiles& files) {
    std::vector<std::string> canonicals;
    for (const IncludedDraft& d : files.drafts)
        if (!draft_conflict(doc, d).empty()) canonicals.push_back(d.canonical);
    return canonicals;
}

Expected<void> check_included_drafts(const SceneDocument& doc, EditorFiles& files) {
    if (files.drafts.empty()) return {};
    // The scene as Save scene would leave it: the panels' edits written in,
    // and each drafted file read as typed.
    std::string main_text = document_text(doc);
    std::vector<std::pair<std::string, std::string>> texts;  // canonical, text
    if (doc.loaded && !doc.draft && scene_edited(doc)) {
        SourceEditResult edit = apply_scene_edits(doc.text, doc.source, *doc.original, doc.scene);
        if (edit.ok())
            for (EditedFile& edited : edit.files)
                texts.emplace_back(doc.source.files[edited.file - 1].canonical,
                                   std::move(edited.text));
    }
    for (const IncludedDraft& d : files.drafts) texts.emplace_back(d.canonical, d.text);
    ParseOptions options = doc.options;
    options.read_include = [&texts](const std::string& file,
                                    std::uintmax_t max_bytes) -> Expected<IncludedText> {
        Expected<IncludedText> read = read_include_file(file, max_bytes);
        if (!read) return read;
        // The last text of a file wins: a draft over the panels' edits.
        for (const auto& [canonical, text] : texts)
            if (canonical == read->canonical) read->text = text;
        return read;
    };
    const CheckedText checked = check_text(0, std::move(main_text), doc.path, options);
    const std::vector<SourceFile>& read = checked.parsed.source.files;
    for (const Diagnostic& d : checked.diagnostics) {
        if (d.severity != Severity::error || d.pos.file == 0 || d.pos.file > read.size()) continue;
        IncludedDraft* draft = find_draft(files, read[d.pos.file - 1].canonical);
        if (!draft) continue;
        // Named as the editor names the file.
        const std::string& name = read[d.pos.file - 1].name;
        std::string line = first_line(format_diagnostic(d, doc.path.string(), checked.text, read));
        if (line.starts_with(name))
            line = std::string(short_file_name(doc, name)) + line.substr(name.size());
        draft->problem = std::move(line);
        return Error{draft->problem};
    }
    return {};
}

Expected<std::vector<std::string>> write_included_drafts(EditorFiles& files) {
    for (const IncludedDraft& d : files.drafts)
        if (Expected<void> ok = check_writable(d.path); !ok) return ok.error();
    std::vector<std::string> written;
    while (!files.drafts.empty()) {
        const IncludedDraft& d = files.drafts.front();
        if (Expected<void> done = write_text_atomically(d.path, d.text); !done)
            return Error{done.error().message};
        written.push_back(d.name);
        forget_history(files, d.canonical);
        files.drafts.erase(files.drafts.begin());
    }
    return written;
}

std::string listed_names(const std::vector<std::string>& names) {
    std::string out;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (i > 0) out += i + 1 == names.size() ? " and " : ", ";
        out += names[i];
    }
    return out;
}

}  // namespace jt::view
