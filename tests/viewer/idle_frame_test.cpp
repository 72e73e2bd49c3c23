// A frame with nothing to do (the render finished, no input, no change on
// disk) must cost nothing that grows with the scene: Dear ImGui's rule is that
// an idle frame allocates nothing. This executable counts the main thread's
// operator new calls (common/counting_new.hpp), so it has one of its own.

#include "app/headless.hpp"
#include "common/counting_new.hpp"
#include "common/scratch_dir.hpp"
#include "model/app_actions.hpp"
#include "model/document_edits.hpp"
#include "model/model_frame.hpp"
#include "model/picking.hpp"
#include "viewer/viewer_test_files.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <thread>

namespace jt::view {
namespace {

using jt::test::Allocated;
using jt::test::allocated_by;

// Enough objects that a copy of the scene (about 40 MB for 100,000) stands
// out from anything a frame of the panels needs.
constexpr int kObjects = 20000;

std::filesystem::path write_scene(const std::filesystem::path& folder) {
    std::ostringstream text;
    text << "render_settings { width: 64; height: 36; }\n"
            "cameras { perspective_camera { position: <0, 0, 30>; look_at: <0, 0, 0>; "
            "aspect: 1.7777777777777777; fov: 60; } }\n"
            "scene {\npoint_light { position: <10, 20, 40>; intensity: <1, 1, 1>; }\n";
    for (int i = 0; i < kObjects; ++i)
        text << "sphere { center: <" << (i % 150) * 0.1 - 7.5 << ", " << (i / 150) * 0.1 - 7
             << ", 0>; radius: 0.04; }\n";
    text << "}\n";
    const auto path = folder / "many.jts";
    std::ofstream(path, std::ios::binary) << text.str();
    return path;
}

// The selection's outline is made from primitive ids that another thread
// computes; the frame that receives them builds a texture and is not idle, so
// the counted frames start a few frames after it (as they do after a select).
void frame_until_the_outline_is_ready(HeadlessViewer& viewer, AppState& state) {
    const auto deadline = std::chrono::steady_clock::now() + test::kTimeout;
    while (!shown_primitive_ids(state) && std::chrono::steady_clock::now() < deadline) {
        viewer.frame(state);
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    for (int i = 0; i < 3; ++i) viewer.frame(state);
}

class IdleFrame : public ::testing::Test {
  protected:
    void SetUp() override {
        ASSERT_TRUE(viewer.ok()) << viewer.error();
        viewer.set_check_revisions(false);  // its copies would be counted
        open_scene(state, write_scene(dir.path()));
        ASSERT_TRUE(viewer.run_until_complete(state, test::kTimeout, 5)) << state.message;
    }
    test::ScratchDir dir{"idle-frame"};
    HeadlessViewer viewer{960, 640};
    AppState state{test::test_config()};
};

TEST_F(IdleFrame, TheModelSideAllocatesNothing) {
    for (int i = 0; i < 5; ++i) {
        const Allocated a = allocated_by([&] { model_frame(state); });
        EXPECT_EQ(a.count, 0) << a.bytes << " bytes in frame " << i;
    }
}

// Panels, labels, status line, ImGui's draw lists: nothing a frame like the
// last one needs is allocated anew.
TEST_F(IdleFrame, AWholeFrameAllocatesNothing) {
    for (int i = 0; i < 5; ++i) {
        const Allocated a = allocated_by([&] { viewer.frame(state); });
        EXPECT_EQ(a.count, 0) << a.bytes << " bytes in frame " << i;
    }
    // What an undo of the next field edit needs is kept block by block: the
    // render settings and the camera the panels show, never a second scene.
    EXPECT_LE(state.history.settled.size(), 2u);
    EXPECT_FALSE(state.history.edit_base);
}

// The same with the 20,000 objects listed, one of them selected (its fields
// drawn) and a light's fields open.
TEST_F(IdleFrame, AFrameWithTheObjectsListedAndFieldsOpenAllocatesNothing) {
    select(state.view, {Selection::Kind::light, 0});  // opens the light's fields, which stay open
    viewer.frame(state);
    select(state.view, {Selection::Kind::primitive, 7});
    frame_until_the_outline_is_ready(viewer, state);
    ASSERT_NE(find_item(viewer.ui_items(), "sphere 8"), nullptr) << "the selected object's row";
    ASSERT_NE(find_item(viewer.ui_items(), "intensity"), nullptr) << "the light's fields";
    for (int i = 0; i < 5; ++i) {
        const Allocated a = allocated_by([&] { viewer.frame(state); });
        EXPECT_EQ(a.count, 0) << a.bytes << " bytes in frame " << i;
    }
}

// Fields written as names, expressions and a named material's, and the time
// slider: their marks and the text under a computed field allocate nothing
// (a tooltip's words are made only while it shows).
TEST_F(IdleFrame, AFrameWithComputedAndInheritedFieldsAndTheSliderAllocatesNothing) {
    const auto path = dir.path() / "names.jts";
    std::ofstream(path, std::ios::binary)
        << "define r = 0.5;\n"
           "material shiny { pigment: <0.9, 0.2, 0.1>; diffuse: <0.8, 0.8, 0.8>; }\n"
           "render_settings { width: 64; height: 36; }\n"
           "cameras { perspective_camera { position: <0, 0, 10>; look_at: <0, 0, 0>; "
           "aspect: 1.7777777777777777; fov: 60; } }\n"
           "scene {\n point_light { position: <10, 20, 40>; intensity: <1, 1, 1>; }\n"
           " sphere { center: <clock * 2 - 1, r * 2 - 1, 0>; radius: r; material: shiny;\n"
           "   transform { yrotate: 90 * clock; } }\n}\n";
    open_scene(state, path);
    ASSERT_TRUE(viewer.run_until_complete(state, test::kTimeout, 5)) << state.message;
    select(state.view, {Selection::Kind::primitive, 0});
    frame_until_the_outline_is_ready(viewer, state);
    ASSERT_NE(find_item(viewer.ui_items(), "= r"), nullptr) << state.message;
    ASSERT_NE(find_item(viewer.ui_items(), "clock"), nullptr) << "the slider";
    for (int i = 0; i < 5; ++i) {
        const Allocated a = allocated_by([&] { viewer.frame(state); });
        EXPECT_EQ(a.count, 0) << a.bytes << " bytes in frame " << i;
    }
}

// After a panel edit, the scene differs from its text's: the document's
// text is then the base with the edit written in, a copy of the whole file,
// made when something needs it (a save, the text editor), not every frame.
TEST_F(IdleFrame, AFrameAfterAPanelEditAllocatesNothing) {
    edit_scene(state, [](Scene& s) { s.settings.width = 32; });
    ASSERT_TRUE(viewer.run_until_complete(state, test::kTimeout, 3)) << state.message;
    for (int i = 0; i < 5; ++i) {
        const Allocated a = allocated_by([&] { viewer.frame(state); });
        EXPECT_EQ(a.count, 0) << a.bytes << " bytes in frame " << i;
    }
}

// The reload choice with its differences shown, over an unsaved panel edit:
// the document's text is the base with the edit written in (a copy of the
// whole file), made for the diff once, not every frame.
TEST_F(IdleFrame, AFrameShowingTheReloadDifferencesAllocatesNothing) {
    edit_scene(state, [](Scene& s) { s.settings.width = 32; });
    viewer.frame(state);
    const std::filesystem::path file = state.doc.path;
    std::ofstream(file, std::ios::binary | std::ios::app) << "# changed on disk\n";
    ASSERT_TRUE(viewer.run_until_loaded(state));
    ASSERT_TRUE(state.files.pending_reload);
    ASSERT_TRUE(viewer.run_until_complete(state, test::kTimeout, 3)) << state.message;
    ASSERT_TRUE(viewer.click(state, "Show differences"));
    for (int i = 0; i < 3; ++i) viewer.frame(state);
    ASSERT_NE(find_item(viewer.ui_items(), "differences"), nullptr);
    EXPECT_EQ(viewer.reload_bar().diff.removed, 1) << "width: 32, mine";
    EXPECT_EQ(viewer.reload_bar().diff.added, 2) << "width: 64 and the comment, theirs";
    for (int i = 0; i < 5; ++i) {
        const Allocated a = allocated_by([&] { viewer.frame(state); });
        EXPECT_EQ(a.count, 0) << a.bytes << " bytes in frame " << i;
    }
}

// The file read again with an error on its last line: the Diagnostics panel
// opens and quotes the line. Its text is made when the diagnostics change,
// not every frame (finding the line is a walk through the whole file).
TEST_F(IdleFrame, AFrameWithAnErrorListedAllocatesNothing) {
    std::ofstream(state.doc.path, std::ios::binary | std::ios::app) << "sphere { radius: 1 x; }\n";
    ASSERT_TRUE(viewer.run_until_loaded(state));
    ASSERT_TRUE(state.doc.load_failed);
    for (int i = 0; i < 3; ++i) viewer.frame(state);
    ASSERT_NE(find_item(viewer.ui_items(), "Showing the last good scene until the file is fixed."),
              nullptr)
        << "the Diagnostics panel is open";
    for (int i = 0; i < 5; ++i) {
        const Allocated a = allocated_by([&] { viewer.frame(state); });
        EXPECT_EQ(a.count, 0) << a.bytes << " bytes in frame " << i;
    }
}

// The text editor open on a text with an error: its lines, the error
// marked on its line and listed under the text, drawn without allocating.
TEST_F(IdleFrame, AFrameWithTheTextEditorShowingAnErrorAllocatesNothing) {
    viewer.text_editor().open = true;
    std::string text = state.doc.text;
    text.replace(text.find("radius: 0.04;"), 13, "radius: 0.04 x;");
    type_text(state, text);
    state.check.checker.wait();
    for (int i = 0; i < 5; ++i) viewer.frame(state);
    ASSERT_TRUE(state.doc.draft);
    ASSERT_TRUE(has_errors(state.doc.diagnostics));
    for (int i = 0; i < 5; ++i) {
        const Allocated a = allocated_by([&] { viewer.frame(state); });
        EXPECT_EQ(a.count, 0) << a.bytes << " bytes in frame " << i;
    }
}

TEST_F(IdleFrame, AnEditAfterIdleFramesStillRendersAndUndoes) {
    for (int i = 0; i < 3; ++i) viewer.frame(state);
    const std::uint64_t jobs = state.render.renderer.jobs_started();
    edit_scene(state, [](Scene& s) { s.primitives[7].material.pigment = Colour(1, 0, 0); });
    viewer.frame(state);
    EXPECT_GT(state.render.renderer.jobs_started(), jobs) << "the edit starts a render";
    undo(state);
    viewer.frame(state);
    EXPECT_EQ(state.doc.scene, *state.doc.original);
    EXPECT_FALSE(has_unsaved_edits(state.doc));
}

}  // namespace
}  // namespace jt::view
