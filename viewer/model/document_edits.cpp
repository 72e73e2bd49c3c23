#include "model/document_edits.hpp"

#include "model/app_actions.hpp"
#include "model/field_sources.hpp"

#include "jtracer/block_edit.hpp"
#include "jtracer/camera_edit.hpp"
#include "jtracer/model_cache.hpp"
#include "jtracer/new_block.hpp"
#include "jtracer/parser.hpp"
#include "jtracer/schema.hpp"
#include "jtracer/serializer.hpp"
#include "jtracer/texture.hpp"
#include "jtracer/transform_edit.hpp"
#include "jtracer/value_text.hpp"

#include <chrono>
#include <filesystem>

namespace jt::view {

namespace {

// The scene as the view sees it: one camera, the one the image shows.
Scene viewed_scene(const AppState& state) {
    Scene view;
    if (state.view.free_camera_active)
        view.cameras.push_back(camera_from(state.view.free_camera, "view"));
    else if (const int selected = selected_camera(state.view, state.doc.scene); selected >= 0)
        view.cameras.push_back(state.doc.scene.cameras[static_cast<std::size_t>(selected)]);
    return view;
}

std::string kind_name(TransformKind kind) {
    return std::string(transform_op(kind).property.name);
}

}  // namespace

Expected<void> rewrite_text(AppState& state,
                            const std::function<Expected<std::string>(const SceneText&)>& edit) {
    SceneDocument& doc = state.doc;
    if (!doc.loaded) return Error{"No scene is open"};
    if (doc.draft) return Error{"The text has errors: fix them in the text editor first"};
    const Scene before = doc.scene;
    Expected<std::string> edited = Error{""};
    if (!scene_edited(doc)) {
        edited = edit(SceneText{doc.text, *doc.original, doc.source});
    } else {
        // The panels' edits become text first, so that the edit starts from what is shown.
        const std::string text = document_text(doc);
        const ParseResult parsed = parse_document_text(doc, text);
        edited = edit(SceneText{text, parsed.scene, parsed.source});
    }
    if (!edited) return Error{"Not done: " + edited.error().message};
    if (const Expected<void> taken = replace_text(doc, std::move(*edited)); !taken)
        return Error{"Not done: " + taken.error().message};
    keep_camera_selection(state.view, state.doc.scene, before);
    state.history.edit_base.reset();
    state.history.typing = false;
    note_command_edit(state.history, state.doc);
    return {};
}

bool edit_text_structure(AppState& state,
                         const std::function<Expected<std::string>(const SceneText&)>& edit,
                         const std::string& done) {
    const DocumentVersion before = version_of(state.doc);
    if (const Expected<void> rewritten = rewrite_text(state, edit); !rewritten) {
        state.message = rewritten.error().message;
        return false;
    }
    state.history.undo.record(before);
    state.message = done + " (Save scene to keep it)";
    return true;
}

namespace {

// What was added last (it becomes the scene's last primitive or light) is
// selected, to be moved or changed next.
void select_last(AppState& state, Selection::Kind kind) {
    const std::size_t count = kind == Selection::Kind::light ? state.doc.scene.lights.size()
                                                             : state.doc.scene.primitives.size();
    if (count == 0) return;
    state.view.selection = {kind, static_cast<int>(count) - 1};
    state.view.reveal_selection = true;
}

}  // namespace

bool add_object(AppState& state, ShapeKind kind) {
    const Primitive added = new_primitive(kind, viewed_scene(state));
    if (!edit_text_structure(
            state, [&](const SceneText& s) { return add_primitive(s, added); },
            "Added a " + std::string(keyword_of(kind))))
        return false;
    select_last(state, Selection::Kind::primitive);
    return true;
}

namespace {

// `file` as a mesh of the scene names it: relative to the scene's folder.
std::string scene_file_name(const Scene& scene, const std::string& file) {
    const std::filesystem::path path(file);
    if (!path.is_absolute() || scene.asset_folder.empty()) return file;
    std::error_code error;
    const std::filesystem::path folder = std::filesystem::absolute(scene.asset_folder, error);
    const std::filesystem::path inside = path.lexically_normal().lexically_relative(folder);
    if (error || inside.empty() || *inside.begin() == "..") return file;
    return inside.generic_string();
}

}  // namespace

bool add_mesh(AppState& state, const std::string& file) {
    if (file.empty()) {
        state.message = "Type the model file's path first";
        return false;
    }
    const std::string name = scene_file_name(state.doc.scene, file);
    const auto model =
        shared_model(asset_path(state.doc.scene, name), state.doc.scene.asset_folder);
    if (!model) {
        state.message = "Not added: " + model.error().message;
        return false;
    }
    if ((*model)->triangles.empty()) {
        state.message = "Not added: '" + name + "' " + model_warnings(**model).back();
        return false;
    }
    const Primitive added = new_mesh(viewed_scene(state), name, **model);
    if (!edit_text_structure(
            state, [&](const SceneText& s) { return add_primitive(s, added); },
            "Added a mesh of " + name))
        return false;
    select_last(state, Selection::Kind::primitive);
    return true;
}

bool add_light(AppState& state) {
    const PointLight added = new_light(viewed_scene(state));
    if (!edit_text_structure(
            state, [&](const SceneText& s) { return jt::add_light(s, added); },
            "Added a point light"))
        return false;
    select_last(state, Selection::Kind::light);
    return true;
}

bool duplicate_block(AppState& state, BlockRef block) {
    const std::string name = block_name(state.doc.scene, block);
    if (!edit_text_structure(
            state, [&](const SceneText& s) { return jt::duplicate_block(s, block); },
            "Duplicated " + name))
        return false;
    // The copy comes right after the original: it is selected, to be moved or changed.
    if (block.kind != BlockKind::camera) {
        state.view.selection = {
            block.kind == BlockKind::light ? Selection::Kind::light : Selection::Kind::primitive,
            static_cast<int>(block.index) + 1};
        state.view.reveal_selection = true;
    }
    return true;
}

std::string why_not_rewrite_block(const SceneDocument& doc, BlockRef block) {
    const EditedBlock::Kind kind = block.kind == BlockKind::camera ? EditedBlock::Kind::camera
                                   : block.kind == BlockKind::primitive
                                       ? EditedBlock::Kind::primitive
                                       : EditedBlock::Kind::light;
    const BlockSource* source = block_source(doc, {kind, block.index});
    if (!source || source->keyword_span.pos.file == 0) return {};
    const std::uint32_t file = source->keyword_span.pos.file;
    const std::string name =
        file <= doc.source.files.size()
            ? std::string(short_file_name(doc, doc.source.files[file - 1].name))
            : std::string("a file the scene includes");
    return "Written in " + name +
           ", which the scene includes: change its blocks in that file (the text editor, T, "
           "opens it); its values are edited here too";
}

bool delete_block(AppState& state, BlockRef block) {
    const std::string name = block_name(state.doc.scene, block);
    if (!edit_text_structure(
            state, [&](const SceneText& s) { return jt::delete_block(s, block); },
            "Deleted " + name))
        return false;
    // The selection is an index: it goes with the deleted block, and follows
    // its object when one before it goes.
    Selection& selection = state.view.selection;
    const Selection::Kind kind = block.kind == BlockKind::light       ? Selection::Kind::light
                                 : block.kind == BlockKind::primitive ? Selection::Kind::primitive
                                                                      : Selection::Kind::none;
    if (kind != Selection::Kind::none && selection.kind == kind) {
        const auto deleted = static_cast<int>(block.index);
        if (selection.index == deleted)
            selection = {};
        else if (selection.index > deleted)
            --selection.index;
    }
    return true;
}

bool add_material_block(AppState& state, std::size_t primitive) {
    return edit_text_structure(
        state,
        [&](const SceneText& s) -> Expected<std::string> {
            if (primitive >= s.scene.primitives.size())
                return Error{"there is no object " + std::to_string(primitive + 1)};
            return jt::add_material_block(s, primitive, s.scene.primitives[primitive].material);
        },
        "Added a material block");
}

bool add_transform_block(AppState& state, std::size_t primitive) {
    return edit_text_structure(
        state, [&](const SceneText& s) { return jt::add_transform_block(s, primitive); },
        "Added a transform block");
}

bool add_transform_op(AppState& state, std::size_t primitive, TransformKind kind) {
    TransformOp op;
    op.kind = kind;
    if (kind == TransformKind::scale) op.vector = Vec3{1.0};
    return edit_text_structure(
        state,
        [&](const SceneText& s) {
            const std::size_t end = primitive < s.scene.primitives.size()
                                        ? s.scene.primitives[primitive].transforms.size()
                                        : 0;
            return jt::add_transform_op(s, primitive, end, op);
        },
        "Added " + kind_name(kind));
}

bool move_transform_op(AppState& state, std::size_t primitive, std::size_t from, std::size_t to) {
    return edit_text_structure(
        state, [&](const SceneText& s) { return jt::move_transform_op(s, primitive, from, to); },
        "Moved transform operation " + std::to_string(from + 1) + " to " + std::to_string(to + 1));
}

bool remove_transform_op(AppState& state, std::size_t primitive, std::size_t index) {
    return edit_text_structure(
        state, [&](const SceneText& s) { return jt::remove_transform_op(s, primitive, index); },
        "Removed transform operation " + std::to_string(index + 1));
}

bool add_camera(AppState& state) {
    const Scene& scene = state.doc.scene;
    const int selected = selected_camera(state.view, state.doc.scene);
    Camera camera;
    if (state.view.free_camera_active) {
        camera = camera_from(state.view.free_camera, "");
        camera.position = ui_rounded(camera.position);
        camera.look_at = ui_rounded(camera.look_at);
    } else if (selected >= 0) {
        camera = scene.cameras[static_cast<std::size_t>(selected)];
    }
    camera.name = unique_camera_name(
        scene, state.view.free_camera_active || camera.name.empty() ? "view" : camera.name);
    const bool added = edit_text_structure(
        state, [&](const SceneText& s) { return jt::add_camera(s, camera); },
        "Added camera \"" + camera.name + "\"");
    if (added) {
        state.view.camera_index = static_cast<int>(state.doc.scene.cameras.size()) - 1;
        state.view.free_camera_active = false;
    }
    return added;
}

bool rename_camera(AppState& state, std::size_t camera, const std::string& name) {
    return edit_text_structure(
        state, [&](const SceneText& s) { return jt::rename_camera(s, camera, name); },
        "Renamed the camera to \"" + name + "\"");
}

bool set_aspect_from_image(AppState& state, std::size_t camera) {
    return edit_text_structure(
        state, [&](const SceneText& s) { return jt::set_aspect_from_image(s, camera); },
        "Set the aspect from the image size");
}

void type_text(AppState& state, std::string text) {
    SceneDocument& doc = state.doc;
    if (!doc.loaded && doc.path.empty()) return;
    if (!state.history.typing) {
        state.history.undo.record(version_of(doc));
        state.history.typing = true;
    }
    state.history.edit_base.reset();
    doc.draft = text;
    ++state.check.draft_id;
    state.check.checker.check(state.check.draft_id, std::move(text), doc.path, kTypingPause,
                              doc.options);
}

namespace {

// The history starts again from the files as they are on disk (one undo
// step back to them, when they read without errors): its steps held
// scenes read from older texts of the included files.
void forget_history_before_files_changed(AppState& state) {
    SceneDocument& doc = state.doc;
    state.history.undo.clear();
    state.history.edit_base.reset();
    if (doc.draft || doc.text == doc.disk_text) return;
    ParseResult on_disk = parse_document_text(doc, doc.disk_text);
    if (!on_disk.ok()) return;
    on_disk.scene.asset_folder = doc.original->asset_folder;
    state.history.undo.record(
        {doc.disk_text, std::move(on_disk.scene), std::nullopt, doc.options.clock});
}

// The draft's check, taken in: a text without errors becomes the document.
void take_in(AppState& state, CheckedText checked) {
    SceneDocument& doc = state.doc;
    state.history.typing = false;  // the pause ended: the next keystroke is a new undo step
    doc.diagnostics = checked.diagnostics;
    doc.diagnostics_source = checked.text;
    doc.diagnostics_path = doc.path;
    doc.diagnostics_files = checked.parsed.source.files;
    note_diagnostics_changed(doc);
    state.check.draft_reads.clear();
    if (!checked.ok) {
        for (const SourceFile& file : checked.parsed.source.files)
            state.check.draft_reads.push_back(file.path);
        bool appeared = false;  // since the check could not read it
        for (const std::string& file : checked.parsed.source.unread_includes) {
            state.check.draft_reads.push_back(file);
            std::error_code ec;
            appeared = appeared || std::filesystem::exists(file, ec);
        }
        // Watched from now on (reload_if_changed); one made meanwhile is checked for now.
        state.files.draft_watcher.watch(state.check.draft_reads);
        if (appeared)
            state.check.checker.check(++state.check.draft_id, checked.text, doc.path,
                                      std::chrono::milliseconds(0), doc.options);
        state.message =
            doc.loaded ? "The text has errors (see Diagnostics): the image is of the last good text"
                       : "The text has errors (see Diagnostics): no image until they are mended";
        return;
    }
    const Scene before = doc.scene;
    const std::uint64_t revision_before = doc.revision;
    if (checked.clock != doc.options.clock) {
        // The clock moved while the text was checked: its values are taken at this one.
        ParseResult now = parse_document_text(doc, checked.text);
        now.scene.asset_folder = checked.parsed.scene.asset_folder;
        if (now.ok()) checked.parsed = std::move(now);
    }
    // An included file that changed on disk since the document read it: the
    // undo history's scenes hold its objects as they were, and stepping back
    // would bring them back as edits that Save writes over the file's new
    // text. As after a reload, the history starts again here.
    const std::string changed = changed_include(doc, checked.parsed.source.files);
    take_text(doc, std::move(checked.text), std::move(checked.parsed));
    if (!changed.empty()) forget_history_before_files_changed(state);
    doc.loaded = true;  // a file that never loaded (empty, broken) now has a scene
    keep_camera_selection(state.view, state.doc.scene, before);
    note_command_edit(state.history, state.doc);
    state.check.checked_revision = doc.revision;  // the diagnostics describe it already
    // A typo fixed back: the image shown is of this very scene.
    if (doc.scene == before) keep_render_for(state.render, revision_before, doc.revision);
    state.message = changed.empty() ? "The text parses: the image follows it"
                                    : changed +
                                          " changed on disk: read again with your unsaved edits; "
                                          "Undo goes back to the files as they are on disk";
}

}  // namespace

bool take_checked_text(AppState& state) {
    std::optional<CheckedText> checked = state.check.checker.take();
    if (!checked) return false;
    if (checked->id != state.check.draft_id || !state.doc.draft) return true;  // overtaken
    take_in(state, std::move(*checked));
    return true;
}

bool start_new_scene(AppState& state) {
    if (!document_is_blank(state.doc)) {
        state.message = "A new scene starts only in an empty file: open or create one";
        return false;
    }
    // As if typed, but taken in at once: the text is short and known to be sound.
    Scene scene = new_scene();
    // The image is named after the scene file, as jtracer-cli's -o would be.
    const std::string image = state.doc.path.stem().string() + ".bmp";
    if (state.doc.path.has_stem() && is_writable_string(image)) scene.settings.filename = image;
    std::string text = serialize_scene(scene);
    state.history.undo.record(version_of(state.doc));
    state.history.edit_base.reset();
    state.doc.draft = text;
    ++state.check.draft_id;
    take_in(state,
            check_text(state.check.draft_id, std::move(text), state.doc.path, state.doc.options));
    state.message = "Started a scene: add objects in the Objects panel (Save scene to keep it)";
    return true;
}

}  // namespace jt::view
