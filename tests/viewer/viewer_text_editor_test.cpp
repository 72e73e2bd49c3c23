// The text editor as a user meets it (issue 27), through the OSMesa frame
// code: keys as a keyboard sends them, through the window's KeyTaps (Ctrl+Z
// past the start of the history, fast typing), and a file broken or deleted
// on disk while it is open, and the files a scene includes.

#include "app/headless.hpp"
#include "app/keys.hpp"
#include "app/text_editor.hpp"
#include "app/ui_items.hpp"
#include "common/files.hpp"
#include "jtracer/diagnostics.hpp"
#include "model/app_actions.hpp"
#include "model/document_edits.hpp"
#include "model/editor_files.hpp"
#include "viewer/viewer_test_files.hpp"

#include <gtest/gtest.h>
#include <imgui.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace jt::view {
namespace {

using namespace jt::test;
namespace fs = std::filesystem;

KeyEvent key(int code, int action, int mods = 0) {
    return KeyEvent{code, 0, action, mods, 0};
}

// A tap of `code`: pressed and let go.
void tap(std::vector<KeyEvent>& events, int code, int mods = 0) {
    events.push_back(key(code, kKeyPress, mods));
    events.push_back(key(code, kKeyRelease, mods));
}

// `text` typed as a keyboard sends it: each key pressed, its character, let go.
void type(std::vector<KeyEvent>& events, const std::string& text) {
    for (char c : text) {
        const int code = c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c;
        events.push_back(key(code, kKeyPress));
        events.push_back(typed_character(static_cast<unsigned char>(c)));
        events.push_back(key(code, kKeyRelease));
    }
}

// `text`, the test scene's, with the ';' after its height taken away: an
// error at that line, which the viewer reports and the editor shows.
std::string without_height_semicolon(std::string text) {
    const std::string_view good = "height: 48;";
    return text.replace(text.find(good), good.size(), "height: 48");
}

// A copy of the test scene under `name` whose file is broken from the start
// (without_height_semicolon): opened, it loads no good scene. Its text goes
// to `broken`.
fs::path broken_scene_copy(const std::string& name, std::string& broken) {
    const fs::path file = scene_copy(name);
    broken = without_height_semicolon(read_file(file));
    write_file(file, broken);
    return file;
}

// Ctrl (with Shift) held around a tap of `code`.
void shortcut(std::vector<KeyEvent>& events, int code, bool shift = false) {
    constexpr int ctrl_mod = 0x0002, shift_mod = 0x0001;
    const int mods = ctrl_mod | (shift ? shift_mod : 0);
    events.push_back(key(keys::left_ctrl, kKeyPress, ctrl_mod));
    if (shift) events.push_back(key(keys::left_shift, kKeyPress, mods));
    tap(events, code, mods);
    if (shift) events.push_back(key(keys::left_shift, kKeyRelease, ctrl_mod));
    events.push_back(key(keys::left_ctrl, kKeyRelease, 0));
}

class ViewerTextEditor : public ::testing::Test {
  protected:
    void SetUp() override {
        ASSERT_TRUE(viewer.ok()) << viewer.error();
        file = scene_copy(::testing::UnitTest::GetInstance()->current_test_info()->name());
        open_scene(state, file);
        ASSERT_TRUE(state.doc.loaded);
        original = read_file(file);
        viewer.press_key(state, keys::letter('T'));
        ASSERT_TRUE(viewer.text_editor().open);
    }
    void TearDown() override { fs::remove_all(file.parent_path()); }

    // Puts the cursor at line:column of the text, as a click there does.
    void put_cursor(int line, int column) {
        viewer.text_editor().jump = offset_of(viewer.text_editor().buffer, line, column);
        viewer.frame(state);
        viewer.frame(state);
        ASSERT_EQ(viewer.text_editor().cursor,
                  offset_of(viewer.text_editor().buffer, line, column));
    }
    std::string text() const { return document_text(state.doc); }
    // Writes a 302-character comment at the start of line 10 to the file,
    // reloads it and types an x at the comment's end, where the view has
    // scrolled sideways.
    void type_at_the_end_of_a_long_line() {
        const std::string comment = "# " + std::string(300, 'w');
        std::string written = original;
        written.insert(offset_of(written, 10, 1), comment);
        write_file(file, written);
        EXPECT_TRUE(viewer.run_until_loaded(state));
        viewer.frame(state);
        EXPECT_EQ(viewer.text_editor().buffer, written);
        put_cursor(10, static_cast<int>(comment.size()) + 1);
        std::vector<KeyEvent> events;
        type(events, "x");
        viewer.key_events(state, events, 40.0, 16.0);
        viewer.frame(state);
        viewer.frame(state);
    }

