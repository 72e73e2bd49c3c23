// The document as one text, whichever way it is edited: the panels' structure
// edits, typing in the text editor and value edits share one undo history,
// and Save scene writes the text they leave, every byte outside the changed
// blocks as it was.

#include "model/document_edits.hpp"
#include "common/files.hpp"
#include "jtracer/model_file.hpp"
#include "jtracer/new_block.hpp"
#include "jtracer/parser.hpp"
#include "model/app_actions.hpp"
#include "viewer/model/model_loop.hpp"
#include "viewer/viewer_test_files.hpp"

#include <gtest/gtest.h>

namespace jt::view {
namespace {

using namespace jt::test;

std::string file_text(const std::filesystem::path& path) {
    return read_file(path);
}

Scene parsed(const std::string& text) {
    ParseResult r = parse_scene(text);
    EXPECT_TRUE(r.ok()) << text;
    return r.scene;
}

// Waits for the typed text's check and takes it in.
void settle_text(AppState& state) {
    state.check.checker.wait();
    for (int i = 0; i < 100 && !take_checked_text(state); ++i) state.check.checker.wait();
}

// An empty file opens as one to start a scene in: Start a scene gives it a
// size, a camera and a light (valid as it is), the panels then add to it, and
// undo goes back to the empty file.
TEST(DocumentEdits, AnEmptyFileStartsANewSceneThatThePanelsBuildOn) {
    const std::filesystem::path path = make_scratch_dir("document_edits_new") / "new.jts";
    write_file(path, "\n");
    AppState state(test_config());
    open_scene(state, path);
    EXPECT_FALSE(state.doc.loaded);
    EXPECT_TRUE(document_is_blank(state.doc));
    EXPECT_NE(state.message.find("new.jts is empty: Start a scene"), std::string::npos)
        << state.message;

    ASSERT_TRUE(start_new_scene(state)) << state.message;
    EXPECT_FALSE(document_is_blank(state.doc));
    ASSERT_TRUE(state.doc.loaded) << "at once: " << format_diagnostics(state.doc);
    EXPECT_NE(state.message.find("Started a scene: add objects"), std::string::npos);
    EXPECT_FALSE(state.doc.draft);
    EXPECT_EQ(format_diagnostics(state.doc), "") << "no error and no warning";
    Scene begun = new_scene();
    begun.settings.filename = "new.bmp";  // named after the file
    EXPECT_TRUE(state.doc.scene == begun);
    ASSERT_EQ(state.doc.scene.cameras.size(), 1u);
    EXPECT_EQ(state.doc.scene.cameras[0].aspect, 640.0 / 360.0);
    EXPECT_FALSE(start_new_scene(state)) << "only an empty file starts one";

    ASSERT_TRUE(add_object(state, ShapeKind::sphere));
    ASSERT_EQ(state.doc.scene.primitives.size(), 1u);
    ModelLoop loop;
    ASSERT_TRUE(loop.run_until_complete(state));
    EXPECT_TRUE(state.render.render_note.empty()) << state.render.render_note;
    ASSERT_TRUE(save_scene(state)) << state.message;
    EXPECT_TRUE(parsed(file_text(path)) == state.doc.scene);

    undo(state);
    undo(state);
    EXPECT_EQ(document_text(state.doc), "\n") << "back to the empty file";
    EXPECT_TRUE(document_is_blank(state.doc)) << "where a scene can be started again";
    redo(state);
    EXPECT_TRUE(state.doc.scene == begun);
}

TEST(DocumentEdits, AddDuplicateDeleteThenSaveGivesTheExpectedSceneAndKeepsOtherBytes) {
    const std::filesystem::path path = scene_copy("document_edits_save");
    const std::string before = file_text(path);
    AppState state(test_config());
    open_scene(state, path);
    ASSERT_TRUE(state.doc.loaded) << state.message;
    Scene expected = state.doc.scene;

    ASSERT_TRUE(add_object(state, ShapeKind::sphere)) << state.message;
    Scene view;
    view.cameras.push_back(expected.cameras[0]);  // the view shows "front"
    expected.primitives.push_back(new_primitive(ShapeKind::sphere, view));
    const int last = static_cast<int>(expected.primitives.size()) - 1;
    EXPECT_EQ(state.view.selection, (Selection{Selection::Kind::primitive, last}))
        << "the new sphere";
    ASSERT_TRUE(duplicate_block(state, {BlockKind::primitive, 1})) << state.message;
    expected.primitives.insert(expected.primitives.begin() + 2, expected.primitives[1]);
    EXPECT_EQ(state.view.selection, (Selection{Selection::Kind::primitive, 2})) << "the copy";
    ASSERT_TRUE(delete_block(state, {BlockKind::light, 0})) << state.message;
    expected.lights.clear();
    EXPECT_TRUE(state.doc.scene == expected);
    EXPECT_TRUE(has_unsaved_edits(state.doc));
    EXPECT_EQ(file_text(path), before) << "nothing is written before Save scene";

    ASSERT_TRUE(save_scene(state)) << state.message;
    const std::string after = file_text(path);
    EXPECT_TRUE(parsed(after) == expected) << after;
    EXPECT_FALSE(has_unsaved_edits(state.doc));
    // Everything up to the sphere's block, and the sphere's block itself, as it was.
    const std::size_t sphere_end = before.find("    point_light");
    EXPECT_EQ(after.substr(0, sphere_end), before.substr(0, sphere_end));
    // The copy follows it, the light's line is gone, the new sphere ends the scene block.
    const std::size_t sphere_begin = before.find("    sphere {");
    const std::string sphere = before.substr(sphere_begin, sphere_end - sphere_begin);
    EXPECT_EQ(after.substr(sphere_end, sphere.size()), sphere);
    EXPECT_EQ(after.find("point_light"), std::string::npos);
    EXPECT_EQ(after.substr(after.size() - 2), "}\n");
}

TEST(DocumentEdits, AddTriangleAndMeshThenSaveGivesTheExpectedSceneAndKeepsOtherBytes) {
    const std::filesystem::path path = scene_copy("document_edits_mesh");
    const std::filesystem::path model_file = path.parent_path() / "models" / "quad.obj";
    std::filesystem::create_directories(model_file.parent_path());
    write_file(model_file, "v 0 0 0\nv 4 0 0\nv 4 2 0\nv 0 2 0\nf 1 2 3 4\n");
    const std::string before = file_text(path);
    AppState state(test_config());
    open_scene(state, path);
    ASSERT_TRUE(state.doc.loaded) << state.message;
    Scene expected = state.doc.scene;
    Scene view;
    view.cameras.push_back(expected.cameras[0]);

    ASSERT_TRUE(add_object(state, ShapeKind::triangle)) << state.message;
    expected.primitives.push_back(new_primitive(ShapeKind::triangle, view));
    EXPECT_FALSE(add_mesh(state, "models/none.obj"));
    EXPECT_NE(state.message.find("none.obj"), std::string::npos) << state.message;
    // An absolute path inside the scene's folder is written relative to it.
    const int triangle = static_cast<int>(expected.primitives.size()) - 1;
    EXPECT_EQ(state.view.selection, (Selection{Selection::Kind::primitive, triangle}))
        << "the triangle";
    ASSERT_TRUE(add_mesh(state, model_file.string())) << state.message;
    EXPECT_EQ(state.view.selection, (Selection{Selection::Kind::primitive, triangle + 1}))
        << "the mesh";
    const Expected<Model> quad = read_model(model_file, path.parent_path());
    ASSERT_TRUE(quad);
    expected.primitives.push_back(new_mesh(view, "models/quad.obj", *quad));
    EXPECT_TRUE(state.doc.scene == expected);

    ASSERT_TRUE(save_scene(state)) << state.message;
    const std::string after = file_text(path);
    const ParseResult reread = parse_scene(after);
    ASSERT_TRUE(reread.ok()) << after;
    EXPECT_TRUE(reread.scene == expected) << after;
    // The two new blocks go with the objects, after the last one (before the
    // light); every byte before and after them stays.
    const std::size_t objects_end = before.find("    point_light");
    ASSERT_NE(objects_end, std::string::npos);
    EXPECT_EQ(after.substr(0, objects_end), before.substr(0, objects_end));
    EXPECT_EQ(after.substr(after.size() - (before.size() - objects_end)),
              before.substr(objects_end));
    EXPECT_NE(after.find("file: \"models/quad.obj\""), std::string::npos) << after;
    // And it renders: the model loads from the scene's folder.
    ModelLoop model;
    ASSERT_TRUE(model.run_until_complete(state));
    EXPECT_TRUE(state.render.render_note.empty()) << state.render.render_note;
}

TEST(DocumentEdits, ATextErrorKeepsTheImageAndIsListedAtItsLineTheFixRendersAgain) {
    const std::filesystem::path path = scene_copy("document_edits_typing");
    AppState state(test_config());
    open_scene(state, path);
    ModelLoop loop;
    ASSERT_TRUE(loop.run_until_complete(state));
    const Image8 good = state.render.display;
    const Scene good_scene = state.doc.scene;

    // Line 34 is the sphere's "radius: 1;": break it.
    std::string text = state.doc.text;
    const std::size_t at = text.find("radius: 1;");
    text.replace(at, 10, "radius: 1 x;");
    type_text(state, text);
    EXPECT_TRUE(state.doc.draft);
    settle_text(state);
    ASSERT_TRUE(state.doc.draft) << "a text with errors stays a draft";
    EXPECT_TRUE(state.doc.scene == good_scene);
    // The first error is where the parser stopped: just past the value, 34:18.
    const Diagnostic* first = nullptr;
    for (const Diagnostic& d : state.doc.diagnostics)
        if (d.severity == Severity::error && !first) first = &d;
    ASSERT_TRUE(first);
    EXPECT_EQ(first->pos.line, 34);
    EXPECT_EQ(first->pos.column, 18);
    EXPECT_NE(first->message.find("expected ';'"), std::string::npos) << first->message;
    EXPECT_EQ(state.doc.diagnostics_source, text) << "they point into the typed text";
    for (int i = 0; i < 5; ++i) loop.frame(state);
    EXPECT_EQ(state.render.display, good) << "the last good image stays";
    EXPECT_FALSE(save_scene(state)) << "a text with errors is not saved";

    // The fix: a bigger sphere, rendered again.
    text.replace(text.find("radius: 1 x;"), 12, "radius: 1.4;");
    type_text(state, text);
    settle_text(state);
    EXPECT_FALSE(state.doc.draft);
    EXPECT_EQ(shape_as<Sphere>(state.doc.scene.primitives[1].shape).radius, 1.4);
    ASSERT_TRUE(loop.run_until_complete(state));
    EXPECT_NE(state.render.display, good);
    ASSERT_TRUE(save_scene(state)) << state.message;
    EXPECT_EQ(file_text(path), text);
}

// A typo fixed back: the text parses to the scene the image shows (the
// previous text, or one that differs in a comment only), and the render
// goes on rather than starting again from the first preview. With a panel
// edit made before the typing too: the text holds it written in.
TEST(DocumentEdits, ATypoFixedBackToTheShownSceneKeepsTheRender) {
    const std::filesystem::path path = scene_copy("document_edits_typo_back");
    AppState state(test_config());
    open_scene(state, path);
    ModelLoop loop;
    edit_scene(state, [](Scene& s) { s.settings.width = 60; });
    ASSERT_TRUE(loop.run_until_complete(state));
    const Image8 good = state.render.display;
    const Scene shown = state.doc.scene;
    const std::uint64_t jobs = state.render.renderer.jobs_started();

    const std::string before = document_text(state.doc);
    for (const std::string& fixed : {before, before + "# a comment\n"}) {
        std::string broken = fixed;
        broken.replace(broken.find("radius: 1;"), 10, "radius: 1 x;");
        type_text(state, broken);
        settle_text(state);
        ASSERT_TRUE(state.doc.draft) << "a text with errors stays a draft";
        loop.frame(state);
        type_text(state, fixed);
        settle_text(state);
        ASSERT_FALSE(state.doc.draft) << format_diagnostics(state.doc);
        EXPECT_TRUE(state.doc.scene == shown);
        for (int i = 0; i < 3; ++i) loop.frame(state);
        EXPECT_EQ(state.render.renderer.jobs_started(), jobs) << "no render started again";
        EXPECT_TRUE(render_complete(state.render));
        EXPECT_EQ(state.render.display, good);
        EXPECT_EQ(document_text(state.doc), fixed);
        EXPECT_FALSE(scene_edited(state.doc)) << "the width is in the text now";
        EXPECT_TRUE(has_unsaved_edits(state.doc));
    }
    // Typing with errors undone: the same.
    std::string broken = document_text(state.doc);
    broken.replace(broken.find("radius: 1;"), 10, "radius: 1 x;");
    type_text(state, broken);
    settle_text(state);
    ASSERT_TRUE(state.doc.draft);
    loop.frame(state);
    undo(state);
    EXPECT_FALSE(state.doc.draft);
    for (int i = 0; i < 3; ++i) loop.frame(state);
    EXPECT_EQ(state.render.renderer.jobs_started(), jobs) << "undone: no render started again";
    EXPECT_TRUE(render_complete(state.render));
    // A fix to another scene renders it.
    std::string bigger = before;
    bigger.replace(bigger.find("radius: 1;"), 10, "radius: 1.4;");
    type_text(state, bigger);
    settle_text(state);
    ASSERT_TRUE(loop.run_until_complete(state));
    EXPECT_GT(state.render.renderer.jobs_started(), jobs);
    EXPECT_NE(state.render.display, good);
}

// Found in the window: Ctrl+Z pressed once too often (the Undo button
// greyed out) started the finished render again from its first preview. An
// undo or redo with nothing to step to changes nothing, the render neither.
TEST(DocumentEdits, UndoOrRedoWithNothingToStepToKeepsTheRender) {
    AppState state(test_config());
    open_scene(state, kScene);
    ModelLoop loop;
    ASSERT_TRUE(loop.run_until_complete(state));
    const std::uint64_t jobs = state.render.renderer.jobs_started();
    const std::uint64_t revision = state.doc.revision;
    ASSERT_FALSE(state.history.undo.can_undo());
    for (int i = 0; i < 2; ++i) {
        undo(state);
        redo(state);
        for (int f = 0; f < 3; ++f) loop.frame(state);
    }
    EXPECT_EQ(state.doc.revision, revision);
    EXPECT_EQ(state.render.renderer.jobs_started(), jobs) << "no render started again";
    EXPECT_TRUE(render_complete(state.render));
    EXPECT_FALSE(has_unsaved_edits(state.doc));
}

// The selection is an index: a Delete button in a panel must not leave it on
// the object that moved into the deleted one's place, nor on the one after
// the selected object when an object before it goes.
TEST(DocumentEdits, DeletingABlockNeverLeavesTheSelectionOnAnotherObject) {
    const std::filesystem::path path = scene_copy("document_edits_delete_selection");
    AppState state(test_config());
    open_scene(state, path);
    ASSERT_EQ(state.doc.scene.primitives.size(), 2u);  // a plane, then a sphere
    const Selection plane{Selection::Kind::primitive, 0}, sphere{Selection::Kind::primitive, 1};

    state.view.selection = plane;
    ASSERT_TRUE(delete_block(state, {BlockKind::primitive, 0})) << state.message;
    EXPECT_EQ(state.view.selection, Selection{}) << "not the sphere, now the first object";

    undo(state);
    state.view.selection = sphere;
    ASSERT_TRUE(delete_block(state, {BlockKind::primitive, 0})) << state.message;
    EXPECT_EQ(state.view.selection, (Selection{Selection::Kind::primitive, 0})) << "the sphere";
    ASSERT_TRUE(delete_block(state, {BlockKind::light, 0})) << state.message;
    EXPECT_EQ(state.view.selection, (Selection{Selection::Kind::primitive, 0}))
        << "a light's deletion leaves an object's selection alone";
    std::filesystem::remove_all(path.parent_path());
}

TEST(DocumentEdits, OneUndoHistoryAcrossPanelStructureAndTextEdits) {
    const std::filesystem::path path = scene_copy("document_edits_undo");
    AppState state(test_config());
    open_scene(state, path);
    const std::string t0 = document_text(state.doc);
    // A value edit, as a panel makes it.
    edit_scene(state, [](Scene& s) { shape_as<Sphere>(s.primitives[1].shape).radius = 0.5; });
    const std::string t1 = document_text(state.doc);
    ASSERT_NE(t1, t0);
    ASSERT_TRUE(add_light(state));
    EXPECT_EQ(
        state.view.selection,
        (Selection{Selection::Kind::light, static_cast<int>(state.doc.scene.lights.size()) - 1}))
        << "the new light";
    const std::string t2 = document_text(state.doc);
    std::string typed = t2;
    typed.replace(typed.find("fov: 40;"), 8, "fov: 30;");
    type_text(state, typed);
    settle_text(state);
    ASSERT_FALSE(state.doc.draft);
    const std::string t3 = document_text(state.doc);
    ASSERT_EQ(t3, typed);
    ASSERT_TRUE(delete_block(state, {BlockKind::primitive, 0}));
    const std::string t4 = document_text(state.doc);

    const std::vector<std::string> history{t0, t1, t2, t3, t4};
    for (int i = 3; i >= 0; --i) {
        undo(state);
        EXPECT_EQ(document_text(state.doc), history[static_cast<std::size_t>(i)])
            << "undo to " << i;
        EXPECT_TRUE(state.doc.scene == parsed(history[static_cast<std::size_t>(i)]));
    }
    EXPECT_FALSE(state.history.undo.can_undo());
    EXPECT_FALSE(has_unsaved_edits(state.doc)) << "back to the file";
    for (std::size_t i = 1; i < history.size(); ++i) {
        redo(state);
        EXPECT_EQ(document_text(state.doc), history[i]) << "redo to " << i;
    }
    ASSERT_TRUE(save_scene(state));
    EXPECT_EQ(file_text(path), t4);
}

TEST(DocumentEdits, TransformOpsCamerasAndRefusals) {
    const std::filesystem::path path = scene_copy("document_edits_more");
    AppState state(test_config());
    open_scene(state, path);
    ASSERT_TRUE(add_transform_op(state, 1, TransformKind::translate));
    ASSERT_TRUE(add_transform_op(state, 1, TransformKind::scale));
    ASSERT_EQ(state.doc.scene.primitives[1].transforms.size(), 2u);
    ASSERT_TRUE(move_transform_op(state, 1, 1, 0));
    EXPECT_EQ(state.doc.scene.primitives[1].transforms[0].kind, TransformKind::scale);
    ASSERT_TRUE(remove_transform_op(state, 1, 1));
    ASSERT_TRUE(add_material_block(state, 0) == false) << "the plane has one already";
    ASSERT_TRUE(rename_camera(state, 0, "main"));
    EXPECT_EQ(state.doc.scene.settings.active_camera, "main");
    EXPECT_FALSE(rename_camera(state, 1, "main"));
    EXPECT_NE(state.message.find("already named"), std::string::npos) << state.message;
    ASSERT_TRUE(add_camera(state));
    EXPECT_EQ(state.doc.scene.cameras.size(), 3u);
    EXPECT_EQ(selected_camera(state.view, state.doc.scene), 2);
    ASSERT_TRUE(delete_block(state, {BlockKind::camera, 0}));
    ASSERT_TRUE(delete_block(state, {BlockKind::camera, 0}));
    EXPECT_FALSE(delete_block(state, {BlockKind::camera, 0}));
    EXPECT_NE(state.message.find("only camera"), std::string::npos) << state.message;
    edit_scene(state, [](Scene& s) {
        s.settings.width = 200;
        s.settings.height = 100;
    });
    ASSERT_TRUE(set_aspect_from_image(state, 0));
    EXPECT_EQ(state.doc.scene.cameras[0].aspect, 2.0);
    ASSERT_TRUE(save_scene(state));
    EXPECT_TRUE(parsed(file_text(path)) == state.doc.scene);
}

}  // namespace
}  // namespace jt::view

