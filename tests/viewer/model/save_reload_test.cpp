// The viewer and its scene file on disk, through the model's frames: no
// save or reload ever loses the user's edits or someone else's newer text
// unasked, and a file that is deleted, cut short, garbage or huge never costs
// the last good image, the UI's frames or a crash.

#include "common/files.hpp"
#include "jtracer/diagnostics.hpp"
#include "jtracer/parser.hpp"
#include "model/app_actions.hpp"
#include "model/document_edits.hpp"
#include "model/picking.hpp"
#include "viewer/model/model_loop.hpp"
#include "viewer/viewer_test_files.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <thread>

namespace jt::view {
namespace {

namespace fs = std::filesystem;
using namespace jt::test;

// Written beside and renamed over, as editors save: never seen half-written.
void save_as_editor(const fs::path& path, const std::string& text) {
    const fs::path temp = fs::path(path).concat(".tmp");
    write_file(temp, text);
    fs::rename(temp, path);
}

std::string replaced(std::string text, std::string_view from, std::string_view to) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

const std::string kOriginal = read_file(kScene);
// What another program writes while the viewer has the file open.
const std::string kTheirs =
    replaced(kOriginal, "point_light { position: <3, 5, 4>; intensity: <1, 1, 1>; }",
             "point_light { position: <3, 5, 4>; intensity: <0.5, 0.5, 0.5>; }");
const Colour kMyPigment(0.25, 0.5, 0.75);
const std::string kMine =
    replaced(kOriginal, "pigment: <0.9, 0.2, 0.1>;", "pigment: <0.25, 0.5, 0.75>;");

class ViewerFiles : public ::testing::Test {
  protected:
    void SetUp() override {
        file = scene_copy(::testing::UnitTest::GetInstance()->current_test_info()->name());
        open_scene(state, file);
        ASSERT_TRUE(model.run_until_complete(state, kTimeout));
    }
    void TearDown() override { fs::remove_all(file.parent_path()); }

    void edit_pigment() {
        edit_scene(state, [](Scene& s) { s.primitives[1].material.pigment = kMyPigment; });
    }
    // The file changes under the viewer, which notices and reloads.
    void they_save(const std::string& text) {
        save_as_editor(file, text);
        ASSERT_TRUE(model.run_until_loaded(state));
    }

    // Frames until `done` (or the timeout).
    bool run_until(const std::function<bool()>& done) {
        const auto until = std::chrono::steady_clock::now() + kTimeout;
        while (!done()) {
            if (std::chrono::steady_clock::now() > until) return false;
            model.frame(state);
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
        }
        model.frame(state);
        return true;
    }

