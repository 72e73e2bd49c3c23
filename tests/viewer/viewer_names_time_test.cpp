// Language 1.3 in the viewer's window (docs/language.md §15.2-§15.4), through
// the frame code under OSMesa and the program itself: --define as jtracer-cli
// reads it, fields written as a name or an expression shown read-only with
// where they come from, inherited fields edited into the object's own
// material, and the time slider, whose finished image at a clock is
// jtracer-cli --clock's, byte for byte.

#include "app/keys.hpp"
#include "common/files.hpp"
#include "common/run_program.hpp"
#include "common/scratch_dir.hpp"
#include "jtracer/png.hpp"
#include "model/app_actions.hpp"
#include "model/document_edits.hpp"
#include "model/picking.hpp"
#include "model/scene_time.hpp"
#include "viewer/viewer_fixture.hpp"

#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <filesystem>
#include <string>
#include <variant>

namespace jt::view {
namespace {

namespace fs = std::filesystem;
using namespace jt::test;

constexpr const char* kScene = R"(define r = 0.5;
material shiny { pigment: <0.9, 0.2, 0.1>; diffuse: <0.8, 0.8, 0.8>; reflection: 0.25; }
render_settings { width: 96; height: 64; samples: 2; }
cameras { perspective_camera { position: <0, 1, 6>; look_at: <0, 0.5, 0>; aspect: 1.5; fov: 40; } }
scene {
    sphere { center: <clock * 2 - 1, r, 0>; radius: r; material: shiny; }
    sphere { center: <0, -100, 0>; radius: 100; material { pigment: <0.7, 0.7, 0.7>; diffuse: <0.8, 0.8, 0.8>; } }
    point_light { position: <2, 5, 3>; intensity: <1, 1, 1>; }
}
)";

// Runs the viewer with `arguments` and no DISPLAY.
ProgramRun run_viewer(const std::vector<std::string>& arguments) {
    Command command{{"env", "-u", "DISPLAY", "-u", "WAYLAND_DISPLAY", JT_VIEWER_EXE}, {}};
    command.argv.insert(command.argv.end(), arguments.begin(), arguments.end());
    return run_program(command);
}

ProgramRun run_cli(const std::vector<std::string>& arguments) {
    Command command{{JT_CLI_EXE}, {}};
    command.argv.insert(command.argv.end(), arguments.begin(), arguments.end());
    return run_program(command);
}

class ViewerNamesCli : public ScratchTest {};

TEST_F(ViewerNamesCli, ABadDefineIsACommandLineErrorNamingTheOptionAsJtracerClisIs) {
    write_file(dir / "scene.jts", kScene);
    const std::string scene = (dir / "scene.jts").string();
    for (const char* bad : {"r", "2r=1", "pi=3", "clock=1", "r=1/0", "r=<1,2>"}) {
        const ProgramRun view =
            run_viewer({scene, "--define", bad, "--screenshot", (dir / "out.png").string()});
        const ProgramRun cli = run_cli({scene, "--define", bad, "-o", (dir / "c.png").string()});
        EXPECT_EQ(view.code, 2) << bad << view.err;
        EXPECT_EQ(cli.code, 2) << bad;
        EXPECT_NE(view.err.find("--define"), std::string::npos) << bad << view.err;
        // The same reason in both (each names its own program).
        const std::size_t reason = cli.err.find("--define");
        ASSERT_NE(reason, std::string::npos) << cli.err;
        const std::string why = cli.err.substr(reason, cli.err.find('\n', reason) - reason);
        EXPECT_NE(view.err.find(why), std::string::npos) << why << "\n" << view.err;
    }
    EXPECT_FALSE(fs::exists(dir / "out.png"));
}

TEST_F(ViewerNamesCli, TheImageWithDefineAndClockIsJtracerClisByteForByte) {
    write_file(dir / "scene.jts", kScene);
    const std::string scene = (dir / "scene.jts").string();
    const ProgramRun cli = run_cli(
        {scene, "-q", "--define", "r=0.75", "--clock", "0.25", "-o", (dir / "cli.png").string()});
    ASSERT_EQ(cli.code, 0) << cli.err;
    const ProgramRun view =
        run_viewer({scene, "--define", "r=0.75", "--clock", "0.25", "--screenshot",
                    (dir / "shot.png").string(), "--save-render", (dir / "view.png").string(),
                    "--size", "640x400"});
    ASSERT_EQ(view.code, 0) << view.err;
    EXPECT_EQ(read_file(dir / "view.png"), read_file(dir / "cli.png"));
    const ProgramRun plain = run_cli({scene, "-q", "-o", (dir / "plain.png").string()});
    ASSERT_EQ(plain.code, 0);
    EXPECT_NE(read_file(dir / "plain.png"), read_file(dir / "cli.png"))
        << "the define and the clock change the image";
}

class ViewerNamesTime : public ViewerFixture {
  protected:
    explicit ViewerNamesTime(int width = 1100, int height = 900) : ViewerFixture(width, height) {}
    void SetUp() override {
        folder = make_scratch_dir(::testing::UnitTest::GetInstance()->current_test_info()->name());
        write_file(folder / "scene.jts", kScene);
        open_rendered(folder / "scene.jts");
    }
    void TearDown() override { fs::remove_all(folder); }
    Image8 cli_image(const std::string& clock) {
        const ProgramRun cli = run_cli({(folder / "scene.jts").string(), "-q", "--clock", clock,
                                        "-o", (folder / "cli.png").string()});
        EXPECT_EQ(cli.code, 0) << cli.err;
        Expected<Image8> image = read_png(folder / "cli.png");
        EXPECT_TRUE(image);
        return image ? *image : Image8{};
    }
    fs::path folder;
};

TEST_F(ViewerNamesTime, ANameOrAnExpressionIsShownReadOnlyWithWhatItIsComputedFrom) {
    ASSERT_FALSE(HasFatalFailure());
    select(state.view, {Selection::Kind::primitive, 0});
    for (int i = 0; i < 4; ++i) viewer.frame(state);
    const UiItem* radius = find_item(viewer.ui_items(), "radius");
    const UiItem* center = find_item(viewer.ui_items(), "center");
    ASSERT_NE(radius, nullptr);
    ASSERT_NE(center, nullptr);
    EXPECT_FALSE(radius->enabled) << "written as the name r";
    EXPECT_FALSE(center->enabled) << "written as an expression";
    EXPECT_NE(find_item(viewer.ui_items(), "= r"), nullptr);
    EXPECT_NE(find_item(viewer.ui_items(), "= <clock * 2 - 1, r, 0>"), nullptr);
    const UiItem* reflection = find_item(viewer.ui_items(), "reflection");
    ASSERT_NE(reflection, nullptr);
    EXPECT_TRUE(reflection->enabled) << "inherited from shiny: editable";
    const std::string before = document_text(state.doc);
    // A click and a typed value reach no read-only field.
    viewer.press_mouse(state, 0, (radius->rect.x0 + radius->rect.x1) * 0.5f,
                       (radius->rect.y0 + radius->rect.y1) * 0.5f, kCtrl);
    viewer.release_mouse(state, 0);
    viewer.frame(state);
    for (char c : std::string("3")) ImGui::GetIO().AddInputCharacter(c);
    viewer.frame(state);
    viewer.press_key(state, keys::enter);
    viewer.frame(state);
    EXPECT_EQ(shape_as<Sphere>(state.doc.scene.primitives[0].shape).radius, 0.5);
    EXPECT_EQ(document_text(state.doc), before);
}

TEST_F(ViewerNamesTime, AnInheritedFieldEditedInThePanelGoesIntoTheObjectsOwnMaterial) {
    ASSERT_FALSE(HasFatalFailure());
    select(state.view, {Selection::Kind::primitive, 0});
    for (int i = 0; i < 4; ++i) viewer.frame(state);
    const UiItem* reflection = find_item(viewer.ui_items(), "reflection");
    ASSERT_NE(reflection, nullptr);
    const std::size_t steps = state.history.undo.size();
    viewer.press_mouse(state, 0, (reflection->rect.x0 + reflection->rect.x1) * 0.5f - 40.0f,
                       (reflection->rect.y0 + reflection->rect.y1) * 0.5f, kCtrl);
    viewer.release_mouse(state, 0);
    viewer.frame(state);
    ImGui::GetIO().AddInputCharacter('0');
    ImGui::GetIO().AddInputCharacter('.');
    ImGui::GetIO().AddInputCharacter('5');
    viewer.frame(state);
    viewer.press_key(state, keys::enter);
    for (int i = 0; i < 3; ++i) viewer.frame(state);
    EXPECT_EQ(state.doc.scene.primitives[0].material.finish->reflection, 0.5);
    const std::string text = document_text(state.doc);
    EXPECT_NE(text.find("material shiny { pigment: <0.9, 0.2, 0.1>; diffuse: <0.8, 0.8, 0.8>; "
                        "reflection: 0.25; }"),
              std::string::npos)
        << "the shared material is untouched:\n"
        << text;
    EXPECT_NE(text.find("material: shiny; material { reflection: 0.5; } }"), std::string::npos)
        << text;
    EXPECT_EQ(state.history.undo.size(), steps + 1) << "one undo step";
    undo(state);
    EXPECT_EQ(document_text(state.doc), kScene);
}

TEST_F(ViewerNamesTime, TheSliderRendersAtItsClockAsJtracerCliDoesAndLeavesTheFile) {
    ASSERT_FALSE(HasFatalFailure());
    for (int i = 0; i < 2; ++i) viewer.frame(state);
    const UiItem* slider = find_item(viewer.ui_items(), "clock");
    ASSERT_NE(slider, nullptr) << "the scene uses clock: the slider shows";
    ASSERT_NE(find_item(viewer.ui_items(), "Play"), nullptr);
    EXPECT_TRUE(state.render.display == cli_image("0")) << "at clock 0";
    // Ctrl+click types a value into the slider.
    viewer.press_mouse(state, 0, (slider->rect.x0 + slider->rect.x1) * 0.5f - 40.0f,
                       (slider->rect.y0 + slider->rect.y1) * 0.5f, kCtrl);
    viewer.release_mouse(state, 0);
    viewer.frame(state);
    for (char c : std::string("0.75")) ImGui::GetIO().AddInputCharacter(c);
    viewer.frame(state);
    viewer.press_key(state, keys::enter);
    viewer.frame(state);
    EXPECT_EQ(state.doc.options.clock, 0.75);
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    EXPECT_TRUE(state.render.display == cli_image("0.75"))
        << "the finished image at clock 0.75 is jtracer-cli --clock 0.75's";
    EXPECT_FALSE(state.render.display == cli_image("0"));
    EXPECT_EQ(read_file(folder / "scene.jts"), kScene) << "the file is never edited";
    EXPECT_FALSE(has_unsaved_edits(state.doc)) << "nor is the document";

    const float slider_left = find_item(viewer.ui_items(), "clock")->rect.x0;
    ASSERT_TRUE(viewer.click(state, "Play"));
    EXPECT_TRUE(state.time.playing);
    viewer.frame(state);
    ASSERT_NE(find_item(viewer.ui_items(), "Pause"), nullptr);
    EXPECT_NE(state.doc.options.clock, 0.75) << "playing moves the clock on";
    EXPECT_EQ(find_item(viewer.ui_items(), "clock")->rect.x0, slider_left)
        << "the slider stays where it was when Play turns to Pause";
}

// A clock typed one key a frame, as a user types it, is taken when Enter is
// pressed: typing 0.5 does not render the scene at clock 0 on the way.
TEST_F(ViewerNamesTime, AClockTypedIsTakenWhenTheTypingEnds) {
    ASSERT_FALSE(HasFatalFailure());
    for (int i = 0; i < 2; ++i) viewer.frame(state);
    ASSERT_TRUE(set_clock(state, 0.25));
    viewer.frame(state);
    const UiItem* slider = find_item(viewer.ui_items(), "clock");
    ASSERT_NE(slider, nullptr);
    viewer.press_mouse(state, 0, (slider->rect.x0 + slider->rect.x1) * 0.5f - 40.0f,
                       (slider->rect.y0 + slider->rect.y1) * 0.5f, kCtrl);
    viewer.release_mouse(state, 0);
    viewer.frame(state);
    for (char c : std::string("0.5")) {
        ImGui::GetIO().AddInputCharacter(c);
        viewer.frame(state);
        EXPECT_EQ(state.doc.options.clock, 0.25) << "not taken while typing, after " << c;
    }
    viewer.press_key(state, keys::enter);
    viewer.frame(state);
    EXPECT_EQ(state.doc.options.clock, 0.5);
}

TEST_F(ViewerNamesTime, ASceneWithoutClockHasNoSlider) {
    ASSERT_FALSE(HasFatalFailure());
    std::string text = kScene;
    text.replace(text.find("clock * 2 - 1"), 13, "0");
    ASSERT_TRUE(replace_text(state.doc, text));
    for (int i = 0; i < 2; ++i) viewer.frame(state);
    EXPECT_EQ(find_item(viewer.ui_items(), "clock"), nullptr);
    EXPECT_EQ(find_item(viewer.ui_items(), "Play"), nullptr);
}

// A 900x600 window, as a user opens it.
class ViewerTimeNarrow : public ViewerNamesTime {
  protected:
    ViewerTimeNarrow() : ViewerNamesTime(900, 600) {}
};

// The slider was 12 font sizes wide whatever the room: with the text editor
// open (or a small window) the image area is narrower than the Play row,
// and the slider ran under the text editor's window, its value and label
// hidden there (or past the window's edge).
TEST_F(ViewerTimeNarrow, TheClockRowStaysInTheImageAreaBesideTheTextEditor) {
    ASSERT_FALSE(HasFatalFailure());
    viewer.text_editor().open = true;
    for (int i = 0; i < 3; ++i) viewer.frame(state);
    const UiItem* editor = find_item(viewer.ui_items(), "text editor");
    ASSERT_NE(editor, nullptr);
    const ScreenRect area = viewer.image_area();
    ASSERT_LE(area.x1, editor->rect.x0 + 1.0f) << "the image area ends where the editor starts";
    const UiItem* slider = find_item(viewer.ui_items(), "clock");
    ASSERT_NE(slider, nullptr);
    EXPECT_LE(slider->rect.x1, area.x1) << "the slider and its label, in the image area";
    EXPECT_GE(slider->rect.x1 - slider->rect.x0, ImGui::GetFontSize() * 6.0f)
        << "still wide enough to drag";
    const UiItem* play = find_item(viewer.ui_items(), "Play");
    ASSERT_NE(play, nullptr);
    EXPECT_TRUE(play->rect.x1 < slider->rect.x0 || play->rect.y1 <= slider->rect.y0)
        << "beside Play or under it, never over it";

    viewer.text_editor().open = false;
    for (int i = 0; i < 3; ++i) viewer.frame(state);
    slider = find_item(viewer.ui_items(), "clock");
    ASSERT_NE(slider, nullptr);
    EXPECT_LE(slider->rect.x1, viewer.image_area().x1);
}

// The tooltip shown now (ImGui's, at most one), or null.
const ImGuiWindow* shown_tooltip() {
    for (const ImGuiWindow* window : GImGui->Windows)
        if (window->Active && (window->Flags & ImGuiWindowFlags_Tooltip)) return window;
    return nullptr;
}

bool overlaps(const ImGuiWindow& window, const UiItem& item) {
    return window.Pos.x < item.rect.x1 && item.rect.x0 < window.Pos.x + window.Size.x &&
           window.Pos.y < item.rect.y1 && item.rect.y0 < window.Pos.y + window.Size.y;
}

// ImGui puts a tooltip under the mouse, or beside it when there is no room
// under it: the Play button's covered the slider's value, which is what
// moves while playing (under Play in a narrow image area, beside it in a
// short window).
// Hovers Play (and Pause) at its top and bottom, the text editor open and
// closed: its tooltip never covers the slider.
void hover_play_and_pause(HeadlessViewer& viewer, AppState& state) {
    for (const bool editor : {true, false})
        for (const bool playing : {false, true}) {
            SCOPED_TRACE(std::string(editor ? "the text editor open" : "the text editor closed") +
                         (playing ? ", playing" : ", paused"));
            viewer.text_editor().open = editor;
            for (int i = 0; i < 3; ++i) viewer.frame(state);
            if (state.time.playing != playing) {
                ASSERT_TRUE(viewer.click(state, playing ? "Play" : "Pause"));
            }
            ASSERT_EQ(state.time.playing, playing);
            viewer.frame(state);  // the click's frame drew the button before it
            const UiItem* play = find_item(viewer.ui_items(), playing ? "Pause" : "Play");
            ASSERT_NE(play, nullptr);
            const float x = (play->rect.x0 + play->rect.x1) * 0.5f;
            for (const float y : {play->rect.y0 + 2.0f, play->rect.y1 - 2.0f}) {
                viewer.move_mouse(state, x, y);
                viewer.frame(state);
                const ImGuiWindow* tip = shown_tooltip();
                ASSERT_NE(tip, nullptr) << "hovering the button shows its tooltip";
                const UiItem* slider = find_item(viewer.ui_items(), "clock");
                ASSERT_NE(slider, nullptr);
                EXPECT_FALSE(overlaps(*tip, *slider));
            }
        }
}

TEST_F(ViewerTimeNarrow, PlaysTooltipLeavesTheSlidersValueInView) {
    ASSERT_FALSE(HasFatalFailure());
    hover_play_and_pause(viewer, state);
}

// A window shorter than the viewer asks for (kMinWindowHeight: a window
// manager may ignore it; Xvfb without one does): no room for the tooltip
// under the mouse, and ImGui put it beside it, over the slider beside Play.
class ViewerTimeShort : public ViewerNamesTime {
  protected:
    ViewerTimeShort() : ViewerNamesTime(900, 140) {}
};

TEST_F(ViewerTimeShort, PlaysTooltipLeavesTheSlidersValueInView) {
    ASSERT_FALSE(HasFatalFailure());
    hover_play_and_pause(viewer, state);
}

}  // namespace
}  // namespace jt::view
