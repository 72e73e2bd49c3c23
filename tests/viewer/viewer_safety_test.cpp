// Faults users met in the viewer, each through the OSMesa frame code as a user meets
// them: the crash after Copy to scene + undo, a drag that jumps, diagnostics
// that lag behind an edit, prompts that say the wrong thing, edits lost on
// quit, files overwritten without asking, clipped or unexplained controls.

#include "app/headless.hpp"
#include "app/keys.hpp"
#include "app/panels/panels.hpp"
#include "app/viewer_frame.hpp"
#include "common/files.hpp"
#include "jtracer/parser.hpp"
#include "jtracer/scene_file.hpp"
#include "jtracer/validate.hpp"
#include "model/app_actions.hpp"
#include "viewer/viewer_test_files.hpp"

#include <gtest/gtest.h>
#include <imgui.h>
#include <glm/geometric.hpp>

#include <chrono>
#include <thread>

namespace jt::view {
namespace {

using namespace jt::test;
namespace fs = std::filesystem;

std::string replaced_text(std::string text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

class ViewerSafety : public ::testing::Test {
  protected:
    void SetUp() override {
        ASSERT_TRUE(viewer.ok()) << viewer.error();
        file = scene_copy(::testing::UnitTest::GetInstance()->current_test_info()->name());
    }
    void TearDown() override { fs::remove_all(file.parent_path()); }

    // The middle of the image area (right of the panel, above the status line).
    ImVec2 image_centre() const {
        const UiItem* panel = find_item(viewer.ui_items(), "panel");
        const float x0 = panel ? panel->rect.x1 : 0.0f;
        return ImVec2((x0 + viewer.width()) * 0.5f, viewer.height() * 0.4f);
    }
    void open_and_render() {
        open_scene(state, file);
        ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    }

    HeadlessViewer viewer{960, 640};
    AppState state{test_config()};
    fs::path file;
};

// The crash: the camera panel indexed the camera list with an index that undo
// had left past its end (the copied camera was the last one).
TEST_F(ViewerSafety, CopyToSceneThenUndoKeepsTheViewOnACameraThatExists) {
    open_and_render();
    for (bool by_button : {false, true}) {
        const ImVec2 c = image_centre();
        viewer.drag(state, 0, c.x, c.y, c.x + 40, c.y + 10);
        ASSERT_TRUE(state.view.free_camera_active);
        state.fields.new_camera_name = by_button ? "by_button" : "by_key";
        viewer.frame(state);
        ASSERT_TRUE(viewer.click(state, "Copy to scene"));
        ASSERT_EQ(state.doc.scene.cameras.size(), 3u) << state.message;
        EXPECT_EQ(state.view.camera_index, 2);
        if (by_button)
            ASSERT_TRUE(viewer.click(state, "Undo"));
        else
            viewer.press_key(state, keys::letter('Z'), /*ctrl=*/true);
        ASSERT_EQ(state.doc.scene.cameras.size(), 2u);
        EXPECT_GE(state.view.camera_index, 0);
        EXPECT_LT(state.view.camera_index, 2);
        for (int i = 0; i < 3; ++i) viewer.frame(state);
        // Redo brings the camera back, and the view can show it again.
        viewer.press_key(state, keys::letter('Z'), /*ctrl=*/true, /*shift=*/true);
        ASSERT_EQ(state.doc.scene.cameras.size(), 3u);
        select_camera(state, 2);
        viewer.press_key(state, keys::letter('Z'), /*ctrl=*/true);
        EXPECT_LT(state.view.camera_index, 2);
        ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
        // Nothing is left to undo for the next round but the scene as loaded.
        while (state.history.undo.can_undo()) undo(state);
        EXPECT_EQ(state.doc.scene, *state.doc.original);
        viewer.frame(state);
    }
}

// The same pattern elsewhere: a reload or a scripted edit that removes the
// selected camera leaves the view on one that exists, named the same if it can.
TEST_F(ViewerSafety, ReplacingTheSceneKeepsTheSelectedCameraByName) {
    open_and_render();
    select_camera(state, 1);  // "top"
    edit_scene(state, [](Scene& s) { s.cameras.erase(s.cameras.begin()); });
    EXPECT_EQ(state.view.camera_index, 0);
    EXPECT_EQ(state.doc.scene.cameras[0].name, "top");
    undo(state);
    EXPECT_EQ(state.view.camera_index, 1) << "still \"top\"";
    edit_scene(state, [](Scene& s) { s.cameras.resize(1); });
    EXPECT_EQ(state.view.camera_index, 0);
    for (int i = 0; i < 3; ++i) viewer.frame(state);
}

// A press right after moving onto the image used the whole move since the
// last frame as the first drag step: the camera jumped.
TEST_F(ViewerSafety, ADragMovesTheCameraOnlyByTheMotionAfterThePress) {
    open_and_render();
    ImGuiIO& io = ImGui::GetIO();
    viewer.move_mouse(state, 20, 20);  // over the panel
    const ImVec2 c = image_centre();
    // In one frame the mouse arrives on the image and the button goes down.
    io.MousePos = c;
    io.MouseDown[0] = true;
    viewer.frame(state);
    const FreeCamera start = free_camera_from(state.doc.scene.cameras[0]);
    EXPECT_FALSE(state.view.free_camera_active) << "no motion since the press yet";
    io.MousePos = ImVec2(c.x + 8, c.y);
    viewer.frame(state);
    io.MouseDown[0] = false;
    viewer.frame(state);
    ASSERT_TRUE(state.view.free_camera_active);
    const double moved = glm::length(state.view.free_camera.position - start.position);
    const double distance = glm::length(start.position - start.look_at);
    // 8 pixels of a view several hundred pixels high: a few degrees, not a jump.
    EXPECT_GT(moved, 0.0);
    EXPECT_LT(moved, distance * 0.2) << "the camera jumped";

    // A drag that starts on the panel never moves the camera.
    state.view.free_camera_active = false;
    viewer.drag(state, 0, 20, 300, c.x, c.y);
    EXPECT_FALSE(state.view.free_camera_active);
}

// After a live width change the Diagnostics panel says what --check says.
TEST_F(ViewerSafety, DiagnosticsFollowEveryEditAsCheckWould) {
    open_and_render();
    EXPECT_TRUE(state.doc.diagnostics.empty());
    edit_scene(state, [](Scene& s) { s.settings.width = 32; });
    viewer.frame(state);
    ASSERT_FALSE(state.doc.diagnostics.empty()) << "the aspect no longer matches";
    // What jtracer-cli --check says about the same values, written to a file.
    state.fields.save_scene_path = (file.parent_path() / "checked.jts").string();
    viewer.frame(state);
    ASSERT_TRUE(viewer.click(state, "Save scene as"));
    Expected<LoadedScene> loaded = jt::load_scene_file(file.parent_path() / "checked.jts");
    ASSERT_TRUE(loaded);
    const std::vector<Diagnostic> check = check_scene(*loaded);
    ASSERT_EQ(check.size(), state.doc.diagnostics.size());
    for (std::size_t i = 0; i < check.size(); ++i) {
        EXPECT_EQ(check[i].message, state.doc.diagnostics[i].message);
        EXPECT_EQ(check[i].pos.line, state.doc.diagnostics[i].pos.line);
    }
    undo(state);
    viewer.frame(state);
    EXPECT_TRUE(state.doc.diagnostics.empty()) << "undone: nothing to warn about";
}

TEST_F(ViewerSafety, ReloadPromptSaysWhetherTheFileChanged) {
    open_and_render();
    edit_scene(state, [](Scene& s) { s.settings.width = 32; });  // an aspect warning
    viewer.frame(state);
    const std::vector<Diagnostic> live = state.doc.diagnostics;
    ASSERT_FALSE(live.empty());
    viewer.press_key(state, keys::letter('R'));
    ASSERT_TRUE(viewer.run_until_loaded(state));
    ASSERT_TRUE(state.files.pending_reload);
    EXPECT_NE(state.message.find("unchanged"), std::string::npos) << state.message;
    EXPECT_EQ(state.message.find("was reloaded"), std::string::npos) << state.message;
    viewer.frame(state);
    EXPECT_EQ(state.doc.diagnostics.size(), live.size()) << "still about the edited scene";
    EXPECT_EQ(find_item(viewer.ui_items(), "Reload, re-apply my edits"), nullptr);
    for (const char* choice : {"Reload, drop my edits", "Keep mine"}) {
        const UiItem* item = find_item(viewer.ui_items(), choice);
        ASSERT_NE(item, nullptr) << choice;
        EXPECT_FALSE(item->clipped) << choice;
    }
    ASSERT_TRUE(viewer.click(state, "Keep mine"));
    write_file(file, read_file(file) + "\n# theirs\n");
    ASSERT_TRUE(viewer.run_until_loaded(state));
    ASSERT_TRUE(state.files.pending_reload);
    EXPECT_NE(state.message.find("changed on disk"), std::string::npos) << state.message;
    viewer.frame(state);
    EXPECT_NE(find_item(viewer.ui_items(), "Reload, re-apply my edits"), nullptr);
}

TEST_F(ViewerSafety, ABrokenFileAtStartUpIsQuotedWithItsLineAndCaret) {
    write_file(file, "render_settings {\n    width: 64;\n    height: 48\n}\n");
    open_scene(state, file);
    viewer.frame(state);
    EXPECT_EQ(state.message.find("Could not open"), std::string::npos) << state.message;
    EXPECT_NE(state.message.find("has errors"), std::string::npos) << state.message;
    const std::string shown = format_diagnostics(state.doc);
    EXPECT_NE(shown.find("    height: 48"), std::string::npos) << shown;
    EXPECT_NE(shown.find('^'), std::string::npos) << shown;
    // A file that cannot be read says so.
    open_scene(state, file.parent_path() / "missing.jts");
    EXPECT_NE(state.message.find("Could not open"), std::string::npos) << state.message;
}

TEST_F(ViewerSafety, EscapeClosesWhatIsOpenAndNeverDropsEdits) {
    open_and_render();
    // Without edits a stray Esc (one more after leaving a field or closing
    // a popup) does not close the window and its render: it says how to
    // quit, and a second Esc right after quits.
    AppState clean{test_config()};
    open_scene(clean, file);
    viewer.frame(clean);
    viewer.press_key(clean, keys::escape);
    EXPECT_FALSE(clean.quit);
    EXPECT_EQ(clean.message, "Esc again quits (Ctrl+Q quits at once)");
    viewer.press_key(clean, keys::escape);
    EXPECT_TRUE(clean.quit);
    // Not two Esc far apart.
    clean.quit = false;
    viewer.press_key(clean, keys::escape);
    for (int i = 0; i < 90; ++i) viewer.frame(clean);  // three seconds
    viewer.press_key(clean, keys::escape);
    EXPECT_FALSE(clean.quit);
    viewer.press_key(clean, keys::escape);
    EXPECT_TRUE(clean.quit);
    viewer.frame(state);

    edit_scene(state, [](Scene& s) { s.settings.recurse_depth = 1; });
    // A combo open: Esc closes it and nothing else.
    viewer.frame(state);
    ASSERT_TRUE(viewer.click(state, "View"));
    ASSERT_TRUE(ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId));
    viewer.press_key(state, keys::escape);
    EXPECT_FALSE(ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId));
    EXPECT_FALSE(state.quit);
    EXPECT_FALSE(state.files.unsaved_prompt);
    // Typing in a field: Esc leaves the field.
    ASSERT_TRUE(viewer.click(state, "camera name"));
    ASSERT_TRUE(ImGui::GetIO().WantTextInput);
    viewer.press_key(state, keys::escape);
    EXPECT_FALSE(state.quit);
    EXPECT_FALSE(state.files.unsaved_prompt);
    // Nothing open: Esc asks, a second Esc cancels.
    viewer.press_key(state, keys::escape);
    EXPECT_FALSE(state.quit);
    ASSERT_TRUE(state.files.unsaved_prompt);
    viewer.press_key(state, keys::escape);
    EXPECT_FALSE(state.files.unsaved_prompt);
    EXPECT_FALSE(state.quit);
    EXPECT_TRUE(has_unsaved_edits(state.doc));
    // Ctrl+Q asks too; Save writes the edits, then quits.
    viewer.press_key(state, keys::letter('Q'), /*ctrl=*/true);
    ASSERT_TRUE(state.files.unsaved_prompt);
    viewer.frame(state);
    ASSERT_TRUE(viewer.click(state, "Save"));
    EXPECT_TRUE(state.quit);
    ParseResult saved = parse_scene(read_file(file));
    ASSERT_TRUE(saved.ok());
    EXPECT_EQ(saved.scene.settings.recurse_depth, 1);
}

TEST_F(ViewerSafety, OpeningAnotherFileWithEditsAsksAndDiscardOpensIt) {
    open_and_render();
    const fs::path other = file.parent_path() / "other.jts";
    fs::copy_file(file, other);
    edit_scene(state, [](Scene& s) { s.settings.recurse_depth = 1; });
    request_open_guarded(state, other);  // as Open, Recent and a dropped file do
    viewer.frame(state);
    ASSERT_TRUE(state.files.unsaved_prompt);
    ASSERT_TRUE(viewer.click(state, "Cancel"));
    EXPECT_EQ(state.doc.path, file);
    EXPECT_EQ(state.doc.scene.settings.recurse_depth, 1);
    request_open_guarded(state, other);
    viewer.frame(state);
    ASSERT_TRUE(viewer.click(state, "Discard"));
    ASSERT_TRUE(viewer.run_until_loaded(state));
    EXPECT_EQ(state.doc.path, other);
    EXPECT_EQ(read_file(file), read_file(kScene)) << "discarded, not saved";
}

// The prompt wrapped its buttons to the width of the hidden frame that
// measured it: its first drawn frame was a row taller and 25 pixels higher
// than the next, and a click on Discard as first shown hit its text.
TEST_F(ViewerSafety, TheUnsavedPromptIsFirstDrawnWhereItStays) {
    open_and_render();
    edit_scene(state, [](Scene& s) { s.settings.recurse_depth = 1; });
    request_quit(state);
    viewer.frame(state);
    const UiItem* shown = find_item(viewer.ui_items(), "Discard");
    if (shown && !shown->drawn) {
        viewer.frame(state);
        shown = find_item(viewer.ui_items(), "Discard");
    }
    ASSERT_TRUE(shown && shown->drawn);
    const ScreenRect first = shown->rect;
    viewer.frame(state);
    const UiItem* now = find_item(viewer.ui_items(), "Discard");
    ASSERT_TRUE(now);
    EXPECT_EQ(now->rect.y0, first.y0) << "the prompt moved after it was first drawn";
    EXPECT_EQ(now->rect.x0, first.x0);
    // Where the user saw it.
    viewer.press_mouse(state, 0, (first.x0 + first.x1) * 0.5f, (first.y0 + first.y1) * 0.5f);
    viewer.release_mouse(state, 0);
    EXPECT_TRUE(state.quit) << "Discard, as first drawn, answered the prompt";
}

TEST_F(ViewerSafety, ImageSavesNeverReplaceAFile) {
    open_and_render();
    const fs::path png = file.parent_path() / "view.png";
    write_file(png, "someone else's picture");
    state.fields.save_image_path = png.string();
    viewer.press_key(state, keys::letter('S'));
    viewer.press_key(state, keys::letter('S'));
    EXPECT_EQ(read_file(png), "someone else's picture");
    const std::string first = read_file(file.parent_path() / "view-001.png");
    EXPECT_EQ(first.substr(0, 4), "\x89PNG");
    EXPECT_TRUE(fs::exists(file.parent_path() / "view-002.png"));
    EXPECT_NE(state.message.find("view-002.png"), std::string::npos) << state.message;
    for (const auto& entry : fs::directory_iterator(file.parent_path()))
        EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << entry.path();
}

TEST_F(ViewerSafety, SaveSceneAsAsksBeforeReplacingAndThenEditsTheNewFile) {
    open_and_render();
    edit_scene(state, [](Scene& s) { s.settings.recurse_depth = 1; });
    const fs::path copy = file.parent_path() / "copy.jts";
    write_file(copy, "# precious\n");
    state.fields.save_scene_path = copy.string();
    viewer.frame(state);
    ASSERT_TRUE(viewer.click(state, "Save scene as"));
    EXPECT_EQ(read_file(copy), "# precious\n");
    EXPECT_FALSE(state.files.save_as_conflict.empty());
    ASSERT_TRUE(viewer.click(state, "Replace it"));
    EXPECT_EQ(state.doc.path, copy);
    EXPECT_FALSE(has_unsaved_edits(state.doc));
    ParseResult saved = parse_scene(read_file(copy));
    ASSERT_TRUE(saved.ok());
    EXPECT_EQ(saved.scene, state.doc.scene);
    EXPECT_EQ(read_file(file), read_file(kScene)) << "the first file is untouched";
}

// Found in the window: with the question "copy.jts exists." up, the user
// typed another path into the field, and Replace it wrote over that file,
// which nobody had asked about. Replace it writes the file it names.
TEST_F(ViewerSafety, ReplaceItWritesOnlyTheFileItAskedAbout) {
    open_and_render();
    edit_scene(state, [](Scene& s) { s.settings.recurse_depth = 1; });
    const fs::path asked = file.parent_path() / "copy.jts";
    const fs::path other = file.parent_path() / "other.jts";
    write_file(asked, "# asked about\n");
    write_file(other, "# precious\n");
    state.fields.save_scene_path = asked.string();
    viewer.frame(state);
    ASSERT_TRUE(viewer.click(state, "Save scene as"));
    ASSERT_EQ(state.files.save_as_conflict, asked.string());
    state.fields.save_scene_path = other.string();  // typed while the question is up
    viewer.frame(state);
    ASSERT_TRUE(viewer.click(state, "Replace it"));
    EXPECT_EQ(read_file(other), "# precious\n") << "replaced without a question";
    EXPECT_EQ(state.doc.path, asked);
    ParseResult saved = parse_scene(read_file(asked));
    ASSERT_TRUE(saved.ok());
    EXPECT_EQ(saved.scene, state.doc.scene);
}

TEST_F(ViewerSafety, StatusAndTitleNameThePassTheTimesAndPausing) {
    open_scene(state, file);
    edit_scene(state, [](Scene& s) { s.settings.samples = 1; });
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    EXPECT_NE(window_title(state).find("done, 1 sample,"), std::string::npos)
        << window_title(state);
    EXPECT_NE(render_status(state).find("done: 1 sample in"), std::string::npos)
        << render_status(state);
    edit_scene(state, [](Scene& s) { s.settings.samples = 4; });
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    EXPECT_NE(window_title(state).find("done, 4 samples,"), std::string::npos)
        << window_title(state);
    const std::string done = render_status(state);
    EXPECT_NE(done.find("done: 4 samples in"), std::string::npos) << done;
    EXPECT_NE(done.find("Mrays/s"), std::string::npos) << done;
    viewer.press_key(state, keys::space);
    // Paused when done: nothing is left to resume, only edits to hold back.
    EXPECT_NE(render_status(state).find("done: 4 samples, paused | edits wait for Space"),
              std::string::npos)
        << render_status(state);
    EXPECT_EQ(render_status(state).find("paused at"), std::string::npos) << render_status(state);
    EXPECT_NE(window_title(state).find("paused"), std::string::npos) << window_title(state);
    edit_scene(state, [](Scene& s) { s.settings.recurse_depth = 1; });
    viewer.frame(state);
    EXPECT_NE(render_status(state).find("edit waiting"), std::string::npos) << render_status(state);
    EXPECT_NE(window_title(state).find("edit waiting"), std::string::npos) << window_title(state);
    viewer.press_key(state, keys::space);
    // Until its first pass the render is "preparing the scene", however long
    // a loaded machine takes to get there: wait for the pass, not for time.
    const auto deadline = std::chrono::steady_clock::now() + kTimeout;
    while (state.render.renderer.progress().pass_count == 0 && !render_complete(state.render) &&
           std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        viewer.frame(state);
    }
    const std::string running = render_status(state);
    EXPECT_TRUE(running.find("preview") == 0 || running.find("full resolution") == 0 ||
                running.find("sample ") == 0 || running.find("done") == 0)
        << running;
}

// Numbers the UI made are written short (an orbited camera as -2.23547, not
// -2.2354736889656803), and a field edit of one component of a vector leaves
// the other components' text as written.
TEST_F(ViewerSafety, SavedNumbersAreShortAndOneComponentEditsKeepTheRestAsWritten) {
    write_file(file, replaced_text(read_file(file), "point_light { position: <3, 5, 4>;",
                                   "point_light { position: <3.0, 5.0, 4.0>;"));
    open_and_render();
    const ImVec2 c = image_centre();
    viewer.drag(state, 0, c.x, c.y, c.x + 37, c.y + 11);
    ASSERT_TRUE(state.view.free_camera_active);
    state.fields.new_camera_name = "kept";
    viewer.frame(state);
    ASSERT_TRUE(viewer.click(state, "Copy to scene"));
    // The light's position field: a drag on its first third changes x alone.
    // (Render settings and Camera closed first, so that the field is inside the window.)
    // Camera first: its fields may reach past the window's bottom, and Render
    // settings' header with them.
    ASSERT_TRUE(viewer.click(state, "Camera"));  // its scene camera's fields, too
    ASSERT_TRUE(viewer.click(state, "Render settings"));
    ASSERT_TRUE(viewer.click(state, "Lights"));
    ASSERT_TRUE(viewer.click(state, "point_light 1"));
    viewer.frame(state);
    const UiItem* light = nullptr;
    for (const UiItem& item : viewer.ui_items())
        if (item.label == "position") light = &item;  // the last: the light's
    ASSERT_NE(light, nullptr);
    ASSERT_LT(light->rect.y1, find_item(viewer.ui_items(), "panel")->rect.y1);
    const float x = light->rect.x0 + (light->rect.x1 - light->rect.x0) * 0.15f;
    const float y = (light->rect.y0 + light->rect.y1) * 0.5f;
    viewer.drag(state, 0, x, y, x + 30, y);
    ASSERT_NE(state.doc.scene.lights[0].position.x, 3.0) << "the drag changed x";
    ASSERT_EQ(state.doc.scene.lights[0].position.y, 5.0);
    viewer.press_key(state, keys::letter('S'), /*ctrl=*/true);
    ASSERT_FALSE(has_unsaved_edits(state.doc)) << state.message;
    const std::string text = read_file(file);
    EXPECT_NE(text.find(", 5.0, 4.0>;"), std::string::npos) << text;
    // The orbited position has at most 6 significant digits a number (the
    // aspect and fov are the scene camera's, copied as written).
    const std::size_t block = text.find("name: \"kept\"");
    ASSERT_NE(block, std::string::npos) << text;
    const std::size_t at = text.find("position:", block);
    ASSERT_NE(at, std::string::npos) << text;
    const std::string camera = text.substr(at, text.find('\n', at) - at);
    int numbers = 0;
    for (std::size_t i = 0; i < camera.size();) {
        if (!std::isdigit(static_cast<unsigned char>(camera[i]))) {
            ++i;
            continue;
        }
        int digits = 0;
        bool leading = true;
        for (; i < camera.size() &&
               (std::isdigit(static_cast<unsigned char>(camera[i])) || camera[i] == '.');
             ++i) {
            if (camera[i] == '.') continue;
            if (leading && camera[i] == '0') continue;
            leading = false;
            ++digits;
        }
        ++numbers;
        EXPECT_LE(digits, 6) << camera;
    }
    EXPECT_EQ(numbers, 3) << camera;
    ParseResult saved = parse_scene(text);
    ASSERT_TRUE(saved.ok());
    EXPECT_EQ(saved.scene, state.doc.scene);
}

// Every control of every panel, opened, at the smallest supported window and
// at 2x: nothing runs past the panel's edge, every disabled control says why.
void expect_nothing_clipped(HeadlessViewer& viewer, AppState& state, const char* what) {
    viewer.frame(state);
    for (const char* header : {"Objects", "Lights", "Diagnostics", "Help"}) {
        ASSERT_TRUE(viewer.click(state, header)) << header;
    }
    for (const char* node : {"sphere 2", "point_light 1"}) viewer.click(state, node);
    for (int i = 0; i < 3; ++i) viewer.frame(state);
    int visible = 0;
    for (const UiItem& item : viewer.ui_items()) {
        EXPECT_FALSE(item.clipped)
            << what << ": " << item.label << " is cut off at x " << item.rect.x1;
        if (!item.enabled) {
            EXPECT_TRUE(item.has_tooltip) << what << ": " << item.label;
        }
        visible += item.rect.y1 < viewer.height();
    }
    EXPECT_GT(visible, 10);
}

TEST(ViewerLayout, NothingIsClippedAt1280x720) {
    HeadlessViewer viewer(1280, 720);
    ASSERT_TRUE(viewer.ok());
    AppState state{test_config()};
    open_scene(state, fs::path(JT_SOURCE_DIR) / "scenes" / "showcase.jts");
    edit_scene(state, [](Scene& s) { s.settings.width = 64; });  // a warning to show
    expect_nothing_clipped(viewer, state, "1280x720");
    // The image keeps room beside the panel.
    const UiItem* panel = find_item(viewer.ui_items(), "panel");
    ASSERT_NE(panel, nullptr);
    EXPECT_LT(panel->rect.x1, 1280 * 0.5f);
}

TEST(ViewerLayout, NothingIsClippedAtTwiceTheScale) {
    HeadlessViewer viewer(2560, 1440);  // 1280x720 at Xft.dpi 192
    ASSERT_TRUE(viewer.ok());
    viewer.set_content_scale(2.0f);
    AppState state{test_config()};
    open_scene(state, fs::path(JT_SOURCE_DIR) / "scenes" / "showcase.jts");
    expect_nothing_clipped(viewer, state, "2x");
    EXPECT_GE(ImGui::GetFontSize(), 28.0f) << "the font follows the scale";
    const UiItem* panel = find_item(viewer.ui_items(), "panel");
    ASSERT_NE(panel, nullptr);
    EXPECT_LT(panel->rect.x1, 2560 * 0.5f);
}

// At a small window on a 2x screen the image's toolbar
// covered a third of the image; it keeps to one short row there.
TEST(ViewerLayout, TheToolbarLeavesASmallImageMostlyUncovered) {
    HeadlessViewer viewer(1400, 900);  // 700x450 window units at 2x, as found
    ASSERT_TRUE(viewer.ok());
    viewer.set_framebuffer_scale(2.0f);
    viewer.set_content_scale(2.0f);
    AppState state{test_config()};
    open_scene(state, kScene);
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    const UiItem* toolbar = find_item(viewer.ui_items(), "image toolbar");
    ASSERT_NE(toolbar, nullptr);
    const ScreenRect image = viewer.image_rect();
    const float covered =
        std::max(0.0f,
                 std::min(toolbar->rect.x1, image.x1) - std::max(toolbar->rect.x0, image.x0)) *
        std::max(0.0f, std::min(toolbar->rect.y1, image.y1) - std::max(toolbar->rect.y0, image.y0));
    EXPECT_LT(covered, 0.12f * image.width() * image.height())
        << "the toolbar covers " << covered / (image.width() * image.height()) << " of the image";
    EXPECT_TRUE(find_item(viewer.ui_items(), "More") || find_item(viewer.ui_items(), "Image"))
        << "the rest is a click away";
}

// The part of `r` inside `clip`.
ScreenRect intersection(const ScreenRect& r, const ScreenRect& clip) {
    ScreenRect out{std::max(r.x0, clip.x0), std::max(r.y0, clip.y0), std::min(r.x1, clip.x1),
                   std::min(r.y1, clip.y1)};
    if (out.x1 < out.x0) out.x1 = out.x0;
    if (out.y1 < out.y0) out.y1 = out.y0;
    return out;
}

// On X11 at Xft.dpi 192 (content scale 2, one framebuffer
// pixel a window unit), in the smallest window (800x520), the image zoomed to
// fill its area and the mouse over it: the toolbar ran past the window's edge
// (its zoom and More out of reach), and it and the pixel inspector (wider
// than the image, over the panel too) covered 37% of the image.
TEST(ViewerLayout, OverlaysLeaveAZoomedImageMostlyUncoveredAtTwiceTheScale) {
    HeadlessViewer viewer(800, 520);
    ASSERT_TRUE(viewer.ok());
    viewer.set_content_scale(2.0f);
    AppState state{test_config()};
    open_scene(state, kScene);
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    const ScreenRect area = viewer.image_area();
    const float cx = (area.x0 + area.x1) * 0.5f, cy = (area.y0 + area.y1) * 0.5f;
    viewer.scroll(state, cx, cy, 8.0f, true);
    const ScreenRect shown = intersection(viewer.image_rect(), area);
    ASSERT_GT(shown.width() * shown.height(), 0.95f * area.width() * area.height())
        << "the image fills its area";
    viewer.move_mouse(state, cx, cy);
    viewer.move_mouse(state, cx, cy);
    ASSERT_FALSE(state.view.inspected.empty()) << "the mouse is over the image";

    float covered = 0.0f;
    for (const char* overlay : {"image toolbar", "pixel inspector"}) {
        const UiItem* window = find_item(viewer.ui_items(), overlay);
        if (!window) continue;
        EXPECT_LE(window->rect.x1, static_cast<float>(viewer.width())) << overlay;
        EXPECT_GE(window->rect.x0, area.x0) << overlay << " stays off the panel";
        const ScreenRect over = intersection(window->rect, shown);
        covered += over.width() * over.height();
    }
    const float fraction = covered / (shown.width() * shown.height());
    EXPECT_LT(fraction, 0.15f) << "the overlays cover " << fraction << " of the image";
    EXPECT_NE(state.view.inspected.find("x "), std::string::npos);
}

// A tiny window squeezed the panel and that squeezed
// width was remembered (panel_width = 14) for the next run.
TEST(ViewerLayout, ATinyWindowDoesNotChangeTheRememberedPanelWidth) {
    const fs::path folder = scene_copy("panel-width-tiny").parent_path();
    ViewerConfig config = test_config();
    config.settings_file = folder / "config" / "viewer-settings.txt";
    fs::create_directories(config.settings_file.parent_path());
    write_file(config.settings_file, "panel_width = 26\n");
    ASSERT_EQ(read_viewer_settings(config.settings_file).panel_width, 26.0f);
    HeadlessViewer viewer(301, 200);  // 0.6 of it, the squeezed panel, is no whole unit
    ASSERT_TRUE(viewer.ok());
    AppState state{config};
    open_scene(state, kScene);
    for (int i = 0; i < 4; ++i) viewer.frame(state);
    viewer.move_mouse(state, 250, 100);
    EXPECT_EQ(state.view.sidebar_width, 26.0f);
    remember_settings(state.view, state.config);
    EXPECT_EQ(read_viewer_settings(config.settings_file).panel_width, 26.0f);
    fs::remove_all(folder);
}

TEST(ViewerLayout, ThePanelEdgeDragsAndTheWidthIsRememberedAcrossRuns) {
    const fs::path folder = scene_copy("panel-width").parent_path();
    ViewerConfig config = test_config();
    config.settings_file = folder / "config" / "viewer-settings.txt";
    HeadlessViewer viewer(1280, 720);
    ASSERT_TRUE(viewer.ok());
    float edge = 0.0f, dragged_edge = 0.0f;
    {
        AppState state{config};
        open_scene(state, kScene);
        viewer.frame(state);
        viewer.frame(state);
        const UiItem* panel = find_item(viewer.ui_items(), "panel");
        ASSERT_NE(panel, nullptr);
        edge = panel->rect.x1;
        const float before = state.view.sidebar_width;
        EXPECT_EQ(before, kDefaultPanelWidth);
        viewer.drag(state, 0, edge - 1, 300, edge + 119, 300);
        EXPECT_GT(state.view.sidebar_width, before) << "dragged wider";
        viewer.frame(state);
        const UiItem* wider = find_item(viewer.ui_items(), "panel");
        ASSERT_NE(wider, nullptr);
        dragged_edge = wider->rect.x1;
        EXPECT_GT(dragged_edge, edge + 60);
        EXPECT_FALSE(state.view.free_camera_active) << "resizing is not a camera drag";
        EXPECT_EQ(read_viewer_settings(config.settings_file).panel_width, state.view.sidebar_width);
    }
    // Where the panel of a new run ends.
    const auto next_run_edge = [&] {
        AppState state{config};
        open_scene(state, kScene);
        viewer.frame(state);
        viewer.frame(state);
        const UiItem* panel = find_item(viewer.ui_items(), "panel");
        return panel ? panel->rect.x1 : -1.0f;
    };
    EXPECT_NEAR(next_run_edge(), dragged_edge, 1.0f) << "as wide as it was left";
    write_file(config.settings_file, "panel_width = 1e999\n\x01\x02");
    EXPECT_NEAR(next_run_edge(), edge, 1.0f) << "a broken file: the default width";
    fs::remove_all(folder);
}

}  // namespace
}  // namespace jt::view
