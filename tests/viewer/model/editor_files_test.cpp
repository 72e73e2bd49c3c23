// The text editor opens the files a scene includes (docs/language.md §15.6):
// each listed once, typed text kept per file, saved into its file (checked,
// atomically) with the scene reloaded; the status line names the files a
// save wrote; a value from an included file names it, and how often it is read.

#include "model/editor_files.hpp"
#include "common/files.hpp"
#include "common/scratch_dir.hpp"
#include "jtracer/file_stamp.hpp"
#include "model/app_actions.hpp"
#include "model/document_edits.hpp"
#include "model/edit_commands.hpp"
#include "model/field_sources.hpp"
#include "viewer/model/model_loop.hpp"
#include "viewer/viewer_test_files.hpp"

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

namespace jt::view {
namespace {

namespace fs = std::filesystem;
using namespace jt::test;

const std::string kMain =
    "render_settings { width: 32; height: 24; }\n"
    "cameras { perspective_camera { aspect: 1.3333333333333333; } }\n"
    "scene { point_light { position: <3, 5, 4>; } include \"parts/ball.jts\"; }\n";
const std::string kHead =
    "render_settings { width: 32; height: 24; }\n"
    "cameras { perspective_camera { aspect: 1.3333333333333333; } }\n";
const std::string kBall = "sphere { center: <0, 0, -5>; radius: 1; }\n";

double radius_of(const AppState& state, std::size_t i) {
    return shape_as<Sphere>(state.doc.scene.primitives.at(i).shape).radius;
}

// The names the editor's file buttons show after the scene file's.
std::vector<std::string> listed_files(const SceneDocument& doc) {
    std::vector<std::string> names;
    const std::span<const SourceFile> readings = latest_readings(doc);
    for (std::size_t i = 0; i < readings.size(); ++i)
        if (first_reading(readings, i)) names.emplace_back(short_file_name(doc, readings[i].name));
    return names;
}

std::string canonical_of(const SceneDocument& doc, const std::string& name) {
    for (const SourceFile& f : latest_readings(doc))
        if (short_file_name(doc, f.name) == name) return f.canonical;
    return {};
}

class EditorFilesTest : public ::testing::Test {
  protected:
    void write(const fs::path& path, const std::string& text) {
        fs::create_directories(path.parent_path());
        write_file(path, text);
    }
    // Opened, and one frame run: the viewer watches the included files from then on.
    void open(const std::string& main_text = kMain) {
        write(main, main_text);
        open_scene(state, main);
        model.frame(state);
    }

