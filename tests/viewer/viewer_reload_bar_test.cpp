// When the file changes under unsaved edits, the choice
// comes to the user, across the top of the image, with the differences
// between the two texts; through the OSMesa frame code.

#include "app/keys.hpp"
#include "app/text_editor.hpp"
#include "app/ui_items.hpp"
#include "common/files.hpp"
#include "common/scratch_dir.hpp"
#include "model/app_actions.hpp"
#include "model/document_edits.hpp"
#include "viewer/viewer_fixture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

namespace jt::view {
namespace {

using namespace jt::test;
namespace fs = std::filesystem;

// An unsaved edit here (width 32), then the file changed on disk (fov 55):
// once the change is found, the reload bar's choice waits.
void edit_here_and_on_disk(HeadlessViewer& viewer, AppState& state, const fs::path& file) {
    edit_scene(state, [](Scene& s) { s.settings.width = 32; });
    viewer.frame(state);
    std::string theirs = read_file(file);
    theirs.replace(theirs.find("fov: 50;"), 8, "fov: 55;");
    write_file(file, theirs);
    ASSERT_TRUE(viewer.run_until_loaded(state));
    ASSERT_TRUE(state.files.pending_reload);
}

class ViewerReloadBar : public ViewerFixture {
  protected:
    ViewerReloadBar() : ViewerFixture(1100, 700) {}
};

TEST_F(ViewerReloadBar, TheChoiceIsAboveTheImageAndShowsTheDifferences) {
    const fs::path file = open_rendered_copy("reload-bar");
    ASSERT_FALSE(HasFatalFailure());
    const ScreenRect image_area = viewer.image_area();
    EXPECT_EQ(find_item(viewer.ui_items(), "reload bar"), nullptr) << "no choice to make";

    ASSERT_NO_FATAL_FAILURE(edit_here_and_on_disk(viewer, state, file));
    EXPECT_NE(state.message.find("bar above the image"), std::string::npos) << state.message;
    viewer.frame(state);
    const UiItem* bar = find_item(viewer.ui_items(), "reload bar");
    ASSERT_NE(bar, nullptr);
    EXPECT_EQ(bar->rect.x0, image_area.x0);
    EXPECT_EQ(bar->rect.y0, image_area.y0);
    EXPECT_EQ(bar->rect.x1, image_area.x1) << "across the image";
    EXPECT_GE(viewer.image_area().y0, bar->rect.y1) << "the image moves down under it";
    for (const char* choice : {"Reload, drop my edits", "Reload, re-apply my edits", "Keep mine"}) {
        const UiItem* item = find_item(viewer.ui_items(), choice);
        ASSERT_NE(item, nullptr) << choice;
        EXPECT_FALSE(item->clipped) << choice;
        EXPECT_GE(item->rect.y0, bar->rect.y0) << choice << " is in the bar";
        EXPECT_LE(item->rect.y1, bar->rect.y1) << choice << " is in the bar";
    }

    ASSERT_TRUE(viewer.click(state, "Show differences"));
    viewer.frame(state);
    ASSERT_NE(find_item(viewer.ui_items(), "differences"), nullptr);
    const TextDiff& diff = viewer.reload_bar().diff;
    EXPECT_EQ(diff.removed, 2) << "width: 32 and fov: 50, mine";
    EXPECT_EQ(diff.added, 2) << "width: 64 and fov: 55, theirs";
    bool fov = false;
    for (const DiffLine& line : diff.lines)
        if (line.kind == DiffLine::Kind::added && line.text.find("fov: 55;") != std::string::npos)
            fov = true;
    EXPECT_TRUE(fov);
    // The differences follow the document as it is edited meanwhile: an
    // edit of the panels, its undo, and text typed.
    edit_scene(state, [](Scene& s) { s.settings.height = 40; });
    viewer.frame(state);
    EXPECT_EQ(viewer.reload_bar().diff.removed, 3) << "height: 40 too";
    undo(state);
    viewer.frame(state);
    EXPECT_EQ(viewer.reload_bar().diff.removed, 2) << "undone";
    std::string typed = document_text(state.doc);
    typed.replace(typed.find("recurse_depth: 2;"), 17, "recurse_depth: 3;");
    type_text(state, typed);
    viewer.frame(state);
    EXPECT_EQ(viewer.reload_bar().diff.removed, 3) << "recurse_depth: 3 typed";
    undo(state);
    viewer.frame(state);
    EXPECT_EQ(viewer.reload_bar().diff.removed, 2) << "the typing undone";

    ASSERT_TRUE(viewer.click(state, "Reload, re-apply my edits"));
    EXPECT_FALSE(state.files.pending_reload);
    viewer.frame(state);
    EXPECT_EQ(find_item(viewer.ui_items(), "reload bar"), nullptr);
    EXPECT_EQ(state.doc.scene.settings.width, 32);
    EXPECT_EQ(state.doc.scene.cameras[1].fov, 55.0);
}

// Found in the real window: with a panel edit unsaved, an included file
// changed on disk; the bar named that file, but its differences were the
// scene file's alone (the edit), never the included file's new lines.
TEST_F(ViewerReloadBar, TheDifferencesShowAnIncludedFileThatChanged) {
    ScratchDir scratch{"reload-bar-include"};
    const fs::path main = scratch.path() / "main.jts";
    const fs::path ball = scratch.path() / "parts" / "ball.jts";
    fs::create_directories(ball.parent_path());
    write_file(ball, "sphere { center: <0, 0, -5>; radius: 1; }\n");
    write_file(main,
               "render_settings { width: 64; height: 48; }\n"
               "cameras { perspective_camera { aspect: 1.3333333333333333; } }\n"
               "scene { point_light { position: <3, 5, 4>; } include \"parts/ball.jts\"; }\n");
    open_rendered(main);
    ASSERT_FALSE(HasFatalFailure());
    edit_scene(state, [](Scene& s) { s.settings.width = 32; });
    viewer.frame(state);
    write_file(ball, "sphere { center: <0, 0, -5>; radius: 2; }\n");
    ASSERT_TRUE(viewer.run_until_loaded(state));
    ASSERT_TRUE(state.files.pending_reload) << state.message;
    viewer.frame(state);
    ASSERT_TRUE(viewer.click(state, "Show differences"));
    viewer.frame(state);
    const TextDiff& diff = viewer.reload_bar().diff;
    const auto has = [&](DiffLine::Kind kind, std::string_view text) {
        return std::any_of(diff.lines.begin(), diff.lines.end(), [&](const DiffLine& line) {
            return line.kind == kind && line.text.find(text) != std::string::npos;
        });
    };
    EXPECT_TRUE(has(DiffLine::Kind::removed, "width: 32;")) << "the edit, mine";
    EXPECT_TRUE(has(DiffLine::Kind::removed, "radius: 1;")) << "the included file, mine";
    EXPECT_TRUE(has(DiffLine::Kind::added, "radius: 2;")) << "the included file, theirs";
    EXPECT_TRUE(has(DiffLine::Kind::file, "parts/ball.jts")) << "named above its lines";
    EXPECT_EQ(diff.removed, 2);
    EXPECT_EQ(diff.added, 2);
}

// Found in the real window at 800x500 (the README's layout on a 2x screen):
// the text editor, at least 30 font widths, took all the width right of the
// panels. The image went, and with it the bar the status line sends the
// user to when the file changes under unsaved edits. The image keeps a
// part of the width beside the text.
// A line of its own in the File panel ("Choose in the bar above the image",
// "Loading..." for every reload) moved every field below it by a row, under
// a mouse that was about to click one: the note shares the file's line.
TEST_F(ViewerReloadBar, TheFilePanelsNoteMovesNoFieldUnderTheMouse) {
    const fs::path file = open_rendered_copy("reload-note");
    ASSERT_FALSE(HasFatalFailure());
    viewer.frame(state);
    const UiItem* fov = find_item(viewer.ui_items(), "fov");
    ASSERT_NE(fov, nullptr);
    const float before = fov->rect.y0;
    ASSERT_NO_FATAL_FAILURE(edit_here_and_on_disk(viewer, state, file));
    viewer.frame(state);
    fov = find_item(viewer.ui_items(), "fov");
    ASSERT_NE(fov, nullptr);
    EXPECT_EQ(fov->rect.y0, before) << "with the choice waiting";
    reload_scene(state);  // a reload under way
    viewer.frame(state);
    fov = find_item(viewer.ui_items(), "fov");
    ASSERT_NE(fov, nullptr);
    EXPECT_EQ(fov->rect.y0, before) << "while loading";
    ASSERT_TRUE(viewer.run_until_loaded(state));
}

class ViewerNarrowWindow : public ViewerFixture {
  protected:
    ViewerNarrowWindow() : ViewerFixture(800, 500) {}
};

TEST_F(ViewerNarrowWindow, TheImageAndTheReloadBarStayBesideTheTextEditor) {
    const fs::path file = open_rendered_copy("narrow-window");
    ASSERT_FALSE(HasFatalFailure());
    viewer.press_key(state, keys::letter('T'));
    ASSERT_TRUE(viewer.text_editor().open);
    viewer.frame(state);
    const UiItem* text = find_item(viewer.ui_items(), "text");
    ASSERT_NE(text, nullptr);
    const ScreenRect area = viewer.image_area();
    EXPECT_GE(area.x1 - area.x0, 100.0f) << "the image has no room beside the text";
    EXPECT_GT(viewer.image_rect().x1, viewer.image_rect().x0);

    ASSERT_NO_FATAL_FAILURE(edit_here_and_on_disk(viewer, state, file));
    viewer.frame(state);
    viewer.frame(state);
    ASSERT_TRUE(viewer.click(state, "Keep mine")) << "the bar's choice is not drawn";
    EXPECT_FALSE(state.files.pending_reload);
    EXPECT_EQ(state.doc.scene.settings.width, 32);
}

// The first diagnostic the last frame drew (its label is its message).
const UiItem* first_diagnostic(const UiItems& items) {
    for (const UiItem& item : items)
        if (item.label.rfind("scene.jts:", 0) == 0) return &item;
    return nullptr;
}

// A reload that fails opens the Diagnostics panel, but in a small window
// it is far below the sidebar's view. The sidebar never scrolls by itself
// (it would move the controls under the mouse); the status line offers a
// link that does, and the controls stay where they were until it is clicked.
TEST_F(ViewerNarrowWindow, AFailedReloadOffersALinkToTheErrorsOutOfView) {
    const fs::path file = open_rendered_copy("errors-link");
    ASSERT_FALSE(HasFatalFailure());
    viewer.frame(state);
    EXPECT_EQ(find_item(viewer.ui_items(), "show errors"), nullptr) << "no errors";
    const UiItem* reload = find_item(viewer.ui_items(), "Reload (R)");
    ASSERT_NE(reload, nullptr);
    const ScreenRect reload_before = reload->rect;

    std::string broken = read_file(file);
    broken.replace(broken.find("fov: 50;"), 8, "fov: 50 x;");
    write_file(file, broken);
    ASSERT_TRUE(viewer.run_until_loaded(state));
    ASSERT_TRUE(state.doc.load_failed);
    for (int i = 0; i < 3; ++i) viewer.frame(state);
    const UiItem* panel = find_item(viewer.ui_items(), "panel");
    const UiItem* status = find_item(viewer.ui_items(), "status");
    const UiItem* error = first_diagnostic(viewer.ui_items());
    ASSERT_NE(panel, nullptr);
    ASSERT_NE(status, nullptr);
    ASSERT_NE(error, nullptr) << "the Diagnostics panel opened";
    EXPECT_GT(error->rect.y1, panel->rect.y1) << "listed below the sidebar's view";
    reload = find_item(viewer.ui_items(), "Reload (R)");
    ASSERT_NE(reload, nullptr);
    EXPECT_EQ(reload->rect.y0, reload_before.y0) << "the sidebar scrolled by itself";
    const UiItem* link = find_item(viewer.ui_items(), "show errors");
    ASSERT_NE(link, nullptr) << "nothing leads to the errors out of view";
    EXPECT_TRUE(link->enabled);
    EXPECT_GE(link->rect.y0, status->rect.y0) << "in the status line";
    EXPECT_LE(link->rect.y1, status->rect.y1) << "in the status line";

    ASSERT_TRUE(viewer.click(state, "show errors"));
    for (int i = 0; i < 3; ++i) viewer.frame(state);
    panel = find_item(viewer.ui_items(), "panel");
    error = first_diagnostic(viewer.ui_items());
    ASSERT_NE(panel, nullptr);
    ASSERT_NE(error, nullptr);
    EXPECT_GE(error->rect.y0, panel->rect.y0) << "scrolled into view";
    EXPECT_LE(error->rect.y1, panel->rect.y1) << "scrolled into view";
    EXPECT_EQ(find_item(viewer.ui_items(), "show errors"), nullptr) << "the errors are in view";

    // The text editor lists the errors under the text: no link then.
    viewer.scroll(state, 10.0f, 10.0f, 40.0f);
    for (int i = 0; i < 3; ++i) viewer.frame(state);
    EXPECT_NE(find_item(viewer.ui_items(), "show errors"), nullptr) << "scrolled away again";
    viewer.text_editor().open = true;
    for (int i = 0; i < 2; ++i) viewer.frame(state);
    EXPECT_EQ(find_item(viewer.ui_items(), "show errors"), nullptr);
}

// Text typed with an error leaves the Diagnostics panel as the user left
// it, collapsed here: the link opens it as well as scrolling to it.
TEST_F(ViewerNarrowWindow, TheLinkOpensACollapsedDiagnosticsPanel) {
    open_rendered_copy("errors-link-collapsed");
    ASSERT_FALSE(HasFatalFailure());
    std::string broken = document_text(state.doc);
    broken.replace(broken.find("fov: 50;"), 8, "fov: 50 x;");
    type_text(state, broken);
    state.check.checker.wait();
    for (int i = 0; i < 3; ++i) viewer.frame(state);
    ASSERT_TRUE(state.doc.draft.has_value());
    ASSERT_EQ(first_diagnostic(viewer.ui_items()), nullptr) << "the panel is collapsed";
    ASSERT_TRUE(viewer.click(state, "show errors"));
    for (int i = 0; i < 3; ++i) viewer.frame(state);
    const UiItem* panel = find_item(viewer.ui_items(), "panel");
    const UiItem* error = first_diagnostic(viewer.ui_items());
    ASSERT_NE(panel, nullptr);
    ASSERT_NE(error, nullptr) << "still collapsed";
    EXPECT_LE(error->rect.y1, panel->rect.y1) << "scrolled into view";
    EXPECT_EQ(find_item(viewer.ui_items(), "show errors"), nullptr);
}

}  // namespace
}  // namespace jt::view