    ModelLoop model;
    AppState state{test_config()};
    fs::path file;
};

TEST_F(ViewerFiles, ReloadWithUnsavedEditsKeepsThemUntilTheUserChooses) {
    edit_pigment();
    they_save(kTheirs);
    ASSERT_TRUE(state.files.pending_reload.has_value()) << state.message;
    EXPECT_EQ(state.doc.scene.primitives[1].material.pigment, kMyPigment) << "edits kept";
    EXPECT_TRUE(has_unsaved_edits(state.doc));
    EXPECT_TRUE(state.files.reapply_problem.empty()) << state.files.reapply_problem;

    resolve_reload(state, ReloadChoice::keep_edits);
    EXPECT_FALSE(state.files.pending_reload.has_value());
    EXPECT_EQ(state.doc.scene.primitives[1].material.pigment, kMyPigment);
    EXPECT_EQ(read_file(file), kTheirs) << "nothing written yet";
}

// R pressed just after opening another file, or the open file changing on
// disk meanwhile, asks to reload the file the open replaces: the open must
// still happen, not be overtaken and dropped.
TEST_F(ViewerFiles, AReloadDoesNotOvertakeAnOpenUnderWay) {
    const fs::path other = scene_copy("reload_overtakes_open");
    request_open(state, other);
    reload_scene(state);
    state.files.loader.wait();
    take_finished_load(state);
    EXPECT_EQ(state.doc.path, other) << state.message;
    fs::remove_all(other.parent_path());
}

// A selection is an index into the scene: in another file it would name an
// object the user never picked, tint and outline it and take Delete or
// Alt+drag to it. A reload of the same file keeps it.
TEST_F(ViewerFiles, OpeningAnotherFileClearsTheSelectionAndTheSaveAsPath) {
    const Selection picked{Selection::Kind::primitive, 1};
    state.view.selection = picked;
    state.fields.save_scene_path = "scene-variant.jts";
    reload_scene(state);
    state.files.loader.wait();
    take_finished_load(state);
    EXPECT_EQ(current_selection(state.view, state.doc.scene), picked) << "kept on reload";
    EXPECT_EQ(state.fields.save_scene_path, "scene-variant.jts") << "kept on reload";

    const fs::path other = scene_copy("open_clears_selection");
    request_open(state, other);
    state.files.loader.wait();
    take_finished_load(state);
    ASSERT_EQ(state.doc.path, other) << state.message;
    EXPECT_EQ(current_selection(state.view, state.doc.scene), Selection{});
    EXPECT_EQ(state.fields.save_scene_path, "") << "a name typed for the file before";
    fs::remove_all(other.parent_path());
}

// An open of another file that fails leaves the file shown as it was: its
// scene, the files it reads and their watches, its own checks. The
// diagnostics are the other file's, and the message says which file is
// still shown, not that a last good scene waits for a fix.
TEST_F(ViewerFiles, AFailedOpenOfAnotherFileLeavesTheShownFileAsItIs) {
    const fs::path other = file.parent_path() / "other.jts";
    write_file(other, "render_settings {\n    width: 64\n}\n");
    const Scene shown = state.doc.scene;
    open_scene(state, other);
    model.frame(state);
    EXPECT_EQ(state.doc.path, file);
    EXPECT_TRUE(state.doc.scene == shown);
    EXPECT_FALSE(state.doc.load_failed) << "the file shown is fine";
    EXPECT_NE(state.message.find("Could not open other.jts"), std::string::npos) << state.message;
    EXPECT_NE(state.message.find("still showing " + file.filename().string()), std::string::npos)
        << state.message;
    EXPECT_EQ(state.message.find("last good"), std::string::npos) << state.message;
    EXPECT_NE(format_diagnostics(state.doc).find("other.jts:2:"), std::string::npos)
        << format_diagnostics(state.doc);

    // An edit of the file shown is checked as ever: the diagnostics are its own again.
    edit_pigment();
    model.frame(state);
    EXPECT_EQ(format_diagnostics(state.doc), "");
    undo(state);
    model.frame(state);
    // And a change of it on disk reloads it.
    open_scene(state, other);
    model.frame(state);
    they_save(kTheirs);
    EXPECT_EQ(state.doc.scene.lights.at(0).intensity, Colour(0.5)) << state.message;
    EXPECT_FALSE(state.doc.load_failed);
    EXPECT_EQ(format_diagnostics(state.doc), "");
}

// An error made in another editor and mended there, the file back as it
// was: the reload reads the scene the image shows, and its render goes on
// rather than starting again from the first preview. A change renders.
TEST_F(ViewerFiles, AFileMendedBackToTheShownSceneKeepsTheRender) {
    const std::uint64_t jobs = state.render.renderer.jobs_started();
    const Image8 good = state.render.display;
    they_save(replaced(kOriginal, "height: 48;", "height: 48"));
    ASSERT_TRUE(state.doc.load_failed);
    model.frame(state);
    they_save(kOriginal + "# mended\n");
    EXPECT_FALSE(state.doc.load_failed);
    for (int i = 0; i < 3; ++i) model.frame(state);
    EXPECT_EQ(state.render.renderer.jobs_started(), jobs) << "no render started again";
    EXPECT_TRUE(render_complete(state.render));
    EXPECT_EQ(state.render.display, good);
    they_save(kTheirs);
    ASSERT_TRUE(model.run_until_complete(state, kTimeout));
    EXPECT_GT(state.render.renderer.jobs_started(), jobs) << "a changed scene renders";
}

TEST_F(ViewerFiles, ReloadCanDropTheEdits) {
    edit_pigment();
    they_save(kTheirs);
    resolve_reload(state, ReloadChoice::drop_edits);
    EXPECT_FALSE(has_unsaved_edits(state.doc));
    EXPECT_EQ(state.doc.text, kTheirs);
    EXPECT_EQ(state.doc.scene, parse_scene(kTheirs).scene);
}

// Edits dropped for a newer file that has errors: the last good scene that
// stays is the file's, not the edits no text holds any more.
TEST_F(ViewerFiles, EditsDroppedForABrokenFileLeaveTheFilesScene) {
    edit_pigment();
    they_save("render_settings {");
    ASSERT_TRUE(state.files.pending_reload.has_value()) << state.message;
    resolve_reload(state, ReloadChoice::drop_edits);
    ASSERT_TRUE(state.doc.draft.has_value()) << state.message;
    EXPECT_NE(state.doc.scene.primitives[1].material.pigment, kMyPigment) << "dropped";
    EXPECT_EQ(state.doc.scene, *state.doc.original);
    model.frame(state);
    model.frame(state);
    EXPECT_FALSE(state.history.undo.can_undo()) << "the drop is no edit to undo";
    EXPECT_FALSE(state.history.undo.can_redo());
}

TEST_F(ViewerFiles, ReloadCanReapplyTheEditsOntoTheNewerText) {
    edit_pigment();
    they_save(kTheirs);
    resolve_reload(state, ReloadChoice::reapply_edits);
    EXPECT_FALSE(state.files.pending_reload.has_value());
    EXPECT_EQ(state.doc.scene.primitives[1].material.pigment, kMyPigment) << "my edit";
    EXPECT_EQ(state.doc.scene.lights[0].intensity, Colour(0.5)) << "their change";
    // Scenes compare equal whatever their folder, so this is checked alone:
    // without it a model or image map named relative to the scene is looked
    // for in the working directory, and the image stops rendering.
    EXPECT_EQ(state.doc.scene.asset_folder, file.parent_path().string());
    EXPECT_TRUE(has_unsaved_edits(state.doc));
    ASSERT_TRUE(save_scene(state)) << state.message;
    EXPECT_EQ(read_file(file),
              replaced(kTheirs, "pigment: <0.9, 0.2, 0.1>;", "pigment: <0.25, 0.5, 0.75>;"));
    undo(state);  // back to the file as they wrote it
    EXPECT_EQ(state.doc.scene, parse_scene(kTheirs).scene);
}

// Found in the real window: `width: 800` typed without its `;`, then the
// file changed on disk, then Keep mine. The text editor showed the broken
// text under "No errors or warnings" and Diagnostics (0): the diagnostics
// stayed the newer file's. Kept edits are described by their own again.
TEST_F(ViewerFiles, KeptEditsShowTheirOwnDiagnosticsAgain) {
    const std::string broken = replaced(kOriginal, "height: 48;", "height: 48");
    type_text(state, broken);
    ASSERT_TRUE(run_until([&] { return !state.check.checker.in_flight(); }));
    ASSERT_TRUE(state.doc.draft.has_value());
    ASSERT_TRUE(has_errors(state.doc.diagnostics));
    they_save(kTheirs);
    ASSERT_TRUE(state.files.pending_reload.has_value());
    resolve_reload(state, ReloadChoice::keep_edits);
    ASSERT_TRUE(run_until([&] { return !state.check.checker.in_flight(); }));
    EXPECT_TRUE(has_errors(state.doc.diagnostics)) << "the kept text's error is listed again";
    EXPECT_EQ(state.doc.diagnostics_source, broken);
    EXPECT_EQ(document_text(state.doc), broken);

    // A panel edit kept over a newer file with errors: that file's errors go.
    undo(state);
    ASSERT_FALSE(state.doc.draft.has_value());
    edit_pigment();
    they_save(broken);
    ASSERT_TRUE(state.doc.load_failed);
    resolve_reload(state, ReloadChoice::keep_edits);
    model.frame(state);
    EXPECT_FALSE(state.doc.load_failed);
    EXPECT_FALSE(has_errors(state.doc.diagnostics)) << "the errors of the file not taken";
    EXPECT_EQ(state.doc.diagnostics_source, state.doc.text);
}

// Found in the real window: " oops" typed after `width: 800;`, then the
// file changed on disk. While the reload bar waited for a choice the text
// editor showed the broken text under "errors: showing the last good
// image", yet listed "No errors or warnings" and Diagnostics (0): the
// diagnostics were the newer file's, until the next keystroke brought the
// text's own back. Typed text keeps its own diagnostics while the choice
// waits (the bar says whether the file on disk has errors).
TEST_F(ViewerFiles, TypedTextKeepsItsDiagnosticsWhileTheReloadChoiceWaits) {
    const std::string broken = replaced(kOriginal, "height: 48;", "height: 48");
    type_text(state, broken);
    ASSERT_TRUE(run_until([&] { return !state.check.checker.in_flight(); }));
    ASSERT_TRUE(state.doc.draft.has_value());
    ASSERT_TRUE(has_errors(state.doc.diagnostics));
    for (const std::string& theirs : {kTheirs, replaced(kTheirs, "radius: 1;", "radius: 1 x;")}) {
        they_save(theirs);
        ASSERT_TRUE(state.files.pending_reload.has_value());
        for (int i = 0; i < 3; ++i) model.frame(state);
        EXPECT_TRUE(has_errors(state.doc.diagnostics)) << "the typed text's error";
        EXPECT_EQ(state.doc.diagnostics_source, broken);
        EXPECT_EQ(document_text(state.doc), broken);
        EXPECT_EQ(state.files.pending_reload->ok, theirs == kTheirs);
        EXPECT_NE(state.message.find("changed on disk"), std::string::npos) << state.message;
    }
    // Dropped for the file with errors: its text is shown, with its errors.
    const std::string theirs = read_file(file);
    resolve_reload(state, ReloadChoice::drop_edits);
    ASSERT_TRUE(run_until([&] { return !state.check.checker.in_flight(); }));
    EXPECT_EQ(document_text(state.doc), theirs);
    EXPECT_TRUE(has_errors(state.doc.diagnostics));
    EXPECT_EQ(state.doc.diagnostics_source, theirs) << "the file's own";
}

// Found by the monkey (seed 4): text typed, then at once the file taken
// from disk (drop my edits). The history was cleared but the burst of
// typing was not ended (its check, overtaken, never ended it), so the next
// keystrokes recorded no undo step: Ctrl+Z could not take them back. A
// scene replaced ends the burst.
TEST_F(ViewerFiles, TypingAfterTheFileIsTakenFromDiskCanBeUndone) {
    // The file changes within the pause after the keystroke, before the
    // text is checked.
    type_text(state, replaced(kOriginal, "height: 48;", "height: 48"));
    ASSERT_TRUE(state.doc.draft.has_value());
    they_save(kTheirs);
    ASSERT_TRUE(state.files.pending_reload.has_value());
    resolve_reload(state, ReloadChoice::drop_edits);
    model.frame(state);
    ASSERT_EQ(document_text(state.doc), kTheirs);
    ASSERT_FALSE(state.history.undo.can_undo());

    type_text(state, kTheirs + "# typed\n");
    EXPECT_TRUE(state.history.undo.can_undo()) << "the typing is no undo step";
    undo(state);
    EXPECT_EQ(document_text(state.doc), kTheirs);
}

// Found in the real window: an open of a large file takes seconds, and the
// panels and the text stay editable meanwhile. The prompt for unsaved edits
// is asked when the open is requested; an edit made after that was replaced
// by the opened file without a word. Such an edit is asked about when the
// open arrives; the edits the user agreed to discard are not asked again.
TEST_F(ViewerFiles, EditsMadeWhileAnotherFileOpensAreNotDroppedUnasked) {
    const fs::path other = file.parent_path() / "other.jts";
    write_file(other, kTheirs);
    request_open_guarded(state, other);
    ASSERT_FALSE(state.files.unsaved_prompt.has_value()) << "nothing unsaved yet: it opens";
    edit_pigment();  // while it loads
    ASSERT_TRUE(model.run_until_loaded(state));
    EXPECT_EQ(state.doc.path, file) << "the open replaced an edit made while it loaded";
    EXPECT_EQ(state.doc.scene.primitives[1].material.pigment, kMyPigment);
    ASSERT_TRUE(state.files.unsaved_prompt.has_value());
    EXPECT_EQ(state.files.unsaved_prompt->path, other);

    resolve_unsaved(state, UnsavedChoice::discard);
    ASSERT_TRUE(model.run_until_loaded(state));
    EXPECT_EQ(state.doc.path, other) << "the edits the user discarded are not asked about again";
    EXPECT_EQ(state.doc.scene, parse_scene(kTheirs).scene);
    EXPECT_FALSE(state.files.unsaved_prompt.has_value());

    // Typed text discarded while its check runs: the check taking the text in
    // during the open is no edit of the user's.
    type_text(state, replaced(kTheirs, "height: 48;", "height: 50;"));
    request_open_guarded(state, file);
    ASSERT_TRUE(state.files.unsaved_prompt.has_value());
    resolve_unsaved(state, UnsavedChoice::discard);
    state.check.checker.wait();
    ASSERT_TRUE(take_checked_text(state));  // before the open arrives
    ASSERT_FALSE(state.doc.draft.has_value()) << "the typed text parses";
    ASSERT_TRUE(model.run_until_loaded(state));
    EXPECT_EQ(state.doc.path, file) << state.message;
    EXPECT_FALSE(state.files.unsaved_prompt.has_value());
}

TEST_F(ViewerFiles, SaveRefusesToOverwriteANewerFileUntilToldTo) {
    edit_pigment();
    they_save(kTheirs);
    resolve_reload(state, ReloadChoice::keep_edits);
    EXPECT_FALSE(save_scene(state));
    EXPECT_NE(state.files.save_conflict.find("changed by another program"), std::string::npos)
        << state.files.save_conflict;
    EXPECT_EQ(read_file(file), kTheirs);
    ASSERT_TRUE(save_scene_anyway(state)) << state.message;
    EXPECT_TRUE(state.files.save_conflict.empty());
    EXPECT_EQ(read_file(file), kMine);
    // Our own save is not a change from outside.
    ASSERT_TRUE(model.run_until_loaded(state));
    EXPECT_FALSE(state.files.pending_reload.has_value());
}

TEST_F(ViewerFiles, SaveRefusesToOverwriteABrokenOrDeletedFile) {
    edit_pigment();
    const std::string broken = replaced(kOriginal, "height: 48;", "height: 48");
    they_save(broken);
    EXPECT_TRUE(state.doc.load_failed);
    EXPECT_EQ(state.doc.scene.primitives[1].material.pigment, kMyPigment);
    EXPECT_FALSE(save_scene(state));
    EXPECT_EQ(read_file(file), broken) << "their newer (broken) text stays";

    fs::remove(file);
    ASSERT_TRUE(model.run_until_loaded(state));
    EXPECT_FALSE(save_scene(state));
    EXPECT_NE(state.files.save_conflict.find("was deleted"), std::string::npos)
        << state.files.save_conflict;
    EXPECT_FALSE(fs::exists(file));
    ASSERT_TRUE(save_scene_anyway(state)) << state.message;
    EXPECT_EQ(read_file(file), kMine);
}

TEST_F(ViewerFiles, SavingAnUntouchedFileNeedsNoConfirmation) {
    edit_pigment();
    ASSERT_TRUE(save_scene(state)) << state.message;
    EXPECT_EQ(read_file(file), kMine);
    fs::last_write_time(file, fs::last_write_time(file) + std::chrono::hours(1));  // touched only
    ASSERT_TRUE(model.run_until_loaded(state));
    edit_scene(state, [](Scene& s) { s.settings.samples = 2; });
    EXPECT_TRUE(save_scene(state)) << state.message;
}

// "Saved scene.jts" stays on the status line after the save; an edit made
// since must not read as saved while the title's "*" says it is not.
TEST_F(ViewerFiles, TheStatusLineDoesNotCallANewerEditSaved) {
    edit_pigment();
    ASSERT_TRUE(save_scene(state)) << state.message;
    EXPECT_EQ(shown_message(state).rfind("Saved ", 0), 0u) << shown_message(state);
    const int samples = state.doc.scene.settings.samples;
    edit_scene(state, [](Scene& s) { s.settings.samples = 5; });
    ASSERT_TRUE(has_unsaved_work(state));
    EXPECT_EQ(shown_message(state).find("Saved"), std::string::npos) << shown_message(state);
    EXPECT_NE(shown_message(state).find("Ctrl+S"), std::string::npos) << shown_message(state);
    // Back to the scene on disk: the save describes it again.
    edit_scene(state, [&](Scene& s) { s.settings.samples = samples; });
    ASSERT_FALSE(has_unsaved_work(state));
    EXPECT_EQ(shown_message(state).rfind("Saved ", 0), 0u) << shown_message(state);

    ASSERT_TRUE(save_scene(state)) << state.message;
    EXPECT_EQ(shown_message(state), "Nothing to save: the files hold this scene");
    edit_scene(state, [](Scene& s) { s.settings.samples = 6; });
    EXPECT_EQ(shown_message(state).find("Nothing to save"), std::string::npos);
    // A later command's message is its own, edits or not.
    state.message = "Renamed the camera";
    EXPECT_EQ(shown_message(state), "Renamed the camera");
    state.message.claim_saved("Saved scene.jts");
    state.message.clear();
    EXPECT_EQ(shown_message(state), "") << "a cleared message claims nothing";
}

// Found in the real window: "Opened main.jts" stayed on the status line
// after a panel edit, beside the title's "*"; so did "Reloaded".
TEST_F(ViewerFiles, TheStatusLineDoesNotCallANewerEditTheFilesScene) {
    ASSERT_EQ(shown_message(state).rfind("Opened ", 0), 0u) << shown_message(state);
    edit_pigment();
    ASSERT_TRUE(has_unsaved_work(state));
    EXPECT_EQ(shown_message(state).find("Opened"), std::string::npos) << shown_message(state);
    EXPECT_NE(shown_message(state).find("Ctrl+S"), std::string::npos) << shown_message(state);
    undo(state);
    ASSERT_FALSE(has_unsaved_work(state));
    EXPECT_EQ(shown_message(state), "Undone");

    they_save(kMine);
    ASSERT_EQ(shown_message(state).rfind("Reloaded ", 0), 0u) << shown_message(state);
    edit_scene(state, [](Scene& s) { s.settings.samples = 3; });
    EXPECT_EQ(shown_message(state).find("Reloaded"), std::string::npos) << shown_message(state);
    EXPECT_NE(shown_message(state).find("Ctrl+S"), std::string::npos) << shown_message(state);
}

// Found in the real window: a file with errors opened as the viewer starts
// is the document (its title, the text editor's to mend), yet the Recent
// list, whose first entry reads as the file shown, still began with the
// scene of the last session. A file that could not be read is not listed.
TEST(ViewerRecent, AFileOpenedWithErrorsAtTheStartIsTheNewestRecentFile) {
    const fs::path file = scene_copy("recent-broken-at-start");
    write_file(file, replaced(kOriginal, "height: 48;", "height: 48"));
    AppState state{test_config()};
    state.files.recent.add("/elsewhere/last-session.jts");
    open_scene(state, file);
    ASSERT_FALSE(state.doc.loaded);
    ASSERT_EQ(state.doc.path, file);
    EXPECT_EQ(state.files.recent.paths().front(), file.string());
    EXPECT_EQ(state.fields.open_path_input, file.string());

    AppState other{test_config()};
    other.files.recent.add("/elsewhere/last-session.jts");
    open_scene(other, file.parent_path() / "no-such-scene.jts");
    EXPECT_EQ(other.files.recent.paths().front(), "/elsewhere/last-session.jts");
    fs::remove_all(file.parent_path());
}

// The save replaces the file by a rename, which the folder allows whatever
// the file's own mode: the file keeps its mode, and one nobody may write is
// not replaced (root may write anything, so its bits are what count).
TEST_F(ViewerFiles, SaveKeepsTheFilesModeAndLeavesAReadOnlyFileAlone) {
    const auto mode = [&] { return fs::status(file).permissions() & fs::perms::all; };
    fs::permissions(file, fs::perms::owner_read | fs::perms::owner_write);
    edit_pigment();
    ASSERT_TRUE(save_scene(state)) << state.message;
    EXPECT_EQ(read_file(file), kMine);
    EXPECT_EQ(mode(), fs::perms::owner_read | fs::perms::owner_write) << "a private file stays so";
    ASSERT_TRUE(model.run_until_loaded(state));

    const fs::perms read_only = fs::perms::owner_read | fs::perms::group_read;
    fs::permissions(file, read_only);
    edit_scene(state, [](Scene& s) { s.settings.samples = 3; });
    EXPECT_FALSE(save_scene(state));
    EXPECT_NE(state.message.find("read-only"), std::string::npos) << state.message;
    EXPECT_FALSE(save_scene_anyway(state)) << "no answer replaces a read-only file";
    EXPECT_EQ(read_file(file), kMine);
    EXPECT_EQ(mode(), read_only);
    EXPECT_TRUE(has_unsaved_edits(state.doc)) << "the edit is still there to save elsewhere";
    const fs::path copy = file.parent_path() / "copy.jts";
    ASSERT_TRUE(save_scene_as(state, copy, false)) << state.message;
    EXPECT_EQ(parse_scene(read_file(copy)).scene.settings.samples, 3);
    fs::permissions(file, fs::perms::owner_all);
}

TEST_F(ViewerFiles, UndoingANewCameraAfterSavingSavesItsRemoval) {
    use_free_camera(state.view, state.doc.scene);
    orbit(state.view.free_camera, 40, 10, 240);
    ASSERT_TRUE(copy_free_camera_to_scene(state, "mine"));
    EXPECT_FALSE(copy_free_camera_to_scene(state, "mine")) << "names stay unique";
    ASSERT_TRUE(save_scene(state)) << state.message;
    EXPECT_EQ(parse_scene(read_file(file)).scene.cameras.size(), 3u);
    undo(state);
    ASSERT_EQ(state.doc.scene.cameras.size(), 2u);
    ASSERT_TRUE(save_scene(state)) << state.message;
    EXPECT_EQ(read_file(file), kOriginal) << "byte for byte the file before the camera";
}

// Save as writes the file's text with the edits in place, so a file's names,
// named materials and expressions are kept, never replaced by their values.
TEST(ViewerSaveAs, KeepsTheFilesNamesAndExpressions) {
    const ScratchDir dir("save_as_names");
    const fs::path file = dir.path() / "named.jts";
    const std::string named =
        "define r = 1;\n"
        "material grey { pigment: <0.5, 0.5, 0.5> * r; }\n"
        "render_settings { width: 16 * r; height: 12; }\n"
        "cameras { perspective_camera { position: <0, 1, 6> * r; aspect: 4 / 3; } }\n"
        "scene {\n"
        "    sphere { radius: r / 2; material: grey; }\n"
        "    point_light { position: <3, 5, 4>; intensity: <1, 1, 1>; }\n"
        "}\n";
    write_file(file, named);
    ModelLoop model;
    AppState state{test_config()};
    open_scene(state, file);
    ASSERT_TRUE(model.run_until_complete(state, kTimeout));
    edit_scene(state, [](Scene& s) { s.lights[0].intensity = Colour(0.5); });
    const fs::path copy = dir.path() / "copy.jts";
    ASSERT_TRUE(save_scene_as(state, copy, false)) << state.message;
    const std::string saved = read_file(copy);
    EXPECT_EQ(saved, replaced(named, "intensity: <1, 1, 1>", "intensity: <0.5, 0.5, 0.5>"));
    EXPECT_TRUE(parse_scene(saved).scene == state.doc.scene);
}

// Found in the window: the split scene (include "parts/materials.jts")
// saved as a copy one folder up gave a file that no longer opened (its
// includes read from the copy's folder), and a scene with image maps the
// same (they are found from it too). A copy in another folder is refused
// when the scene names files relative to its own; in the same folder, or
// with nothing relative, it is written and opens as the same scene.
TEST(ViewerSaveAs, ACopyInAnotherFolderMustReadTheSameFiles) {
    const ScratchDir dir("save_as_folders");
    fs::copy(fs::path(JT_SOURCE_DIR) / "scenes" / "split", dir.path() / "split",
             fs::copy_options::recursive);
    fs::create_directories(dir.path() / "elsewhere");
    ModelLoop model;
    AppState state{test_config()};
    const fs::path main = dir.path() / "split" / "main.jts";
    open_scene(state, main);
    ASSERT_TRUE(model.run_until_loaded(state));
    ASSERT_TRUE(state.doc.loaded) << format_diagnostics(state.doc);
    edit_scene(state, [](Scene& s) { s.settings.width = 64; });
    for (const fs::path& away : {dir.path() / "copy.jts", dir.path() / "elsewhere" / "copy.jts"}) {
        EXPECT_FALSE(save_scene_as(state, away, false)) << away;
        EXPECT_FALSE(fs::exists(away)) << away;
        EXPECT_NE(state.message.find("save the copy in that folder"), std::string::npos)
            << state.message;
        EXPECT_EQ(state.doc.path, main);
        EXPECT_TRUE(has_unsaved_edits(state.doc));
    }
    // Beside it the includes read the same files.
    const fs::path beside = dir.path() / "split" / "copy.jts";
    ASSERT_TRUE(save_scene_as(state, beside, false)) << state.message;
    AppState again{test_config()};
    open_scene(again, beside);
    ASSERT_TRUE(model.run_until_loaded(again));
    ASSERT_TRUE(again.doc.loaded) << format_diagnostics(again.doc);
    EXPECT_TRUE(again.doc.scene == state.doc.scene);

    // Image maps named relative to the scene's folder: the same.
    const fs::path globe = dir.path() / "globe" / "globe.jts";
    fs::create_directories(globe.parent_path());
    fs::copy(fs::path(JT_SOURCE_DIR) / "scenes" / "globe.jts", globe);
    fs::copy(fs::path(JT_SOURCE_DIR) / "scenes" / "maps", globe.parent_path() / "maps");
    open_scene(state, globe);
    ASSERT_TRUE(model.run_until_loaded(state));
    ASSERT_TRUE(state.doc.loaded) << format_diagnostics(state.doc);
    const fs::path away = dir.path() / "elsewhere" / "globe.jts";
    EXPECT_FALSE(save_scene_as(state, away, false));
    EXPECT_FALSE(fs::exists(away));
    EXPECT_NE(state.message.find("maps/"), std::string::npos) << state.message;

    // Nothing named relative: any folder will do.
    open_scene(state, kScene);
    ASSERT_TRUE(model.run_until_loaded(state));
    const fs::path plain = dir.path() / "elsewhere" / "plain.jts";
    ASSERT_TRUE(save_scene_as(state, plain, false)) << state.message;
    EXPECT_TRUE(parse_scene(read_file(plain)).scene == state.doc.scene);
}

// The working folder is `folder` while this lives, then the one before.
struct InFolder {
    explicit InFolder(const fs::path& folder) : back(fs::current_path()) {
        fs::current_path(folder);
    }
    ~InFolder() { fs::current_path(back); }
    InFolder(const InFolder&) = delete;
    InFolder& operator=(const InFolder&) = delete;
    fs::path back;
};

// Found in the window: "copy.jts" typed into Save scene as, for the split
// scene (which includes parts/), was refused with "save the copy in that
// folder": the name was read against the folder the viewer was started
// from. A relative name is a file beside the scene, "Replace it" writes the
// same file, and a scene opened by a relative path resolves the same.
TEST(ViewerSaveAs, ARelativeNameIsAFileBesideTheScene) {
    const ScratchDir dir("save_as_relative");
    fs::copy(fs::path(JT_SOURCE_DIR) / "scenes" / "split", dir.path() / "split",
             fs::copy_options::recursive);
    const fs::path started_in = fs::current_path();
    ASSERT_NE(fs::weakly_canonical(started_in), fs::weakly_canonical(dir.path() / "split"));
    ModelLoop model;
    AppState state{test_config()};
    open_scene(state, dir.path() / "split" / "main.jts");
    ASSERT_TRUE(model.run_until_loaded(state));
    ASSERT_TRUE(state.doc.loaded) << format_diagnostics(state.doc);
    edit_scene(state, [](Scene& s) { s.settings.width = 64; });
    const fs::path beside = dir.path() / "split" / "copy.jts";
    ASSERT_TRUE(save_scene_as(state, "copy.jts", false)) << state.message;
    EXPECT_TRUE(fs::exists(beside));
    EXPECT_FALSE(fs::exists(started_in / "copy.jts"));
    EXPECT_EQ(fs::weakly_canonical(state.doc.path), fs::weakly_canonical(beside));

    // Asked again: the file beside it exists, and Replace writes that one.
    edit_scene(state, [](Scene& s) { s.settings.width = 72; });
    EXPECT_FALSE(save_scene_as(state, "copy.jts", false));
    ASSERT_FALSE(state.files.save_as_conflict.empty());
    EXPECT_EQ(fs::weakly_canonical(state.files.save_as_conflict), fs::weakly_canonical(beside));
    ASSERT_TRUE(save_scene_as(state, state.files.save_as_conflict, true)) << state.message;
    EXPECT_NE(read_file(beside).find("width: 72"), std::string::npos);
    EXPECT_FALSE(has_unsaved_edits(state.doc));

    // A scene opened by a relative path: the name is read against its folder
    // once, also when it is confirmed.
    const InFolder in_dir(dir.path());
    AppState relative{test_config()};
    open_scene(relative, "split/main.jts");
    ASSERT_TRUE(model.run_until_loaded(relative));
    ASSERT_TRUE(relative.doc.loaded) << format_diagnostics(relative.doc);
    edit_scene(relative, [](Scene& s) { s.settings.width = 80; });
    EXPECT_FALSE(save_scene_as(relative, "copy.jts", false));
    ASSERT_TRUE(save_scene_as(relative, relative.files.save_as_conflict, true)) << relative.message;
    EXPECT_NE(read_file(beside).find("width: 80"), std::string::npos);
    EXPECT_FALSE(fs::exists(dir.path() / "split" / "split"));
}

// Found in the real window: a relative name typed in the Open field was
// read against the folder the viewer was started from, while Save scene as
// reads it beside the scene. Both read it beside the scene; the path the
// field shows after an open is absolute, so that Open pressed again opens
// the same file (not split/split/main.jts).
TEST(ViewerOpenField, ARelativeNameIsAFileBesideTheScene) {
    const ScratchDir dir("open_relative");
    fs::copy(fs::path(JT_SOURCE_DIR) / "scenes" / "split", dir.path() / "split",
             fs::copy_options::recursive);
    const fs::path other = dir.path() / "split" / "other.jts";
    fs::copy_file(dir.path() / "split" / "main.jts", other);
    const fs::path started_in = fs::current_path();
    ASSERT_FALSE(fs::exists(started_in / "other.jts"));
    ModelLoop model;
    AppState state{test_config()};
    open_scene(state, dir.path() / "split" / "main.jts");
    ASSERT_TRUE(model.run_until_loaded(state));
    ASSERT_TRUE(state.doc.loaded) << format_diagnostics(state.doc);
    state.fields.open_path_input = "other.jts";
    open_typed_path(state);
    ASSERT_TRUE(model.run_until_loaded(state));
    EXPECT_TRUE(state.doc.loaded) << state.message;
    EXPECT_EQ(fs::weakly_canonical(state.doc.path), fs::weakly_canonical(other)) << state.message;

    const InFolder in_dir(dir.path());
    AppState relative{test_config()};
    open_scene(relative, "split/main.jts");
    ASSERT_TRUE(model.run_until_loaded(relative));
    ASSERT_TRUE(relative.doc.loaded) << format_diagnostics(relative.doc);
    EXPECT_TRUE(fs::path(relative.fields.open_path_input).is_absolute())
        << relative.fields.open_path_input;
    open_typed_path(relative);
    ASSERT_TRUE(model.run_until_loaded(relative));
    EXPECT_EQ(fs::weakly_canonical(relative.doc.path),
              fs::weakly_canonical(dir.path() / "split" / "main.jts"))
        << relative.message;
    EXPECT_EQ(relative.message.rfind("Opened ", 0), 0u) << relative.message;
}

// A file the viewer had loaded, then broken in each way a file breaks.
struct Fault {
    const char* name;
    std::string (*contents)(const std::string& good);
};

void PrintTo(const Fault& fault, std::ostream* out) {
    *out << fault.name;
}

class ViewerFaults : public ViewerFiles, public ::testing::WithParamInterface<Fault> {};

TEST_P(ViewerFaults, KeepTheLastImageShowTheErrorAndRecover) {
    const Image8 good = state.render.display;
    static_cast<void>(take_display_changes(state.render));  // shown
    const Scene good_scene = state.doc.scene;
    const auto jobs = state.render.renderer.jobs_started();
    if (GetParam().contents)  // written in place: a save cut short leaves just this
        std::ofstream(file, std::ios::binary | std::ios::trunc) << GetParam().contents(kOriginal);
    else
        fs::remove(file);

    // Frames keep coming while the file loads: the UI thread never parses.
    const auto deadline = std::chrono::steady_clock::now() + kTimeout;
    int frames = 0, frames_while_loading = 0;
    double slowest_ms = 0.0;
    model.frame(state);  // sees the change, starts the reload
    do {
        const auto start = std::chrono::steady_clock::now();
        const bool loading = state.files.loader.busy();
        model.frame(state);
        slowest_ms = std::max(slowest_ms, std::chrono::duration<double, std::milli>(
                                              std::chrono::steady_clock::now() - start)
                                              .count());
        ++frames;
        if (loading) ++frames_while_loading;
    } while (state.files.loader.busy() && std::chrono::steady_clock::now() < deadline);
    std::printf("%s: %d frames while loading, slowest %.1f ms\n", GetParam().name, frames,
                slowest_ms);
    RecordProperty("slowest_frame_ms", std::to_string(slowest_ms));
    ASSERT_FALSE(state.files.loader.busy()) << "the load never finished";

    EXPECT_TRUE(state.doc.load_failed);
    ASSERT_FALSE(state.doc.diagnostics.empty());
    EXPECT_FALSE(format_diagnostics(state.doc).empty());
    EXPECT_EQ(state.doc.scene, good_scene);
    EXPECT_EQ(state.render.display, good);
    EXPECT_FALSE(take_display_changes(state.render)) << "nothing new to show";
    EXPECT_EQ(state.render.renderer.jobs_started(), jobs);
    if (std::string(GetParam().name) == "huge") {
        EXPECT_GT(frames_while_loading, 2);
    }

    save_as_editor(file, kOriginal);  // fixed
    ASSERT_TRUE(model.run_until_loaded(state));
    EXPECT_FALSE(state.doc.load_failed);
    EXPECT_TRUE(state.doc.diagnostics.empty());
    ASSERT_TRUE(model.run_until_complete(state, kTimeout));
    EXPECT_EQ(state.render.display, good);
}

// 100 MB: the good scene, then a comment the lexer reads through to an error
// at the very end. (25 MB under AddressSanitizer, which reads it ~10x slower:
// the same path, within the time a CI test may take.)
#ifdef __SANITIZE_ADDRESS__
constexpr std::size_t kHugeBytes = 25u << 20;
#else
constexpr std::size_t kHugeBytes = 100u << 20;
#endif
std::string huge(const std::string& good) {
    constexpr std::size_t size = kHugeBytes;
    std::string text = good + "#";
    text.append(size - text.size() - 7, 'x');
    text += "\noops;\n";
    return text;
}

INSTANTIATE_TEST_SUITE_P(
    Faults, ViewerFaults,
    ::testing::Values(
        Fault{"deleted", nullptr}, Fault{"empty", [](const std::string&) { return std::string(); }},
        Fault{"truncated", [](const std::string& good) { return good.substr(0, good.size() / 2); }},
        Fault{"garbage",
              [](const std::string&) {
                  return std::string(
                      "\x7f"
                      "ELF\x02\x01\x01\0\0\xff\xfe{{",
                      14);
              }},
        Fault{"huge", huge}),
    [](const ::testing::TestParamInfo<Fault>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace jt::view
