#include "model/scene_document.hpp"

#include <atomic>

#include "jtracer/parallel_chunks.hpp"
#include "jtracer/parser.hpp"
#include "jtracer/scene_file.hpp"
#include "jtracer/source_edit.hpp"
#include "jtracer/texture.hpp"
#include "model/image_files.hpp"
#include "model/scene_time.hpp"

#include <algorithm>
#include <fstream>
#include <iterator>

namespace jt::view {

LoadAttempt attempt_load(const std::filesystem::path& path, const ParseOptions& options,
                         const ParsedScene& parsed) {
    LoadAttempt attempt;
    attempt.times.started = LoadTimes::Clock::now();
    // With the source map: saving in place writes edits back at their spans.
    ParseOptions with_map = options;
    with_map.source_map = true;
    Expected<LoadedScene> read = load_scene_file(path, with_map);
    // The core reads and parses in one call: both steps end here.
    attempt.times.read = attempt.times.parsed = LoadTimes::Clock::now();
    if (!read) {
        std::error_code ec;
        attempt.missing = !std::filesystem::exists(path, ec) && !ec;
        attempt.diagnostics.push_back(
            Diagnostic{Severity::error, SourcePos{}, read.error().message});
        return attempt;
    }
    // The scene stays where it was parsed, so that what `parsed` starts can
    // read it while it is validated; the pointer keeps the load's other
    // members (emptied below) alive with it.
    const auto loaded = std::make_shared<LoadedScene>(std::move(*read));
    std::shared_ptr<const Scene> scene(loaded, &loaded->parsed.scene);
    attempt.read = true;
    if (parsed && !has_errors(loaded->parsed.diagnostics)) parsed(scene);
    // Straight from the parser: its primitives' ranges need no second check.
    attempt.diagnostics = check_scene(
        *loaded, {.validation = {.run_chunks = parallel_chunks(), .primitives_as_parsed = true}});
    attempt.parse_diagnostics = std::move(loaded->parsed.diagnostics);
    attempt.times.validated = LoadTimes::Clock::now();
    attempt.ok = !has_errors(attempt.diagnostics);
    attempt.text = std::move(loaded->text);
    attempt.scene = std::move(scene);
    attempt.source = std::move(loaded->parsed.source);
    return attempt;
}

ParseOptions document_options(const SceneDocument& doc) {
    ParseOptions options = doc.options;
    options.source_map = true;
    options.main_file = doc.path.string();
    return options;
}

ParseOptions document_options(const SceneDocument& doc, const SourceEditResult& edit) {
    ParseOptions options = document_options(doc);
    if (edit.files.empty()) return options;
    options.read_include = [&doc, &edit](const std::string& file,
                                         std::uintmax_t max_bytes) -> Expected<IncludedText> {
        Expected<IncludedText> read = read_include_file(file, max_bytes);
        if (!read) return read;
        for (const EditedFile& edited : edit.files)
            if (doc.source.files[edited.file - 1].canonical == read->canonical)
                read->text = edited.text;
        return read;
    };
    return options;
}

void note_diagnostics_changed(SceneDocument& doc) {
    static std::atomic<std::uint64_t> generations{0};
    doc.diagnostics_generation = ++generations;
}

ParseResult parse_document_text(const SceneDocument& doc, std::string_view text) {
    return parse_scene(text, document_options(doc));
}

namespace {

// The files `source`'s text read or tried to read through `include`: watched
// from now on (reload_if_changed).
void note_included_files(SceneDocument& doc, const SceneSource& source) {
    doc.included_files.clear();
    for (const SourceFile& file : source.files) doc.included_files.push_back(file.path);
    for (const std::string& file : source.unread_includes) doc.included_files.push_back(file);
}

}  // namespace

void accept_load(SceneDocument& doc, const std::filesystem::path& path, LoadAttempt attempt) {
    if (!attempt.ok && doc.loaded && path != doc.path) {
        // Another file did not open: the document, the files it reads and
        // their watches stay as they are. The diagnostics are the other
        // file's until the document's are checked again (an edit, a reload).
        doc.diagnostics = std::move(attempt.diagnostics);
        doc.diagnostics_path = path;
        doc.diagnostics_files = std::move(attempt.source.files);
        doc.diagnostics_source = std::move(attempt.text);
        note_diagnostics_changed(doc);
        return;
    }
    ++doc.file_generation;
    note_diagnostics_changed(doc);
    doc.diagnostics = std::move(attempt.diagnostics);
    doc.diagnostics_path = path;
    doc.diagnostics_files = attempt.source.files;
    note_included_files(doc, attempt.source);
    if (!attempt.ok && attempt.read && !has_errors(attempt.parse_diagnostics)) {
        // The text parsed, so what failed is a file it names (a sky map not
        // there yet, a broken model): the scene's files are watched only
        // once it loads, so these are watched with the included ones, and
        // the file appearing or mended reloads.
        const NamedFiles named = named_files(*attempt.scene);
        for (const std::filesystem::path& file : named.models) doc.included_files.push_back(file);
        for (const std::filesystem::path& file : named.images) doc.included_files.push_back(file);
    }
    doc.load_failed = !attempt.ok;
    doc.file_unread = !attempt.read;
    doc.file_deleted = attempt.missing;
    if (!attempt.ok) {
        doc.diagnostics_source = std::move(attempt.text);  // moved: it may be huge
        if (!doc.loaded) {
            // Nothing good yet: the text editor starts from the file as it is.
            doc.path = path;
            doc.disk_text = doc.diagnostics_source;
        }
        return;
    }
    std::optional<LoadAttempt::TextCopies>& copies = attempt.text_copies;
    doc.diagnostics_source = copies ? std::move(copies->diagnostics_source) : attempt.text;
    doc.parse_diagnostics = std::move(attempt.parse_diagnostics);
    doc.path = path;
    doc.loaded = true;
    doc.text = std::move(attempt.text);
    doc.disk_text = copies ? std::move(copies->disk_text) : doc.text;
    doc.original = std::move(attempt.scene);
    doc.source = std::move(attempt.source);
    if (attempt.scene_copy)
        doc.scene = std::move(*attempt.scene_copy);
    else
        doc.scene = *doc.original;
    doc.draft.reset();
    doc.uses_clock = copies ? copies->uses_clock : text_uses_clock(doc.text, doc.source);
    note_scene_changed(doc);
}

void accept_broken_file(SceneDocument& doc, LoadAttempt attempt) {
    const std::filesystem::path path = doc.path;
    accept_load(doc, path, std::move(attempt));
    if (!doc.loaded) return;  // the file's text is shown already (document_text)
    doc.disk_text = doc.diagnostics_source;
    doc.draft = doc.disk_text;
}

DocumentVersion version_of(const SceneDocument& doc) {
    // Before any text was taken in, the file's own text is what the editor
    // shows: undo brings it back as a draft.
    const double clock = doc.options.clock;
    if (!doc.loaded && !doc.draft) return {doc.text, doc.scene, doc.disk_text, clock};
    return {doc.text, doc.scene, doc.draft, clock};
}

void restore_version(SceneDocument& doc, const DocumentVersion& version) {
    if (version.text != doc.text) {
        ParseResult parsed = parse_document_text(doc, version.text);
        parsed.scene.asset_folder = doc.original->asset_folder;
        take_text(doc, version.text, std::move(parsed));
    }
    doc.scene = version.scene;
    doc.draft = version.draft;
    // A version kept at another clock: its edits are taken at this one.
    if (version.clock != doc.options.clock && doc.loaded) {
        ParseOptions then = document_options(doc);
        then.clock = version.clock;
        const Scene original_then = parse_scene(doc.text, then).scene;
        const SourceEditResult edit =
            apply_scene_edits(doc.text, doc.source, original_then, doc.scene);
        if (edit.ok()) {
            ParseResult now = parse_scene(edit.text, document_options(doc, edit));
            now.scene.asset_folder = doc.original->asset_folder;
            if (now.ok()) doc.scene = std::move(now.scene);
        }
    }
    note_scene_changed(doc);
}

namespace {

// The text the editor shows when it is held as it is (a draft, the file's own
// text, the base text with no edit); null when the edits must be written into
// the base text first.
const std::string* held_text(const SceneDocument& doc) {
    if (doc.draft) return &*doc.draft;
    if (!doc.loaded) return &doc.disk_text;
    if (!scene_edited(doc)) return &doc.text;
    return nullptr;
}

}  // namespace

std::string document_text(const SceneDocument& doc) {
    if (const std::string* held = held_text(doc)) return *held;
    SourceEditResult edit = apply_scene_edits(doc.text, doc.source, *doc.original, doc.scene);
    return edit.ok() ? std::move(edit.text) : doc.text;
}

void take_text(SceneDocument& doc, std::string text, ParseResult parsed) {
    doc.text = std::move(text);
    doc.original = std::make_shared<const Scene>(std::move(parsed.scene));
    doc.source = std::move(parsed.source);
    // A text typed or undone to reads its own includes, saved or not.
    note_included_files(doc, doc.source);
    doc.parse_diagnostics = std::move(parsed.diagnostics);
    doc.scene = *doc.original;
    doc.draft.reset();
    doc.load_failed = false;
    doc.uses_clock = text_uses_clock(doc.text, doc.source);
    note_scene_changed(doc);
}

Expected<void> replace_text(SceneDocument& doc, std::string text) {
    ParseResult parsed = parse_document_text(doc, text);
    for (const Diagnostic& d : parsed.diagnostics)
        if (d.severity == Severity::error)
            return Error{"the edited text does not parse (" + std::to_string(d.pos.line) + ":" +
                         std::to_string(d.pos.column) + ": " + d.message + ")"};
    parsed.scene.asset_folder = doc.original->asset_folder;
    take_text(doc, std::move(text), std::move(parsed));
    return {};
}

std::string_view short_file_name(const SceneDocument& doc, std::string_view name) {
    // Diagnostics name an included file from the scene file's name as given
    // (docs/language.md §15.6), which is where its folder is cut off.
    const std::string_view main = doc.path.native();
    const std::size_t slash = main.rfind('/');
    if (slash == std::string_view::npos) return name;
    const std::string_view folder = main.substr(0, slash + 1);
    if (name.size() > folder.size() && name.starts_with(folder)) name.remove_prefix(folder.size());
    return name;
}

std::string format_diagnostics(const SceneDocument& doc) {
    std::string out;
    const std::string name = doc.diagnostics_path.string();
    for (const Diagnostic& d : doc.diagnostics)
        out += format_diagnostic(d, name, doc.diagnostics_source, doc.diagnostics_files);
    return out;
}

bool scene_edited(const SceneDocument& doc) {
    if (!doc.edited_at || doc.edited_at->first != doc.revision)
        doc.edited_at = {doc.revision, doc.scene != *doc.original};
    return doc.edited_at->second;
}

bool diagnostics_of_another_file(const SceneDocument& doc) {
    return doc.loaded && !doc.diagnostics_path.empty() && doc.diagnostics_path != doc.path;
}

bool has_unsaved_edits(const SceneDocument& doc) {
    if (doc.draft) return *doc.draft != doc.disk_text;  // a broken file's own text is saved
    if (!doc.loaded) return false;
    if (scene_edited(doc)) return true;
    const std::pair key{doc.revision, doc.file_generation};
    if (!doc.text_changed_at || doc.text_changed_at->first != key)
        doc.text_changed_at = {key, doc.text != doc.disk_text};
    return doc.text_changed_at->second;
}

bool file_changed_on_disk(const SceneDocument& doc, std::string& what) {
    std::error_code ec;
    if (!std::filesystem::exists(doc.path, ec)) {
        what = "was deleted";
        return true;
    }
    // A size that differs answers without reading a file that may be huge.
    const std::uintmax_t size = std::filesystem::file_size(doc.path, ec);
    if (!ec && size == doc.disk_text.size()) {
        std::ifstream in(doc.path, std::ios::binary);
        std::string bytes(doc.disk_text.size(), '\0');
        if (in.read(bytes.data(), static_cast<std::streamsize>(bytes.size())) &&
            in.peek() == std::char_traits<char>::eof() && bytes == doc.disk_text)
            return false;
    }
    what = "was changed by another program";
    return true;
}

Expected<Scene> reapply_edits(const SceneDocument& doc, const LoadAttempt& newer) {
    if (!newer.ok) return Error{"the file on disk has errors"};
    if (doc.draft || doc.text != doc.disk_text)
        return Error{
            "the text itself was edited (typed, or blocks added or deleted); only "
            "changed values can be re-applied to a newer file"};
    SourceEditResult edit = apply_scene_edits(newer.text, newer.source, *doc.original, doc.scene);
    if (!edit.ok()) return Error{edit.error};
    // An edit of a value in an included file is read from that file's text
    // with the edit written in, as Save would write it; its place in
    // `edit.files` is one in the newer reading's files.
    ParseOptions options = document_options(doc);
    if (!edit.files.empty())
        options.read_include = [&newer, &edit](const std::string& file,
                                               std::uintmax_t max_bytes) -> Expected<IncludedText> {
            Expected<IncludedText> read = read_include_file(file, max_bytes);
            if (!read) return read;
            for (const EditedFile& edited : edit.files)
                if (newer.source.files[edited.file - 1].canonical == read->canonical)
                    read->text = edited.text;
            return read;
        };
    ParseResult parsed = parse_scene(edit.text, options);
    if (!parsed.ok()) return Error{"the edits do not fit the new text"};
    parsed.scene.asset_folder = newer.scene->asset_folder;
    return std::move(parsed.scene);
}

std::string changed_include(const SceneDocument& doc, const std::vector<SourceFile>& files) {
    for (const SourceFile& file : files)
        for (const SourceFile& old : doc.source.files)
            if (old.canonical == file.canonical && old.text != file.text)
                return std::string(short_file_name(doc, file.name));
    return {};
}

std::string changed_on_disk(const SceneDocument& doc, const LoadAttempt& newer) {
    if (newer.text != doc.disk_text) return doc.path.filename().string();
    const std::vector<SourceFile>& before = doc.source.files;
    const std::vector<SourceFile>& now = newer.source.files;
    for (const SourceFile& file : now) {
        const auto same = [&](const SourceFile& old) {
            return old.canonical == file.canonical && old.text == file.text;
        };
        if (std::find_if(before.begin(), before.end(), same) == before.end())
            return std::string(short_file_name(doc, file.name));
    }
    // A file read before and no longer (an error stopped the reading first).
    for (const SourceFile& file : before) {
        const auto read = [&](const SourceFile& next) { return next.canonical == file.canonical; };
        if (std::find_if(now.begin(), now.end(), read) == now.end())
            return std::string(short_file_name(doc, file.name));
    }
    return {};
}

TextDiff reload_differences(const SceneDocument& doc, const LoadAttempt& newer) {
    TextDiff all;
    const auto add = [&](std::string_view name, std::string_view mine, std::string_view theirs) {
        if (mine == theirs) return;
        TextDiff diff = diff_lines(mine, theirs);
        all.lines.push_back({DiffLine::Kind::file, std::string(name), 0, 0});
        std::move(diff.lines.begin(), diff.lines.end(), std::back_inserter(all.lines));
        all.removed += diff.removed;
        all.added += diff.added;
        all.coarse = all.coarse || diff.coarse;
    };
    add(doc.path.filename().string(), document_text(doc), newer.text);

    const std::vector<SourceFile>& before = doc.source.files;
    const std::vector<SourceFile>& now = newer.source.files;
    std::vector<EditedFile> edited;
    if (doc.loaded && !doc.draft && scene_edited(doc)) {
        SourceEditResult edit = apply_scene_edits(doc.text, doc.source, *doc.original, doc.scene);
        if (edit.ok()) edited = std::move(edit.files);
    }
    const auto first_of = [](const std::vector<SourceFile>& files, const std::string& canonical) {
        return std::find_if(files.begin(), files.end(),
                            [&](const SourceFile& f) { return f.canonical == canonical; });
    };
    const auto mine = [&](const SourceFile& file) -> std::string_view {
        for (const EditedFile& e : edited)
            if (before[e.file - 1].canonical == file.canonical) return e.text;
        return file.text;
    };
    for (auto f = now.begin(); f != now.end(); ++f) {
        if (first_of(now, f->canonical) != f) continue;  // listed at its first reading
        const auto old = first_of(before, f->canonical);
        add(short_file_name(doc, f->name), old == before.end() ? std::string_view() : mine(*old),
            f->text);
    }
    // A file read before and no longer (an error stopped the reading first).
    for (auto f = before.begin(); f != before.end(); ++f)
        if (first_of(before, f->canonical) == f && first_of(now, f->canonical) == now.end())
            add(short_file_name(doc, f->name), mine(*f), {});
    return all;
}

Expected<std::vector<std::string>> save_scene_in_place(SceneDocument& doc) {
    return save_scene_copy(doc, doc.path);
}

namespace {

// The first file the scene names relative to its folder (an image map, the
// background map, a mesh's model), or null.
const std::string* relative_file_name(const Scene& scene) {
    const auto relative = [](const std::string& name) {
        return !name.empty() && !std::filesystem::path(name).is_absolute();
    };
    if (relative(scene.settings.background_map)) return &scene.settings.background_map;
    for (const Primitive& p : scene.primitives) {
        if (const Mesh* mesh = shape_if<Mesh>(&p.shape); mesh && relative(mesh->file))
            return &mesh->file;
        if (relative(p.material.finish->image_map)) return &p.material.finish->image_map;
    }
    return nullptr;
}

std::filesystem::path folder_of(const std::filesystem::path& file) {
    std::error_code ec;
    const std::filesystem::path folder = std::filesystem::absolute(file, ec).parent_path();
    const std::filesystem::path canonical = std::filesystem::weakly_canonical(folder, ec);
    return ec ? folder : canonical;
}

}  // namespace

Expected<std::vector<std::string>> save_scene_copy(SceneDocument& doc,
                                                   const std::filesystem::path& path) {
    if (!doc.loaded) return Error{"no scene is open"};
    // A copy in another folder reads its includes, images and models from
    // there: one whose paths are relative to this file's folder would be a
    // broken file, found only when it is opened again.
    const std::filesystem::path folder = folder_of(doc.path);
    const bool moved = folder_of(path) != folder;
    if (moved)
        if (const std::string* name = relative_file_name(doc.scene))
            return Error{"it names \"" + *name + "\" relative to " + folder.string() +
                         ": save the copy in that folder"};
    if (doc.draft) return Error{"the text has errors (see Diagnostics): fix them before saving"};
    SourceEditResult edit = apply_scene_edits(doc.text, doc.source, *doc.original, doc.scene);
    if (!edit.ok()) return Error{edit.error};
    if (!edit.files.empty() && path != doc.path)
        return Error{
            "values read from included files are saved in place (Save scene), "
            "not into a copy"};
    // Check before writing: the new texts must mean exactly the edited
    // scene. The included files are read as they would be written.
    ParseOptions options = document_options(doc, edit);
    if (moved) options.main_file = path.string();  // includes are read from the copy's folder
    ParseResult check = parse_scene(edit.text, options);
    if (moved && (!check.ok() || check.scene != doc.scene))
        return Error{"its includes are relative to " + folder.string() +
                     " and would not read the same scene from " + folder_of(path).string() +
                     ": save the copy in that folder"};
    if (!check.ok() || check.scene != doc.scene)
        return Error{
            "internal error: the edited text would not read back as the edited scene; "
            "the file was left as it was"};
    // The scene file is left alone when only values in included files
    // changed and it holds its text already, so that the status line names
    // only the files that changed.
    const Expected<std::string> on_disk = path == doc.path && edit.text == doc.text
                                              ? read_text_file(path)
                                              : Expected<std::string>(Error{"not read"});
    const bool write_main = !on_disk || *on_disk != edit.text;
    // Every file is checked before any is written: a save is whole or nothing.
    for (const EditedFile& edited : edit.files)
        if (Expected<void> ok = check_writable(edited.path); !ok) return ok.error();
    if (write_main)
        if (Expected<void> ok = check_writable(path); !ok) return ok.error();
    std::vector<std::string> names;
    if (write_main) names.push_back(path.string());
    for (const EditedFile& edited : edit.files) {
        if (Expected<void> written = write_text_atomically(edited.path, edited.text); !written)
            return Error{written.error().message};
        names.emplace_back(short_file_name(doc, doc.source.files[edited.file - 1].name));
    }
    if (write_main)
        if (Expected<void> written = write_text_atomically(path, edit.text); !written)
            return Error{written.error().message};
    doc.path = path;
    doc.diagnostics_path = path;
    doc.text = std::move(edit.text);
    doc.disk_text = doc.text;
    // Files named from now on are found where the copy is.
    if (moved) doc.scene.asset_folder = path.parent_path().string();
    doc.original = std::make_shared<const Scene>(doc.scene);
    // The scene itself did not change (no new revision: it is no edit), but
    // it now equals the original.
    doc.edited_at = {doc.revision, false};
    doc.source = std::move(check.source);
    if (moved) note_included_files(doc, doc.source);
    doc.diagnostics = check.diagnostics;
    doc.parse_diagnostics = std::move(check.diagnostics);
    doc.diagnostics_source = doc.text;
    doc.diagnostics_files = doc.source.files;
    note_diagnostics_changed(doc);
    doc.load_failed = false;
    ++doc.file_generation;
    return names;
}

bool document_is_blank(const SceneDocument& doc) {
    if (doc.path.empty() || doc.file_unread) return false;
    constexpr const char* blank = " \t\r\n";
    // Asked every frame: a held text is looked at where it is, not copied.
    if (const std::string* held = held_text(doc))
        return held->find_first_not_of(blank) == std::string::npos;
    // Panel edits write values into the base text or add them, never leaving
    // blank a text that was not: only an edited blank text is written out to
    // look (every frame a copy of the whole file, after any panel edit).
    if (doc.text.find_first_not_of(blank) != std::string::npos) return false;
    return document_text(doc).find_first_not_of(blank) == std::string::npos;
}

}  // namespace jt::view