    HeadlessViewer viewer{1200, 700};
    AppState state{test_config()};
    fs::path file;
    std::string original;
};

// After Ctrl+Z undid the typing, one more Ctrl+Z, with
// nothing left to undo, changed a byte of the next line (ImGui's own undo
// acting at an offset into text the app had replaced), and redo was lost.
TEST_F(ViewerTextEditor, CtrlZPastTheStartOfTheHistoryChangesNothingAndRedoComesBack) {
    put_cursor(10, 1);  // the empty line before `cameras {`
    std::vector<KeyEvent> events;
    type(events, "# hello world");
    viewer.key_events(state, events, 40.0, 16.0);
    const std::string typed = text();
    ASSERT_EQ(typed, std::string(original).insert(offset_of(original, 10, 1), "# hello world"));

    // The typing is one undo step, or a few when the machine is slow enough
    // that the check of the text ran between keys (kTypingPause).
    const auto ctrl_z = [&](bool shift) {
        std::vector<KeyEvent> keys_typed;
        shortcut(keys_typed, keys::letter('Z'), shift);
        viewer.key_events(state, keys_typed, 40.0, 16.0);
    };
    for (int i = 0; i < 13 && state.history.undo.can_undo(); ++i) ctrl_z(false);
    ASSERT_FALSE(state.history.undo.can_undo());
    EXPECT_EQ(text(), original) << "Ctrl+Z undoes the typing";
    EXPECT_EQ(viewer.text_editor().cursor, offset_of(original, 10, 1))
        << "the cursor goes back to where the typing was";
    for (int i = 0; i < 3; ++i) {
        ctrl_z(false);
        ASSERT_EQ(text(), original) << "a Ctrl+Z past the start of the history changed the text";
    }
    for (int i = 0; i < 13 && state.history.undo.can_redo(); ++i) ctrl_z(true);
    EXPECT_EQ(text(), typed) << "Ctrl+Shift+Z brings the typing back";
}

// A quick Ctrl+Z lets go of Ctrl before Z (xdotool sends it so): Ctrl down
// in one frame, then Z down, Ctrl up and Z up before the next. That frame
// saw Z without Ctrl, and the undo was lost about one time in three under Xvfb.
TEST_F(ViewerTextEditor, ACtrlZWhoseCtrlComesUpFirstUndoes) {
    put_cursor(10, 1);
    std::vector<KeyEvent> events;
    type(events, "# chord");
    viewer.key_events(state, events, 40.0, 16.0);
    ASSERT_NE(text(), original);
    ASSERT_TRUE(state.history.undo.can_undo());
    for (int i = 0; i < 8 && state.history.undo.can_undo(); ++i) {
        constexpr int ctrl_mod = 0x0002;
        events = {key(keys::left_ctrl, kKeyPress, 0), key(keys::letter('Z'), kKeyPress, ctrl_mod),
                  key(keys::left_ctrl, kKeyRelease, ctrl_mod),
                  key(keys::letter('Z'), kKeyRelease, 0)};
        // Events 12 ms apart, a frame every 40 ms: Ctrl in the first frame, the rest in the next.
        const std::size_t undo_steps = state.history.undo.size();
        viewer.key_events(state, events, 12.0, 40.0);
        ASSERT_LT(state.history.undo.size(), undo_steps) << "Ctrl+Z undid nothing";
    }
    EXPECT_EQ(text(), original);
}

// Esc leaves the editor without putting back the text it was entered with
// (which an undo since replaced).
TEST_F(ViewerTextEditor, EscAfterAnUndoKeepsTheUndoneText) {
    put_cursor(10, 1);
    std::vector<KeyEvent> events;
    type(events, "# x");
    viewer.key_events(state, events, 40.0, 16.0);
    for (int i = 0; i < 4 && state.history.undo.can_undo(); ++i) {
        events.clear();
        shortcut(events, keys::letter('Z'));
        viewer.key_events(state, events, 40.0, 16.0);
    }
    events.clear();
    tap(events, keys::escape);
    viewer.key_events(state, events, 40.0, 16.0);
    EXPECT_EQ(text(), original);
}

// In `width: 64|;` three Backspaces and "123" typed 12 ms
// apart, at frame times from a fast frame to a slow one, give `width:123;`
// (the characters came before the Backspaces of their frame).
TEST_F(ViewerTextEditor, FastTypingKeepsItsOrderWhateverTheFrameRate) {
    const int width_line = 3;  // "    width: 64;"
    ASSERT_NE(original.find("    width: 64;"), std::string::npos);
    std::string expected = original;
    expected.replace(expected.find("width: 64;"), 10, "width:123;");
    for (double frame_ms : {5.0, 16.0, 40.0, 120.0}) {
        put_cursor(width_line, 14);  // after "64"
        std::vector<KeyEvent> events;
        tap(events, keys::backspace);
        tap(events, keys::backspace);
        tap(events, keys::backspace);
        type(events, "123");
        viewer.key_events(state, events, 12.0, frame_ms);
        ASSERT_EQ(text(), expected) << "with a frame every " << frame_ms << " ms";
        while (state.history.undo.can_undo()) undo(state);  // one step, or more on a slow machine
        viewer.frame(state);
        ASSERT_EQ(text(), original);
    }
}

// Found in the real window under load: a path typed into the File panel's
// field, then a click on Open. The keys wait in KeyTaps for frames (each
// key changes once a frame), the click did not: it pressed Open with half
// the path typed, and the characters after it became the image's
// shortcuts (T closed the text editor, X deleted the selection, S saved an
// image). The click keeps its place among the keys.
TEST_F(ViewerTextEditor, AClickAfterTypingWaitsForTheTyping) {
    const fs::path target = file.parent_path() / "sixteen_xts.jts";
    fs::copy_file(file, target);
    viewer.frame(state);
    const UiItem* field = find_item(viewer.ui_items(), "open path");
    const UiItem* open = find_item(viewer.ui_items(), "Open");
    ASSERT_TRUE(field && open);
    const auto centre = [](const UiItem& item, int button, int action) {
        return mouse_button_event(button, action, (item.rect.x0 + item.rect.x1) * 0.5f,
                                  (item.rect.y0 + item.rect.y1) * 0.5f);
    };
    state.view.selection = {Selection::Kind::primitive, 1};  // what a stray X would delete
    std::vector<KeyEvent> events;
    events.push_back(centre(*field, 0, kKeyPress));
    events.push_back(centre(*field, 0, kKeyRelease));
    shortcut(events, keys::letter('A'));  // the field's text selected, to be replaced
    type(events, target.string());
    events.push_back(centre(*open, 0, kKeyPress));
    events.push_back(centre(*open, 0, kKeyRelease));
    // Events 4 ms apart, a frame every 60 ms: a slow frame, as with a render running.
    viewer.key_events(state, events, 4.0, 60.0);
    ASSERT_TRUE(viewer.run_until_loaded(state));
    EXPECT_EQ(state.fields.open_path_input, target.string());
    EXPECT_EQ(state.doc.path, target) << state.message;
    EXPECT_TRUE(viewer.text_editor().open) << "a T typed in the field toggled the text editor";
    EXPECT_EQ(state.doc.scene.primitives.size(), 2u);
    EXPECT_FALSE(state.history.undo.can_undo()) << "no edit was made";
}

// Found in the real window: Ctrl+Q while typing in the text editor did
// nothing (a text field took every shortcut but its own).
TEST_F(ViewerTextEditor, CtrlQInTheTextAsksBeforeQuitting) {
    put_cursor(10, 1);
    std::vector<KeyEvent> events;
    type(events, "# q");
    viewer.key_events(state, events, 40.0, 16.0);
    const std::string typed = text();
    ASSERT_NE(typed, original);
    events.clear();
    shortcut(events, keys::letter('Q'));
    viewer.key_events(state, events, 40.0, 16.0);
    EXPECT_TRUE(state.files.unsaved_prompt.has_value()) << "Ctrl+Q in the text did nothing";
    EXPECT_FALSE(state.quit);
    EXPECT_EQ(text(), typed) << "Ctrl+Q typed nothing";
}

// A file broken on disk showed the old good text and "No
// errors" in the editor, and saving wrote the old text over the broken file.
TEST_F(ViewerTextEditor, ABrokenFileOnDiskIsShownWithItsErrorsAndNeverSavedOver) {
    const std::string broken = without_height_semicolon(std::string(original));
    write_file(file, broken);
    ASSERT_TRUE(viewer.run_until_loaded(state));
    viewer.frame(state);
    EXPECT_EQ(viewer.text_editor().buffer, broken) << "the file's own text";
    ASSERT_FALSE(state.doc.diagnostics.empty());
    const Diagnostic error = state.doc.diagnostics[0];
    EXPECT_EQ(error.pos.line, 4) << error.message;  // the ';' missing after "48"
    const std::string label = std::to_string(error.pos.line) + ":" +
                              std::to_string(error.pos.column) + ": error: " + error.message;
    ASSERT_TRUE(viewer.click(state, label)) << "the error is listed under the text";
    viewer.frame(state);  // the editor takes the focus
    viewer.frame(state);
    EXPECT_EQ(viewer.text_editor().cursor, offset_of(broken, error.pos.line, error.pos.column))
        << "a click on it puts the cursor there";
    EXPECT_FALSE(has_unsaved_edits(state.doc)) << "the file's text is no unsaved edit";

    // Ctrl+S (the cursor in the text): refused, the file stays as it is.
    viewer.press_key(state, keys::letter('S'), true);
    EXPECT_EQ(read_file(file), broken) << state.message;
    save_scene_anyway(state);
    EXPECT_EQ(read_file(file), broken) << state.message;

    // Mended in place, then saved.
    viewer.text_editor().jump = offset_of(broken, 4, 15);  // after "height: 48"
    viewer.frame(state);
    viewer.frame(state);
    std::vector<KeyEvent> events;
    type(events, ";");
    viewer.key_events(state, events, 40.0, 16.0);
    state.check.checker.wait();
    viewer.frame(state);
    EXPECT_FALSE(state.doc.draft.has_value()) << "the mended text parses";
    EXPECT_TRUE(save_scene(state)) << state.message;
    EXPECT_EQ(read_file(file), original);
}

// Found in the real window: a scene with an error, opened as the viewer
// starts (no good scene yet), showed an empty text in the editor, line 1
// and "No errors or warnings", where typing would have replaced the file's
// whole text. The editor shows the file's text with its errors.
TEST(ViewerTextEditorOpen, AFileBrokenFromTheStartIsShownWithItsErrors) {
    HeadlessViewer viewer{1200, 700};
    ASSERT_TRUE(viewer.ok()) << viewer.error();
    std::string broken;
    const fs::path file = broken_scene_copy("text-editor-broken-at-start", broken);
    AppState state{test_config()};
    open_scene(state, file);
    ASSERT_FALSE(state.doc.loaded);
    viewer.press_key(state, keys::letter('T'));
    ASSERT_TRUE(viewer.text_editor().open);
    viewer.frame(state);
    viewer.frame(state);
    EXPECT_EQ(viewer.text_editor().buffer, broken);
    ASSERT_FALSE(state.doc.diagnostics.empty());
    const Diagnostic& error = state.doc.diagnostics[0];
    const std::string label = std::to_string(error.pos.line) + ":" +
                              std::to_string(error.pos.column) + ": error: " + error.message;
    EXPECT_NE(find_item(viewer.ui_items(), label), nullptr) << "the error under the text";

    // Mended in the editor, it opens.
    viewer.text_editor().jump = offset_of(broken, 4, 15);  // after "height: 48"
    viewer.frame(state);
    viewer.frame(state);
    std::vector<KeyEvent> events;
    type(events, ";");
    viewer.key_events(state, events, 40.0, 16.0);
    state.check.checker.wait();
    viewer.frame(state);
    EXPECT_TRUE(state.doc.loaded) << format_diagnostics(state.doc);
    EXPECT_EQ(document_text(state.doc), read_file(kScene));
    fs::remove_all(file.parent_path());
}

// Found in the real window: a scene with a Latin-1 comment ("café") is
// refused (not UTF-8 text), and the text editor showed an empty text, line
// 1 and "No errors or warnings", ready to be typed over. Like a text with
// NUL bytes, it says what the file is and is not edited here.
TEST(ViewerTextEditorBytes, AFileThatIsNotUtf8IsNotShownAsAnEmptyText) {
    HeadlessViewer viewer{1200, 700};
    ASSERT_TRUE(viewer.ok()) << viewer.error();
    const fs::path file = scene_copy("text-editor-latin1");
    std::string latin1 = read_file(file);
    latin1.insert(0, "# caf\xe9\n");
    write_file(file, latin1);
    AppState state{test_config()};
    open_scene(state, file);
    ASSERT_FALSE(state.doc.loaded);
    viewer.press_key(state, keys::letter('T'));
    ASSERT_TRUE(viewer.text_editor().open);
    viewer.frame(state);
    viewer.frame(state);
    EXPECT_EQ(find_item(viewer.ui_items(), "text"), nullptr) << "an editable text";
    EXPECT_NE(find_item(viewer.ui_items(), "not UTF-8 text"), nullptr) << "nothing says why";
    std::vector<KeyEvent> events;
    type(events, "x");
    viewer.key_events(state, events, 40.0, 16.0);
    EXPECT_FALSE(state.doc.draft.has_value()) << "typed over";
    EXPECT_EQ(read_file(file), latin1);
    fs::remove_all(file.parent_path());
}

// Found in the real window: a valid scene with an emoji in a comment (a
// character past U+FFFF, which ImGui's 16-bit characters cannot hold).
// One space typed anywhere wrote the whole text back with NUL bytes in the
// emoji's place: the editor then refused the text and Save with it. The
// text is not put in the widget; the panels still edit the scene.
TEST(ViewerTextEditorBytes, ATextTheWidgetWouldChangeIsNotEditedInIt) {
    HeadlessViewer viewer{1200, 700};
    ASSERT_TRUE(viewer.ok()) << viewer.error();
    const fs::path file = scene_copy("text-editor-emoji");
    std::string text = read_file(file);
    text.insert(0, "# \xf0\x9f\x98\x80 caf\xc3\xa9\n");
    write_file(file, text);
    AppState state{test_config()};
    open_scene(state, file);
    ASSERT_TRUE(state.doc.loaded) << format_diagnostics(state.doc);
    viewer.press_key(state, keys::letter('T'));
    viewer.frame(state);
    EXPECT_EQ(find_item(viewer.ui_items(), "text"), nullptr) << "an editable text";
    EXPECT_NE(find_item(viewer.ui_items(), "not UTF-8 text"), nullptr) << "nothing says why";
    std::vector<KeyEvent> events;
    type(events, " ");
    viewer.key_events(state, events, 40.0, 16.0);
    EXPECT_FALSE(state.doc.draft.has_value()) << "typed over";
    EXPECT_EQ(document_text(state.doc), text);

    // Only UTF-8 up to U+FFFF (the é): the text is edited as before.
    text.replace(2, 4, "x");
    write_file(file, text);
    ASSERT_TRUE(viewer.run_until_loaded(state));
    viewer.frame(state);
    viewer.frame(state);
    EXPECT_NE(find_item(viewer.ui_items(), "text"), nullptr);
    EXPECT_EQ(viewer.text_editor().buffer, text);
    fs::remove_all(file.parent_path());
}

// Typing at the end of a long line left the cursor out of
// view (the editor did not scroll sideways), and a long error message was
// cut off at the list's edge.
TEST_F(ViewerTextEditor, TheViewFollowsTheCursorSidewaysAndLongErrorsWrap) {
    const std::string comment = "# " + std::string(300, 'w');
    std::string text = original;
    text.insert(offset_of(text, 10, 1), comment);  // line 10, 302 characters
    write_file(file, text);
    ASSERT_TRUE(viewer.run_until_loaded(state));
    viewer.frame(state);
    ASSERT_EQ(viewer.text_editor().buffer, text);
    viewer.text_editor().jump = offset_of(text, 10, 1) + static_cast<int>(comment.size());
    viewer.frame(state);
    viewer.frame(state);
    std::vector<KeyEvent> events;
    type(events, "x");
    viewer.key_events(state, events, 40.0, 16.0);
    viewer.frame(state);
    const UiItem* window = find_item(viewer.ui_items(), "text editor");
    ASSERT_NE(window, nullptr);
    const float x = viewer.text_editor().cursor_x;
    EXPECT_GT(x, window->rect.x0);
    EXPECT_LT(x, window->rect.x1) << "the cursor at the end of the long line is in view";

    // A message longer than the list is wide: wrapped, never past its edge.
    std::string broken = text;
    broken.replace(broken.find("fov: 40;"), 8, "fov: 40; f" + std::string(150, 'o') + "v: 1;");
    write_file(file, broken);
    ASSERT_TRUE(viewer.run_until_loaded(state));
    resolve_reload(state, ReloadChoice::drop_edits);  // the typed "x"
    viewer.frame(state);
    ASSERT_EQ(viewer.text_editor().buffer, broken);
    ASSERT_FALSE(state.doc.diagnostics.empty());
    const Diagnostic& d = state.doc.diagnostics[0];
    const std::string label =
        std::to_string(d.pos.line) + ":" + std::to_string(d.pos.column) + ": error: " + d.message;
    const UiItem* item = find_item(viewer.ui_items(), label);
    ASSERT_NE(item, nullptr) << label;
    EXPECT_FALSE(item->clipped) << label;
    window = find_item(viewer.ui_items(), "text editor");  // of this frame's items
    ASSERT_NE(window, nullptr);
    EXPECT_LE(item->rect.x1, window->rect.x1);
}

// The line numbers were drawn in the text's place, so with the cursor at
// the end of a long line (the view scrolled sideways) they scrolled out of
// view and the line's text showed in their column instead.
TEST_F(ViewerTextEditor, LineNumbersStayWhenTheTextScrollsSideways) {
    type_at_the_end_of_a_long_line();
    const UiItem* window = find_item(viewer.ui_items(), "text editor");
    ASSERT_NE(window, nullptr);
    const TextEditorState& editor = viewer.text_editor();
    ASSERT_LT(editor.line1_x, window->rect.x0) << "the view scrolled sideways";
    // Line 10's row, from the editor's left edge across the numbers' column
    // (two digits and two spaces of the monospace font).
    const Image8 screen = viewer.screenshot();
    const float char_w = editor.line_height * 0.5f;
    const int y0 = static_cast<int>(editor.line1_y + 9.0f * editor.line_height) + 1;
    const int x0 = static_cast<int>(window->rect.x0) + 2;
    int number_pixels = 0, text_pixels = 0;
    for (int y = y0; y < y0 + static_cast<int>(editor.line_height) - 1; ++y)
        for (int x = x0; x < x0 + static_cast<int>(char_w * 5.0f); ++x) {
            const std::uint8_t* p = screen.pixel(x, screen.height - 1 - y);
            text_pixels += p[0] > 200;  // the text's white
            number_pixels += p[0] > 90 && p[0] <= 200 && p[0] == p[1] && p[1] == p[2];
        }
    EXPECT_EQ(text_pixels, 0) << "no text under the numbers";
    EXPECT_GT(number_pixels, 5) << "the number 10 is there";
}

// Found in the real window: typing new lines at the bottom of the view, the
// line being typed went under the horizontal scroll bar (a long line shows
// one): the view followed the cursor as if the bar took no room.
TEST_F(ViewerTextEditor, TheLineBeingTypedStaysAboveTheScrollBar) {
    type_at_the_end_of_a_long_line();
    const TextEditorState& editor = viewer.text_editor();
    std::vector<KeyEvent> events;
    for (int i = 0; i < 60; ++i) tap(events, keys::enter);
    viewer.key_events(state, events, 40.0, 16.0);
    viewer.frame(state);
    viewer.frame(state);
    const UiItem* view = find_item(viewer.ui_items(), "text view");
    ASSERT_NE(view, nullptr);
    const int line = 1 + static_cast<int>(std::count(editor.buffer.begin(),
                                                     editor.buffer.begin() + editor.cursor, '\n'));
    ASSERT_EQ(line, 70);
    const float bottom = editor.line1_y + static_cast<float>(line) * editor.line_height;
    EXPECT_LE(bottom, view->rect.y1 - ImGui::GetStyle().ScrollbarSize)
        << "the cursor's line ends under the scroll bar";
    EXPECT_GE(bottom - editor.line_height, view->rect.y0) << "and is in the view";
}

// The view kept its scroll from file to file: another file opened after
// typing at the end of a long line (or far down) showed cut off at the
// left, its first lines out of view.
TEST_F(ViewerTextEditor, AnotherFileOpensScrolledToItsStart) {
    viewer.frame(state);
    const TextEditorState& editor = viewer.text_editor();
    const float x = editor.line1_x, y = editor.line1_y;
    type_at_the_end_of_a_long_line();
    ASSERT_LT(editor.line1_x, x) << "scrolled sideways";

    const fs::path other = file.parent_path() / "other.jts";
    write_file(other, original);
    std::vector<KeyEvent> events;
    tap(events, keys::escape);  // out of the text, as a click on the Open field is
    viewer.key_events(state, events, 40.0, 16.0);
    viewer.frame(state);
    request_open_guarded(state, other);
    ASSERT_TRUE(state.files.unsaved_prompt) << "the typed x";
    viewer.frame(state);  // the prompt comes up
    ASSERT_TRUE(viewer.click(state, "Discard"));
    ASSERT_FALSE(state.files.unsaved_prompt) << "Discard answered the prompt";
    ASSERT_TRUE(viewer.run_until_loaded(state));
    ASSERT_EQ(state.doc.path, other) << state.message;
    viewer.frame(state);
    viewer.frame(state);
    EXPECT_EQ(editor.line1_x, x) << "the other file from its first column";
    EXPECT_EQ(editor.line1_y, y) << "and its first line";
}

// While the text was being edited (after every keystroke,
// until its check a quarter second later, and as long as it has errors) a
// two-line note stood above the Camera panel: the sidebar under the mouse
// moved 38 pixels down and back, and a click meant for a field hit another.
TEST_F(ViewerTextEditor, TypingInTheTextKeepsThePanelsWhereTheyWere) {
    const UiItem* view = find_item(viewer.ui_items(), "View");
    ASSERT_NE(view, nullptr) << "the Camera panel's camera choice";
    const float before = view->rect.y0;
    put_cursor(3, 13);  // "    width: 6|4;"
    std::vector<KeyEvent> events;
    type(events, "x");  // an error: the draft stays until it is mended
    viewer.key_events(state, events, 40.0, 16.0);
    state.check.checker.wait();
    viewer.frame(state);
    viewer.frame(state);
    ASSERT_TRUE(state.doc.draft.has_value());
    view = find_item(viewer.ui_items(), "View");
    ASSERT_NE(view, nullptr);
    EXPECT_EQ(view->rect.y0, before) << "while the text has errors";
    EXPECT_FALSE(view->enabled) << "the panels are read-only";

    events.clear();
    tap(events, keys::backspace);
    viewer.key_events(state, events, 40.0, 16.0);
    state.check.checker.wait();
    viewer.frame(state);
    viewer.frame(state);
    ASSERT_FALSE(state.doc.draft.has_value()) << state.message;
    view = find_item(viewer.ui_items(), "View");
    ASSERT_NE(view, nullptr);
    EXPECT_EQ(view->rect.y0, before) << "once it parses";
    EXPECT_TRUE(view->enabled);
}

// A deleted file says so, and the editor keeps the viewer's text.
TEST_F(ViewerTextEditor, ADeletedFileSaysItWasDeletedAndKeepsTheText) {
    fs::remove(file);
    ASSERT_TRUE(viewer.run_until_loaded(state));
    viewer.frame(state);
    EXPECT_TRUE(state.doc.file_deleted);
    EXPECT_NE(state.message.find("was deleted"), std::string::npos) << state.message;
    EXPECT_EQ(viewer.text_editor().buffer, original);
    EXPECT_TRUE(save_scene_anyway(state)) << state.message;
    EXPECT_EQ(read_file(file), original);
}

// A scene whose light is in main.jts and whose ball is in parts/ball.jts,
// written into a scratch folder of its own; the folder.
constexpr std::string_view kIncludingMain =
    "render_settings { width: 32; height: 24; }\n"
    "cameras { perspective_camera { aspect: 1.3333333333333333; } }\n"
    "scene { point_light { position: <3, 5, 4>; } include \"parts/ball.jts\"; }\n";
constexpr std::string_view kIncludedBall = "sphere { center: <0, 0, -5>; radius: 1; }\n";
fs::path write_including_scene(const std::string& name) {
    const fs::path dir = make_scratch_dir(name);
    fs::create_directories(dir / "parts");
    write_file(dir / "main.jts", kIncludingMain);
    write_file(dir / "parts" / "ball.jts", kIncludedBall);
    return dir;
}

// Ctrl+Z (with `shift`, Ctrl+Shift+Z) pressed once.
void press_undo(HeadlessViewer& viewer, AppState& state, bool shift = false) {
    std::vector<KeyEvent> events;
    shortcut(events, keys::letter('Z'), shift);
    viewer.key_events(state, events, 40.0, 16.0);
}

// An included file is opened from the button above the
// text, typed in (Ctrl+Z undoes that typing only), kept while another file
// is shown, and Ctrl+S writes it into its file.
TEST(ViewerIncludedFileEditor, OpensTypesUndoesAndSavesAnIncludedFile) {
    HeadlessViewer viewer{1200, 700};
    ASSERT_TRUE(viewer.ok()) << viewer.error();
    const fs::path dir = write_including_scene("included-file-editor");
    const std::string main_text(kIncludingMain), ball_text(kIncludedBall);
    AppState state{test_config()};
    open_scene(state, dir / "main.jts");
    ASSERT_TRUE(state.doc.loaded) << format_diagnostics(state.doc);
    viewer.press_key(state, keys::letter('T'));
    TextEditorState& ed = viewer.text_editor();
    ASSERT_TRUE(ed.open);
    EXPECT_EQ(ed.buffer, main_text);

    ASSERT_TRUE(viewer.click(state, "parts/ball.jts")) << "a button for the included file";
    viewer.frame(state);
    EXPECT_FALSE(state.editor.shown.empty());
    EXPECT_EQ(ed.buffer, ball_text);

    ed.jump = 0;
    viewer.frame(state);
    viewer.frame(state);
    std::vector<KeyEvent> events;
    type(events, "# hi\n");
    viewer.key_events(state, events, 40.0, 16.0);
    const std::string typed = "# hi\n" + ball_text;
    ASSERT_EQ(ed.buffer, typed);
    ASSERT_NE(draft_of(state.editor, state.editor.shown), nullptr);
    EXPECT_EQ(draft_of(state.editor, state.editor.shown)->text, typed);
    EXPECT_EQ(document_text(state.doc), main_text) << "the scene file's text is not touched";

    // One Ctrl+Z undoes the typing in this file, typed without a pause, as
    // in the scene file (it undid a character a press); it is no undo of
    // the scene's, and Ctrl+Shift+Z brings it back.
    press_undo(viewer, state);
    EXPECT_EQ(ed.buffer, ball_text);
    EXPECT_FALSE(has_included_drafts(state.editor)) << "typed back: nothing to save";
    EXPECT_EQ(document_text(state.doc), main_text);
    press_undo(viewer, state, /*shift=*/true);
    ASSERT_EQ(ed.buffer, typed);
    ASSERT_NE(draft_of(state.editor, state.editor.shown), nullptr);
    EXPECT_EQ(draft_of(state.editor, state.editor.shown)->text, typed);

    // The scene file shown and back: the typing is still there.
    ASSERT_TRUE(viewer.click(state, "main.jts"));
    viewer.frame(state);
    EXPECT_EQ(ed.buffer, main_text);
    ASSERT_TRUE(viewer.click(state, "parts/ball.jts *")) << "marked as typed in";
    viewer.frame(state);
    EXPECT_EQ(ed.buffer, typed);

    ed.jump = 0;
    viewer.frame(state);
    viewer.frame(state);
    viewer.press_key(state, keys::letter('S'), true);
    EXPECT_EQ(read_file(dir / "parts" / "ball.jts"), typed) << state.message;
    EXPECT_EQ(read_file(dir / "main.jts"), main_text);
    EXPECT_EQ(state.message, "Saved parts/ball.jts");
    EXPECT_FALSE(has_unsaved_work(state));
    viewer.frame(state);
    viewer.frame(state);
    EXPECT_EQ(ed.buffer, typed) << "the file as saved";
    EXPECT_EQ(state.message, "Saved parts/ball.jts") << "its own write reloads nothing";
    fs::remove_all(dir);
}

// Found in the real window: Delete, Duplicate, Add material block and
// Add operation were offered on a ball read from parts/ball.jts, and
// clicking them only said, in the status line, that it could not be done.
// They are greyed with the reason in their tooltip; the Delete key says it,
// and the scene stays as it is. A block of the scene file keeps them.
TEST(ViewerIncludedFileEditor, ABlockOfAnIncludedFileOffersNoBlockCommands) {
    HeadlessViewer viewer{1200, 900};
    ASSERT_TRUE(viewer.ok()) << viewer.error();
    const fs::path dir = write_including_scene("included-block-commands");
    AppState state{test_config()};
    open_scene(state, dir / "main.jts");
    ASSERT_TRUE(state.doc.loaded) << format_diagnostics(state.doc);
    ASSERT_TRUE(viewer.run_until_loaded(state));
    select(state.view, {Selection::Kind::primitive, 0});
    for (int i = 0; i < 4; ++i) viewer.frame(state);
    // The object's buttons; the camera panel has a Duplicate and a Delete
    // too, its Delete disabled (the only camera).
    const auto disabled_with_reason = [&](std::string_view label) {
        int found = 0;
        for (const UiItem& item : viewer.ui_items())
            if (item.label == label && !item.enabled && item.has_tooltip) ++found;
        return found;
    };
    EXPECT_EQ(disabled_with_reason("Duplicate"), 1);
    EXPECT_EQ(disabled_with_reason("Delete"), 2);
    for (const char* label : {"Add material block", "Add transform block", "Add operation"})
        EXPECT_EQ(disabled_with_reason(label), 1) << label;
    EXPECT_NE(why_not_rewrite_block(state.doc, {BlockKind::primitive, 0}).find("parts/ball.jts"),
              std::string::npos);
    const std::string text = document_text(state.doc);
    viewer.press_key(state, keys::del);
    EXPECT_EQ(document_text(state.doc), text);
    EXPECT_EQ(state.doc.scene.primitives.size(), 1u);
    EXPECT_NE(state.message.find("parts/ball.jts"), std::string::npos) << state.message;

    // The light is written in main.jts: its commands are there.
    EXPECT_EQ(why_not_rewrite_block(state.doc, {BlockKind::light, 0}), "");
    select(state.view, {Selection::Kind::light, 0});
    for (int i = 0; i < 4; ++i) viewer.frame(state);
    int duplicates = 0;
    for (const UiItem& item : viewer.ui_items())
        if (item.label == "Duplicate") {
            ++duplicates;
            EXPECT_TRUE(item.enabled);
        }
    EXPECT_EQ(duplicates, 2) << "the camera's and the light's";
    fs::remove_all(dir);
}

// Found in the real window: "} oops" typed in parts/objects.jts, the list
// under the text said "No errors or warnings." (typed text in an included
// file is read only when saved), and Ctrl+S then said it had an error. The
// list says when the text is checked instead.
TEST(ViewerIncludedFileEditor, TypedTextIsNotCalledFreeOfErrors) {
    HeadlessViewer viewer{1200, 700};
    ASSERT_TRUE(viewer.ok()) << viewer.error();
    const fs::path dir = write_including_scene("included-file-unchecked");
    AppState state{test_config()};
    open_scene(state, dir / "main.jts");
    ASSERT_TRUE(state.doc.loaded) << format_diagnostics(state.doc);
    viewer.press_key(state, keys::letter('T'));
    ASSERT_TRUE(viewer.click(state, "parts/ball.jts"));
    viewer.frame(state);
    EXPECT_NE(find_item(viewer.ui_items(), "No errors or warnings."), nullptr) << "as read";

    viewer.text_editor().jump = static_cast<int>(kIncludedBall.size());
    viewer.frame(state);
    viewer.frame(state);
    std::vector<KeyEvent> events;
    type(events, "} oops");
    viewer.key_events(state, events, 40.0, 16.0);
    viewer.frame(state);
    ASSERT_TRUE(has_included_drafts(state.editor));
    EXPECT_EQ(find_item(viewer.ui_items(), "No errors or warnings."), nullptr);
    EXPECT_NE(find_item(viewer.ui_items(), kCheckedWhenSaved), nullptr);

    viewer.press_key(state, keys::letter('S'), true);
    EXPECT_EQ(state.message.rfind("Not saved: ", 0), 0u) << state.message;
    viewer.frame(state);
    EXPECT_EQ(find_item(viewer.ui_items(), kCheckedWhenSaved), nullptr) << "the error instead";
    fs::remove_all(dir);
}

// Found in the real window: bad.jts, broken from the start, typed in and
// still with errors: the editor said "errors: showing the last good image"
// and the status line "the image is of the last good text", over an empty
// image area ("No scene loaded"): there was never a good one.
TEST(ViewerTextEditorOpen, TypedErrorsBeforeAnyGoodSceneNameNoLastGoodImage) {
    HeadlessViewer viewer{1200, 700};
    ASSERT_TRUE(viewer.ok()) << viewer.error();
    std::string broken;
    const fs::path file = broken_scene_copy("text-editor-never-good", broken);
    AppState state{test_config()};
    open_scene(state, file);
    ASSERT_FALSE(state.doc.loaded);
    viewer.press_key(state, keys::letter('T'));
    viewer.text_editor().jump = 0;
    viewer.frame(state);
    viewer.frame(state);
    std::vector<KeyEvent> events;
    type(events, "# still broken\n");
    viewer.key_events(state, events, 40.0, 16.0);
    state.check.checker.wait();
    viewer.frame(state);
    viewer.frame(state);
    ASSERT_FALSE(state.doc.loaded);
    ASSERT_TRUE(state.doc.draft.has_value()) << "the typed text, with its error";
    EXPECT_EQ(state.message.find("last good"), std::string::npos) << state.message;
    EXPECT_EQ(find_item(viewer.ui_items(), "errors: showing the last good image"), nullptr);
    EXPECT_NE(find_item(viewer.ui_items(), "errors: no image until they are mended"), nullptr);
    fs::remove_all(file.parent_path());
}

// Found in the real window (1500x950, the split scene): the hint beside an
// included file's name ran past the editor's right edge ("Ctrl+Z undoe").
// A hint that does not fit gives its brief form, the whole in its tooltip,
// on the same one line, in the scene file's view too.
TEST(ViewerIncludedFileEditor, TheHintsBesideTheFileNameFitTheEditor) {
    HeadlessViewer viewer{1100, 700};
    ASSERT_TRUE(viewer.ok()) << viewer.error();
    const fs::path dir = write_including_scene("included-file-hint");
    AppState state{test_config()};
    open_scene(state, dir / "main.jts");
    ASSERT_TRUE(state.doc.loaded) << format_diagnostics(state.doc);
    viewer.press_key(state, keys::letter('T'));
    ASSERT_TRUE(viewer.text_editor().open);
    const auto hint_fits = [&](const char* file) {
        viewer.frame(state);
        const UiItem* hint = find_item(viewer.ui_items(), "text editor hint");
        ASSERT_NE(hint, nullptr) << file;
        EXPECT_FALSE(hint->clipped) << file;
        const UiItem* text = find_item(viewer.ui_items(), "text");
        ASSERT_NE(text, nullptr);
        EXPECT_LE(hint->rect.x1, text->rect.x1) << file << ": past the text's right edge";
    };
    hint_fits("main.jts");
    ASSERT_TRUE(viewer.click(state, "parts/ball.jts"));
    hint_fits("parts/ball.jts");
    fs::remove_all(dir);
}

// Where not even the brief form fits (640x400) there is none.
TEST(ViewerIncludedFileEditor, NoHintIsCutInATinyWindow) {
    HeadlessViewer viewer{640, 400};
    ASSERT_TRUE(viewer.ok()) << viewer.error();
    AppState state{test_config()};
    open_scene(state, kScene);
    ASSERT_TRUE(state.doc.loaded) << format_diagnostics(state.doc);
    viewer.text_editor().open = true;
    viewer.frame(state);
    viewer.frame(state);
    ASSERT_NE(find_item(viewer.ui_items(), "text"), nullptr);
    const UiItem* hint = find_item(viewer.ui_items(), "text editor hint");
    EXPECT_TRUE(hint == nullptr || !hint->clipped) << "cut at the editor's edge";
}

// Found in the real window: text typed in an included file, then Esc to
// leave the editor. ImGui's Esc puts back the text the widget was entered
// with, so everything typed since the click was gone, the draft with it,
// and the next Esc or Ctrl+Q quit without asking. Esc leaves the text as
// it is, as it does in the scene file's text.
TEST(ViewerIncludedFileEditor, EscKeepsWhatWasTypedInAnIncludedFile) {
    HeadlessViewer viewer{1200, 700};
    ASSERT_TRUE(viewer.ok()) << viewer.error();
    const fs::path dir = write_including_scene("included-file-esc");
    const std::string main_text(kIncludingMain), ball_text(kIncludedBall);
    AppState state{test_config()};
    open_scene(state, dir / "main.jts");
    ASSERT_TRUE(state.doc.loaded) << format_diagnostics(state.doc);
    viewer.press_key(state, keys::letter('T'));
    TextEditorState& ed = viewer.text_editor();
    ASSERT_TRUE(viewer.click(state, "parts/ball.jts"));
    viewer.frame(state);
    ed.jump = 0;
    viewer.frame(state);
    viewer.frame(state);
    std::vector<KeyEvent> events;
    type(events, "# mine\n");
    viewer.key_events(state, events, 40.0, 16.0);
    const std::string typed = "# mine\n" + ball_text;
    ASSERT_EQ(ed.buffer, typed);

    events.clear();
    tap(events, keys::escape);
    viewer.key_events(state, events, 40.0, 16.0);
    EXPECT_EQ(ed.buffer, typed) << "Esc put back the text from before the typing";
    ASSERT_NE(draft_of(state.editor, state.editor.shown), nullptr);
    EXPECT_EQ(draft_of(state.editor, state.editor.shown)->text, typed);
    // Nothing is active now: a second Esc asks before quitting.
    events.clear();
    tap(events, keys::escape);
    viewer.key_events(state, events, 40.0, 16.0);
    EXPECT_FALSE(state.quit) << "quit with the typing unsaved";
    EXPECT_TRUE(state.files.unsaved_prompt.has_value());
    resolve_unsaved(state, UnsavedChoice::cancel);

    // Ctrl+Z still undoes the typing in this file once it is entered again.
    ed.jump = static_cast<int>(std::string("# mine\n").size());
    viewer.frame(state);
    viewer.frame(state);
    press_undo(viewer, state);
    EXPECT_EQ(ed.buffer, ball_text);
    fs::remove_all(dir);
}

}  // namespace
}  // namespace jt::view