namespace jt::view {
namespace {

using namespace jt::test;

// From an empty file: nothing loads, the text typed in makes the scene, the
// panels' commands build on it and Save scene writes it.
TEST(DocumentEdits, AnEmptyFileBecomesASceneThroughTheText) {
    const std::filesystem::path path = make_scratch_dir("document_edits_empty") / "new.jts";
    write_file(path, "");
    AppState state(test_config());
    open_scene(state, path);
    EXPECT_FALSE(state.doc.loaded) << "no camera: nothing to show";
    EXPECT_EQ(document_text(state.doc), "");
    const std::string text =
        "render_settings { width: 40; height: 30; }\n"
        "cameras { perspective_camera { position: <0, 1, 5>; } }\n";
    type_text(state, text);
    EXPECT_TRUE(has_unsaved_edits(state.doc)) << "typed text is never dropped unasked";
    state.check.checker.wait();
    ASSERT_TRUE(take_checked_text(state));
    ASSERT_TRUE(state.doc.loaded) << state.message;
    ASSERT_TRUE(add_object(state, ShapeKind::sphere)) << state.message;
    ASSERT_TRUE(add_light(state)) << state.message;
    ASSERT_TRUE(set_aspect_from_image(state, 0)) << state.message;
    ModelLoop loop;
    ASSERT_TRUE(loop.run_until_complete(state));
    ASSERT_TRUE(save_scene(state)) << state.message;
    const Scene saved = parse_scene(read_file(path)).scene;
    EXPECT_TRUE(saved == state.doc.scene);
    EXPECT_EQ(saved.primitives.size(), 1u);
    EXPECT_EQ(saved.lights.size(), 1u);
    const std::size_t first_line = text.find('\n') + 1;  // render_settings: untouched
    EXPECT_EQ(read_file(path).substr(0, first_line), text.substr(0, first_line));
}

// The title's "*" is remembered between changes (has_unsaved_edits): every
// way the text or the file's text changes must be seen, back to "saved" too.
TEST(DocumentEdits, UnsavedFollowsTypingUndoRedoAndSaveAs) {
    const std::filesystem::path path = scene_copy("document_edits_unsaved");
    AppState state(test_config());
    open_scene(state, path);
    ASSERT_TRUE(state.doc.loaded) << state.message;
    EXPECT_FALSE(has_unsaved_edits(state.doc));
    const std::string saved = state.doc.text;

    type_text(state, saved + "# typed\n");
    settle_text(state);
    ASSERT_FALSE(state.doc.draft);
    EXPECT_TRUE(has_unsaved_edits(state.doc));
    type_text(state, saved);  // typed back to the file's text
    settle_text(state);
    EXPECT_FALSE(has_unsaved_edits(state.doc));

    type_text(state, saved + "# again\n");
    settle_text(state);
    EXPECT_TRUE(has_unsaved_edits(state.doc));
    undo(state);
    ASSERT_EQ(state.doc.text, saved);
    EXPECT_FALSE(has_unsaved_edits(state.doc)) << "undone back to the saved text";
    redo(state);
    EXPECT_TRUE(has_unsaved_edits(state.doc));

    const std::filesystem::path other = path.parent_path() / "other.jts";
    ASSERT_TRUE(save_scene_as(state, other, true)) << state.message;
    EXPECT_FALSE(has_unsaved_edits(state.doc)) << "saved, under another name";
    edit_scene(state, [](Scene& s) { shape_as<Sphere>(s.primitives[1].shape).radius = 0.5; });
    EXPECT_TRUE(has_unsaved_edits(state.doc));
    undo(state);
    EXPECT_FALSE(has_unsaved_edits(state.doc));
}

}  // namespace
}  // namespace jt::view