    ScratchDir scratch{"viewer-editor-files"};
    const fs::path main = scratch.path() / "main.jts";
    const fs::path ball = scratch.path() / "parts" / "ball.jts";
    const fs::path lamp = scratch.path() / "parts" / "lamp.jts";
    ModelLoop model;
    AppState state{test_config()};
};

TEST_F(EditorFilesTest, ListsEachIncludedFileOnceAfterTheSceneFile) {
    write(ball, kBall);
    write(lamp, "point_light { position: <0, 9, 0>; }\n");
    open(kHead +
         "scene { include \"parts/ball.jts\"; include \"parts/lamp.jts\";\n"
         "        include \"parts/ball.jts\"; }\n");
    ASSERT_TRUE(state.doc.loaded) << format_diagnostics(state.doc);
    EXPECT_EQ(listed_files(state.doc),
              (std::vector<std::string>{"parts/ball.jts", "parts/lamp.jts"}));
    EXPECT_EQ(reading_count(latest_readings(state.doc), canonical_of(state.doc, "parts/ball.jts")),
              2);
}

TEST_F(EditorFilesTest, TypedTextOfAnIncludedFileIsKeptAcrossFilesAndSavedIntoIt) {
    write(ball, kBall);
    open();
    ASSERT_TRUE(state.doc.loaded) << format_diagnostics(state.doc);
    const std::string file = canonical_of(state.doc, "parts/ball.jts");
    ASSERT_FALSE(file.empty());
    show_file(state.editor, state.doc, file);
    EXPECT_EQ(state.editor.shown, file);
    EXPECT_EQ(included_text(state.doc, file), kBall);
    const std::string typed = "sphere { center: <0, 0, -5>; radius: 2; }  # typed\n";
    type_included_text(state.editor, state.doc, typed);
    // Another file shown and back: the typed text is still there, and unsaved.
    show_file(state.editor, state.doc, "");
    EXPECT_TRUE(state.editor.shown.empty());
    show_file(state.editor, state.doc, file);
    ASSERT_NE(draft_of(state.editor, file), nullptr);
    EXPECT_EQ(draft_of(state.editor, file)->text, typed);
    EXPECT_TRUE(has_unsaved_work(state));
    EXPECT_EQ(read_file(ball), kBall);
    EXPECT_EQ(radius_of(state, 0), 1.0);

    ASSERT_TRUE(save_scene(state)) << state.message;
    EXPECT_EQ(read_file(ball), typed);
    EXPECT_EQ(read_file(main), kMain);  // not typed in: not written
    EXPECT_EQ(state.message, "Saved parts/ball.jts");
    EXPECT_EQ(radius_of(state, 0), 2.0);  // the scene was read again
    EXPECT_FALSE(has_unsaved_work(state));
    EXPECT_EQ(included_text(state.doc, file), typed);
    // The viewer's own write is no change on disk to reload for.
    model.frame(state);
    EXPECT_EQ(state.message, "Saved parts/ball.jts");
}

TEST_F(EditorFilesTest, TypingTheFileBackDropsItsDraft) {
    write(ball, kBall);
    open();
    const std::string file = canonical_of(state.doc, "parts/ball.jts");
    show_file(state.editor, state.doc, file);
    type_included_text(state.editor, state.doc, "sphere { radius: 3; }\n");
    EXPECT_TRUE(has_included_drafts(state.editor));
    type_included_text(state.editor, state.doc, kBall);
    EXPECT_FALSE(has_included_drafts(state.editor));
    type_included_text(state.editor, state.doc, "sphere { radius: 3; }\n");
    revert_included_draft(state.editor, file);
    EXPECT_FALSE(has_included_drafts(state.editor));
}

// Found in the window: "# hi" typed fast in parts/ball.jts took one Ctrl+Z
// a character to undo, where the scene file's typing goes a step a pause.
// Keys closer than kTypingPause are one step; undone back to the file's
// text there is nothing to save, and redo brings each step back.
TEST_F(EditorFilesTest, TypingInAnIncludedFileIsUndoneAStepAPause) {
    write(ball, kBall);
    open();
    const std::string file = canonical_of(state.doc, "parts/ball.jts");
    show_file(state.editor, state.doc, file);
    using Clock = std::chrono::steady_clock;
    Clock::time_point t{};
    const auto type_keys = [&](const std::string& prefix, std::string_view keys) {
        std::string text = prefix;
        for (const char key : keys) {
            text.insert(text.size() - kBall.size(), 1, key);
            t += std::chrono::milliseconds(40);
            type_included_text(state.editor, state.doc, text, t);
        }
        return text;
    };
    const std::string first = type_keys(kBall, "# a\n");
    t += kTypingPause;
    const std::string second = type_keys(first, "# b\n");
    ASSERT_EQ(draft_of(state.editor, file)->text, "# a\n# b\n" + kBall);

    ASSERT_TRUE(undo_included_typing(state.editor, state.doc));
    EXPECT_EQ(draft_of(state.editor, file)->text, first) << "the second run, whole";
    ASSERT_TRUE(undo_included_typing(state.editor, state.doc));
    EXPECT_FALSE(has_included_drafts(state.editor)) << "the file's text again";
    EXPECT_FALSE(undo_included_typing(state.editor, state.doc));
    EXPECT_FALSE(state.history.undo.can_undo()) << "no step of the scene's history";

    ASSERT_TRUE(redo_included_typing(state.editor, state.doc));
    ASSERT_NE(draft_of(state.editor, file), nullptr);
    EXPECT_EQ(draft_of(state.editor, file)->text, first);
    ASSERT_TRUE(redo_included_typing(state.editor, state.doc));
    EXPECT_EQ(draft_of(state.editor, file)->text, second);
    EXPECT_FALSE(redo_included_typing(state.editor, state.doc));

    // A key right after an undo begins a step of its own.
    ASSERT_TRUE(undo_included_typing(state.editor, state.doc));
    t += std::chrono::milliseconds(10);
    type_included_text(state.editor, state.doc, "#" + first, t);
    ASSERT_TRUE(undo_included_typing(state.editor, state.doc));
    EXPECT_EQ(draft_of(state.editor, file)->text, first);

    // The scene file shown: Ctrl+Z there is none of this file's.
    show_file(state.editor, state.doc, "");
    EXPECT_FALSE(undo_included_typing(state.editor, state.doc));
    EXPECT_EQ(draft_of(state.editor, file)->text, first);
}

// Steps typed over a text the file no longer has would put it back unasked:
// typed back to the file's text, then the file changed on disk, Ctrl+Z
// finds nothing to undo; a save or Revert ends the file's steps too.
TEST_F(EditorFilesTest, IncludedTypingStepsEndWithTheTextTheyWereTypedOver) {
    write(ball, kBall);
    open();
    const std::string file = canonical_of(state.doc, "parts/ball.jts");
    show_file(state.editor, state.doc, file);
    type_included_text(state.editor, state.doc, "# a\n" + kBall);
    ASSERT_TRUE(undo_included_typing(state.editor, state.doc));
    EXPECT_FALSE(has_included_drafts(state.editor));
    const std::string theirs = "sphere { center: <0, 0, -5>; radius: 4.5; }\n";
    write(ball, theirs);
    ASSERT_TRUE(model.run_until_loaded(state));
    ASSERT_EQ(radius_of(state, 0), 4.5);
    EXPECT_FALSE(redo_included_typing(state.editor, state.doc));
    EXPECT_FALSE(has_included_drafts(state.editor));
    EXPECT_EQ(included_text(state.doc, file), theirs);

    type_included_text(state.editor, state.doc, "# b\n" + theirs);
    revert_included_draft(state.editor, file);
    EXPECT_FALSE(undo_included_typing(state.editor, state.doc)) << "Revert ended them";

    type_included_text(state.editor, state.doc, "# c\n" + theirs);
    ASSERT_TRUE(save_scene(state)) << state.message;
    EXPECT_FALSE(undo_included_typing(state.editor, state.doc)) << "saved: the file holds it";
    EXPECT_EQ(read_file(ball), "# c\n" + theirs);
}

// Found in the window: text typed in parts/ball.jts, the file then changed
// by another program, Ctrl+Z dropped the draft (back to the text typing
// began over) and showed the file's new text; Ctrl+Y then found no step,
// and the typed text was gone unasked. Undone, it is a draft still.
TEST_F(EditorFilesTest, TypingUndoneAfterTheFileChangedOnDiskCanBeRedone) {
    write(ball, kBall);
    open();
    const std::string file = canonical_of(state.doc, "parts/ball.jts");
    show_file(state.editor, state.doc, file);
    const std::string typed = "# a\n" + kBall;
    type_included_text(state.editor, state.doc, typed);
    const std::string theirs = "sphere { center: <0, 0, -5>; radius: 4.5; }\n";
    write(ball, theirs);
    ASSERT_TRUE(model.run_until_loaded(state));
    ASSERT_EQ(radius_of(state, 0), 4.5);

    ASSERT_TRUE(undo_included_typing(state.editor, state.doc));
    ASSERT_NE(draft_of(state.editor, file), nullptr) << "the text before the typing, shown";
    EXPECT_EQ(draft_of(state.editor, file)->text, kBall);
    ASSERT_TRUE(redo_included_typing(state.editor, state.doc));
    ASSERT_NE(draft_of(state.editor, file), nullptr);
    EXPECT_EQ(draft_of(state.editor, file)->text, typed);

    // Typed back to the file's text as it is now: nothing to save.
    type_included_text(state.editor, state.doc, theirs);
    EXPECT_FALSE(has_included_drafts(state.editor));
}

TEST_F(EditorFilesTest, AnIncludedTextWithAnErrorIsNotSaved) {
    write(ball, kBall);
    open();
    const std::string file = canonical_of(state.doc, "parts/ball.jts");
    show_file(state.editor, state.doc, file);
    type_included_text(state.editor, state.doc, "sphere { radius: -1; }\n");
    EXPECT_FALSE(save_scene(state));
    EXPECT_EQ(read_file(ball), kBall);
    EXPECT_NE(state.message.find("parts/ball.jts:1:18: error:"), std::string::npos)
        << state.message;
    ASSERT_NE(draft_of(state.editor, file), nullptr);
    EXPECT_NE(draft_of(state.editor, file)->problem.find("parts/ball.jts:1:18"), std::string::npos);
    EXPECT_EQ(draft_of(state.editor, file)->text, "sphere { radius: -1; }\n");
}

TEST_F(EditorFilesTest, AnIncludedFileChangedOnDiskIsNotReplacedUnasked) {
    write(ball, kBall);
    open();
    const std::string file = canonical_of(state.doc, "parts/ball.jts");
    show_file(state.editor, state.doc, file);
    const std::string typed = "sphere { center: <0, 0, -5>; radius: 2; }\n";
    type_included_text(state.editor, state.doc, typed);
    const std::string theirs = "sphere { center: <0, 0, -5>; radius: 4.5; }\n";
    write(ball, theirs);
    EXPECT_FALSE(save_scene(state));
    EXPECT_NE(state.files.save_conflict.find("parts/ball.jts"), std::string::npos)
        << state.files.save_conflict;
    EXPECT_EQ(read_file(ball), theirs);
    // The reload that follows the change keeps the typed text.
    ASSERT_TRUE(model.run_until_loaded(state));
    EXPECT_EQ(radius_of(state, 0), 4.5);
    ASSERT_NE(draft_of(state.editor, file), nullptr);
    EXPECT_EQ(draft_of(state.editor, file)->text, typed);
    EXPECT_FALSE(save_scene(state));  // still not unasked
    ASSERT_TRUE(save_scene_anyway(state)) << state.message;
    EXPECT_EQ(read_file(ball), typed);
    EXPECT_EQ(radius_of(state, 0), 2.0);
}

// Found in the real window: a save refused because an included file changed
// under the text typed in it offered "Reload (choose what to keep)", but a
// reload keeps that text, so the same refusal came back and no choice was
// ever offered. The choice is to drop the typed text and keep the file.
TEST_F(EditorFilesTest, AConflictOverTypedIncludedTextCanBeEndedByDroppingIt) {
    write(ball, kBall);
    open();
    const std::string file = canonical_of(state.doc, "parts/ball.jts");
    show_file(state.editor, state.doc, file);
    type_included_text(state.editor, state.doc, "sphere { center: <0, 0, -5>; radius: 2; }\n");
    const std::string theirs = "sphere { center: <0, 0, -5>; radius: 4.5; }\n";
    write(ball, theirs);
    ASSERT_TRUE(model.run_until_loaded(state));
    // Said at once: the editor still shows the text typed before the change.
    EXPECT_NE(shown_message(state).find("parts/ball.jts changed on disk while you were typing"),
              std::string::npos)
        << shown_message(state);
    EXPECT_FALSE(save_scene(state));
    ASSERT_EQ(state.files.save_conflict_drafts, std::vector<std::string>{file});

    revert_conflicting_drafts(state);
    EXPECT_EQ(draft_of(state.editor, file), nullptr);
    EXPECT_TRUE(state.files.save_conflict.empty());
    EXPECT_NE(state.message.find("parts/ball.jts"), std::string::npos) << state.message;
    EXPECT_FALSE(has_unsaved_work(state));
    EXPECT_EQ(radius_of(state, 0), 4.5);
    EXPECT_EQ(read_file(ball), theirs);

    // A conflict over the scene file itself names no included file.
    edit_scene(state, [](Scene& s) { s.lights[0].position.x = 2; });
    write(main, kMain + "\n");
    EXPECT_FALSE(save_scene(state));
    EXPECT_TRUE(state.files.save_conflict_drafts.empty());
}

TEST_F(EditorFilesTest, ABrokenIncludedFileIsMendedInTheEditor) {
    write(ball, "sphere { radius: -1; }\n");
    open();
    EXPECT_FALSE(state.doc.loaded);
    const std::string file = canonical_of(state.doc, "parts/ball.jts");
    ASSERT_FALSE(file.empty());
    show_file(state.editor, state.doc, file);
    EXPECT_EQ(included_text(state.doc, file), "sphere { radius: -1; }\n");
    type_included_text(state.editor, state.doc, kBall);
    ASSERT_TRUE(save_scene(state)) << state.message;
    EXPECT_EQ(read_file(ball), kBall);
    ASSERT_TRUE(state.doc.loaded) << format_diagnostics(state.doc);
    EXPECT_EQ(radius_of(state, 0), 1.0);
}

TEST_F(EditorFilesTest, QuittingWithTextTypedInAnIncludedFileAsksFirst) {
    write(ball, kBall);
    open();
    show_file(state.editor, state.doc, canonical_of(state.doc, "parts/ball.jts"));
    type_included_text(state.editor, state.doc, "sphere { radius: 3; }\n");
    request_quit(state);
    EXPECT_FALSE(state.quit);
    EXPECT_TRUE(state.files.unsaved_prompt.has_value());
    resolve_unsaved(state, UnsavedChoice::save);
    EXPECT_TRUE(state.quit);
    EXPECT_EQ(read_file(ball), "sphere { radius: 3; }\n");
}

// The prompt names the files that hold unsaved work: under Xvfb it said
// "main.jts has unsaved edits" when only parts/materials.jts had been typed in.
TEST_F(EditorFilesTest, ThePromptNamesTheFilesWithUnsavedWork) {
    write(ball, kBall);
    open();
    EXPECT_TRUE(unsaved_file_names(state).empty());
    show_file(state.editor, state.doc, canonical_of(state.doc, "parts/ball.jts"));
    type_included_text(state.editor, state.doc, "sphere { radius: 3; }\n");
    EXPECT_EQ(unsaved_file_names(state), std::vector<std::string>{"parts/ball.jts"});
    type_text(state, document_text(state.doc) + "# typed\n");
    EXPECT_EQ(unsaved_file_names(state), (std::vector<std::string>{"main.jts", "parts/ball.jts"}));
}

TEST_F(EditorFilesTest, OpeningAnotherSceneAsksAndDropsTheTypedTextOnlyWhenTold) {
    write(ball, kBall);
    open();
    const fs::path other = scratch.path() / "other.jts";
    write(other, kHead + "scene { sphere { radius: 2; } }\n");
    show_file(state.editor, state.doc, canonical_of(state.doc, "parts/ball.jts"));
    type_included_text(state.editor, state.doc, "sphere { radius: 3; }\n");
    request_open_guarded(state, other);
    ASSERT_TRUE(state.files.unsaved_prompt.has_value());
    resolve_unsaved(state, UnsavedChoice::cancel);
    EXPECT_TRUE(has_included_drafts(state.editor));
    request_open_guarded(state, other);
    resolve_unsaved(state, UnsavedChoice::discard);
    ASSERT_TRUE(model.run_until_loaded(state));
    EXPECT_EQ(state.doc.path, other);
    EXPECT_FALSE(has_unsaved_work(state)) << "nothing typed carries over to another scene";
    EXPECT_TRUE(state.editor.shown.empty());
    EXPECT_EQ(read_file(ball), kBall);
}

TEST_F(EditorFilesTest, SavingAPanelEditSaysWhichFilesWereWritten) {
    write(ball, kBall);
    open();
    ASSERT_TRUE(state.doc.loaded) << format_diagnostics(state.doc);
    edit_scene(state, [](Scene& s) {
        shape_as<Sphere>(s.primitives[0].shape).radius = 1.5;
        s.lights[0].position.x = 2;
    });
    ASSERT_TRUE(save_scene(state)) << state.message;
    EXPECT_EQ(state.message, "Saved " + main.string() + " and parts/ball.jts");
    // Its own write reloads nothing (which would say "Reloaded" instead).
    model.frame(state);
    model.run_until_loaded(state);
    EXPECT_EQ(state.message, "Saved " + main.string() + " and parts/ball.jts");
    EXPECT_EQ(listed_names({"a", "b", "c"}), "a, b and c");
}

TEST_F(EditorFilesTest, APanelEditOfAnIncludedValueIsOneUndoStepAndSavesOnlyItsFile) {
    write(ball, kBall);
    open();
    ASSERT_TRUE(state.doc.loaded) << format_diagnostics(state.doc);
    edit_scene(state, [](Scene& s) { shape_as<Sphere>(s.primitives[0].shape).radius = 1.5; });
    undo(state);
    EXPECT_EQ(radius_of(state, 0), 1.0);
    EXPECT_FALSE(has_unsaved_work(state));
    redo(state);
    EXPECT_EQ(radius_of(state, 0), 1.5);
    const auto main_stamp = file_stamp(main);
    ASSERT_TRUE(save_scene(state)) << state.message;
    EXPECT_EQ(state.message, "Saved parts/ball.jts");
    EXPECT_EQ(read_file(ball), "sphere { center: <0, 0, -5>; radius: 1.5; }\n");
    EXPECT_TRUE(file_stamp(main) == main_stamp) << "the scene file was not written";
    model.frame(state);
    EXPECT_EQ(state.message, "Saved parts/ball.jts");
    // Undone after the save: one step back, unsaved again.
    undo(state);
    EXPECT_EQ(radius_of(state, 0), 1.0);
    EXPECT_TRUE(has_unsaved_work(state));
}

TEST_F(EditorFilesTest, APanelEditAndTypedTextAreSavedTogether) {
    write(ball, kBall);
    open();
    const std::string file = canonical_of(state.doc, "parts/ball.jts");
    edit_scene(state, [](Scene& s) { s.lights[0].position.x = 2; });
    show_file(state.editor, state.doc, file);
    const std::string typed = "sphere { center: <0, 0, -5>; radius: 2.5; }\n";
    type_included_text(state.editor, state.doc, typed);
    ASSERT_TRUE(save_scene(state)) << state.message;
    EXPECT_EQ(state.message, "Saved " + main.string() + " and parts/ball.jts");
    EXPECT_EQ(read_file(ball), typed);
    EXPECT_NE(read_file(main).find("position: <2, 5, 4>"), std::string::npos) << read_file(main);
    EXPECT_EQ(radius_of(state, 0), 2.5);
    EXPECT_EQ(state.doc.scene.lights[0].position.x, 2.0);
}

TEST_F(EditorFilesTest, AValueFromAnIncludedFileNamesItAndHowOftenItIsRead) {
    write(ball, kBall);
    write(lamp, "sphere { center: <2, 0, -5>; radius: 1; }\n");
    open(kHead +
         "scene { include \"parts/ball.jts\"; include \"parts/lamp.jts\";\n"
         "        include \"parts/ball.jts\"; include \"parts/ball.jts\";\n"
         "        sphere { radius: 2; } }\n");
    ASSERT_TRUE(state.doc.loaded) << format_diagnostics(state.doc);
    const auto block = [&](std::size_t i) {
        return block_source(state.doc, EditedBlock{EditedBlock::Kind::primitive, i});
    };
    std::array<char, 256> buffer{};
    for (std::size_t i : {0u, 2u, 3u}) {
        const SharedText shared = shared_text(state.doc, block(i));
        EXPECT_EQ(shared.name, "parts/ball.jts");
        EXPECT_EQ(shared.readings, 3);
        EXPECT_EQ(shared_text_note(shared, buffer),
                  "in parts/ball.jts (included 3 times): an edit changes every object read "
                  "from it");
    }
    // Included once: only where it is.
    EXPECT_EQ(shared_text(state.doc, block(1)).readings, 1);
    EXPECT_EQ(shared_text_note(shared_text(state.doc, block(1)), buffer), "in parts/lamp.jts");
    // In the scene file: nothing to say.
    EXPECT_EQ(shared_text(state.doc, block(4)).readings, 0);
    EXPECT_TRUE(shared_text_note(shared_text(state.doc, block(4)), buffer).empty());
    // A cut note still ends in its buffer.
    std::array<char, 8> small{};
    EXPECT_EQ(shared_text_note(shared_text(state.doc, block(0)), small), "in part");
}

// An open asked over unsaved work, answered Discard, that fails leaves the
// file shown with its own edits, and with the text typed in its included
// files too: not half of the edits.
TEST_F(EditorFilesTest, AFailedOpenKeepsTheTextTypedInIncludedFiles) {
    write(ball, kBall);
    open();
    ASSERT_TRUE(state.doc.loaded) << format_diagnostics(state.doc);
    const std::string file = canonical_of(state.doc, "parts/ball.jts");
    show_file(state.editor, state.doc, file);
    type_included_text(state.editor, state.doc, "sphere { center: <0, 0, -5>; radius: 2; }\n");
    edit_scene(state, [](Scene& s) { s.settings.width = 40; });
    ASSERT_TRUE(has_included_drafts(state.editor));
    const fs::path other = scratch.path() / "other.jts";
    write(other, "render_settings {\n    width: 64\n}\n");
    request_open_guarded(state, other);
    ASSERT_TRUE(state.files.unsaved_prompt);
    resolve_unsaved(state, UnsavedChoice::discard);
    state.files.loader.wait();
    take_finished_load(state);
    ASSERT_EQ(state.doc.path, main) << state.message;
    EXPECT_TRUE(scene_edited(state.doc)) << "the main file's edit stays";
    EXPECT_TRUE(has_included_drafts(state.editor))
        << "so does the included file's: " << state.message;
}

}  // namespace
}  // namespace jt::view
