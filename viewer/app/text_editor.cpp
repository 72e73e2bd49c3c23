#include "app/text_editor.hpp"

#include "app/keys.hpp"
#include "app/panels/panels.hpp"
#include "app/panels/widgets.hpp"
#include "app/ui_items.hpp"
#include "jtracer/utf8.hpp"
#include "model/app_actions.hpp"
#include "model/document_edits.hpp"
#include "model/editor_files.hpp"
#include "model/picking.hpp"
#include "model/selection_commands.hpp"
#include "model/text_cursor.hpp"

#include <imgui.h>
#include <imgui_internal.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string_view>

namespace jt::view {

namespace {

constexpr ImU32 kErrorLine = IM_COL32(200, 40, 40, 70);
constexpr ImU32 kErrorText = IM_COL32(255, 110, 100, 255);
constexpr ImU32 kWarningLine = IM_COL32(200, 160, 40, 50);
constexpr ImU32 kCurrentLine = IM_COL32(255, 255, 255, 18);
constexpr ImU32 kLineNumber = IM_COL32(130, 130, 130, 255);

int line_count(const std::string& text) {
    return 1 + static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

int line_of(const std::string& text, int offset) {
    offset = std::clamp(offset, 0, static_cast<int>(text.size()));
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + offset, '\n'));
}

// The length of the longest line, in bytes.
std::size_t widest_line(std::string_view text) {
    std::size_t widest = 0;
    while (!text.empty()) {
        const std::size_t end = std::min(text.find('\n'), text.size());
        widest = std::max(widest, end);
        text.remove_prefix(std::min(end + 1, text.size()));
    }
    return widest;
}

// The text of line `line` (from 1).
std::string_view line_text(const std::string& text, int line) {
    const int start = offset_of(text, line, 1);
    const std::size_t end = text.find('\n', static_cast<std::size_t>(start));
    return std::string_view(text).substr(
        static_cast<std::size_t>(start),
        (end == std::string::npos ? text.size() : end) - static_cast<std::size_t>(start));
}

// ImGui's text widget decodes its text into 16-bit characters and encodes
// it back on every edit: a byte that is not UTF-8 is cut or replaced, and a
// character past U+FFFF (an emoji in a comment) came back as NUL bytes.
std::size_t first_unshowable_byte(std::string_view text) {
    std::size_t at = 0;
    while (at < text.size()) {
        const std::optional<Utf8Character> character = utf8_character_at(text, at);
        if (!character || character->code > IM_UNICODE_CODEPOINT_MAX) return at;
        at += character->length;
    }
    return std::string_view::npos;
}

void set_buffer(TextEditorState& ed, std::string text) {
    if (text == ed.shown) return;
    ed.unshowable = first_unshowable_byte(text);
    ed.shown = text;
    ed.buffer = std::move(text);
    ed.push = true;
}

// Keeps the shown file's text in the buffer: recomputed only when the
// document, the file shown or its draft changed.
void follow_document(const AppState& state, TextEditorState& ed) {
    const SceneDocument& doc = state.doc;
    const std::string& file = state.editor.shown;
    if (!file.empty()) {
        const IncludedDraft* draft = draft_of(state.editor, file);
        if (ed.shown_file == file && doc.revision == ed.shown_revision &&
            doc.file_generation == ed.shown_generation &&
            (draft != nullptr) == ed.shown_file_draft && state.editor.steps_taken == ed.shown_steps)
            return;
        ed.shown_file = file;
        ed.shown_revision = doc.revision;
        ed.shown_generation = doc.file_generation;
        ed.shown_file_draft = draft != nullptr;
        ed.shown_steps = state.editor.steps_taken;
        set_buffer(ed, draft ? draft->text : included_text(doc, file));
        return;
    }
    // The file's generation too: a file that has never loaded (no revision,
    // no base text yet) is shown from its text on disk, which each load
    // replaces.
    if (ed.shown_file.empty() && doc.revision == ed.shown_revision &&
        doc.file_generation == ed.shown_generation && doc.text == ed.shown_base &&
        doc.draft == ed.shown_draft)
        return;
    ed.shown_file.clear();
    ed.shown_base = doc.text;
    ed.shown_draft = doc.draft;
    ed.shown_revision = doc.revision;
    ed.shown_generation = doc.file_generation;
    set_buffer(ed, document_text(doc));
}

// The widget keeps its own undo history and, for Esc, the text it was
// activated with; both describe text the app may have replaced since (an undo
// of the app's, a panel edit), and acting on them would change bytes at stale
// offsets. Undo is the app's alone (Ctrl+Z walks the one history), so after
// every frame the widget's history is empty.
void forget_widget_history(ImGuiInputTextState& widget) {
    ImStb::StbUndoState& undo = widget.Stb.undostate;
    undo.undo_point = 0;
    undo.undo_char_point = 0;
    undo.redo_point = STB_TEXTEDIT_UNDOSTATECOUNT;
    undo.redo_char_point = STB_TEXTEDIT_UNDOCHARCOUNT;
}

// Esc leaves the editor and keeps the text: the widget's Esc would put back
// the text it was activated with, throwing away what was typed since (in an
// included file, the whole draft, unasked). So its Esc text is the text now.
void keep_text_on_escape(ImGuiInputTextState& widget, std::string_view text) {
    ImVector<char>& initial = widget.InitialTextA;
    if (initial.Size == static_cast<int>(text.size()) + 1 &&
        std::memcmp(initial.Data, text.data(), text.size()) == 0)
        return;
    initial.resize(static_cast<int>(text.size()) + 1);
    std::memcpy(initial.Data, text.data(), text.size());
    initial[static_cast<int>(text.size())] = '\0';
}

int on_input(ImGuiInputTextCallbackData* data) {
    auto& ed = *static_cast<TextEditorState*>(data->UserData);
    if (ed.push) {
        ed.push = false;
        const std::string_view now(data->Buf, static_cast<std::size_t>(data->BufTextLen));
        if (now != ed.buffer) {
            const int cursor = cursor_after_replace(now, ed.buffer, data->CursorPos);
            data->DeleteChars(0, data->BufTextLen);
            data->InsertChars(0, ed.buffer.data(), ed.buffer.data() + ed.buffer.size());
            data->CursorPos = data->SelectionStart = data->SelectionEnd = cursor;
        }
    }
    if (ed.jump) {
        data->CursorPos = data->SelectionStart = data->SelectionEnd =
            std::clamp(*ed.jump, 0, data->BufTextLen);
        ed.jump.reset();
    }
    ed.cursor = data->CursorPos;
    if (ImGuiInputTextState* widget = ImGui::GetInputTextState(ImGui::GetActiveID())) {
        forget_widget_history(*widget);
        keep_text_on_escape(
            *widget, std::string_view(data->Buf, static_cast<std::size_t>(data->BufTextLen)));
    }
    return 0;
}

// The diagnostics that point into the scene file's text shown.
bool diagnostics_apply(const AppState& state, const TextEditorState& ed) {
    return state.doc.diagnostics_source == ed.shown ||
           (!state.doc.draft && state.doc.diagnostics_source == state.doc.text);
}

// The reading of an included file a diagnostic is in, or null for the scene file's.
const SourceFile* reading_of_diagnostic(const SceneDocument& doc, const Diagnostic& d) {
    if (d.pos.file == 0 || d.pos.file > doc.diagnostics_files.size()) return nullptr;
    return &doc.diagnostics_files[d.pos.file - 1];
}

// Whether `d` is listed under the text shown: in the scene file's view
// every diagnostic (those in included files named by their file), in an
// included file's the ones in the text shown.
bool listed(const AppState& state, const TextEditorState& ed, const Diagnostic& d) {
    if (ed.shown_file.empty()) return diagnostics_apply(state, ed);
    const SourceFile* read = reading_of_diagnostic(state.doc, d);
    return read && read->canonical == ed.shown_file && read->text == ed.shown;
}

// Whether `d` marks a line of the text shown.
bool marked(const AppState& state, const TextEditorState& ed, const Diagnostic& d) {
    if (ed.shown_file.empty()) return d.pos.file == 0 && diagnostics_apply(state, ed);
    return listed(state, ed, d);
}

void error_list(AppState& state, TextEditorState& ed, float height) {
    ImGui::BeginChild("##errors", ImVec2(0, height), true);
    int shown = 0;
    const IncludedDraft* draft = draft_of(state.editor, ed.shown_file);
    if (draft && !draft->problem.empty()) {
        ++shown;
        ImGui::PushStyleColor(ImGuiCol_Text, kErrorText);
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextUnformatted(("Not saved: " + draft->problem).c_str());
        ImGui::PopTextWrapPos();
        ImGui::PopStyleColor();
    }
    {
        for (const Diagnostic& d : state.doc.diagnostics) {
            if (!listed(state, ed, d)) continue;
            ++shown;
            const bool error = d.severity == Severity::error;
            // One in an included file, listed under the scene file's text, names its file.
            const SourceFile* in =
                ed.shown_file.empty() ? reading_of_diagnostic(state.doc, d) : nullptr;
            char where[320];
            if (d.pos.line > 0) {
                const std::string_view file =
                    in ? short_file_name(state.doc, in->name) : std::string_view();
                std::snprintf(where, sizeof where,
                              "%.*s%s%d:%d: %s: ", static_cast<int>(file.size()), file.data(),
                              in ? ":" : "", d.pos.line, d.pos.column, error ? "error" : "warning");
            } else
                std::snprintf(where, sizeof where, "%s: ", error ? "error" : "warning");
            // Into a string kept from frame to frame: an idle frame allocates nothing.
            std::string& label = ed.label;
            label.assign(where);
            label += d.message;
            // Wrapped, so that a long message is read whole; a click goes to its place.
            ImGui::PushStyleColor(ImGuiCol_Text, error ? kErrorText : IM_COL32(230, 190, 80, 255));
            ImGui::PushTextWrapPos(0.0f);
            ImGui::TextUnformatted(label.c_str());
            ImGui::PopTextWrapPos();
            ImGui::PopStyleColor();
            if (ImGui::IsItemHovered()) {
                ImGui::GetWindowDrawList()->AddRectFilled(ImGui::GetItemRectMin(),
                                                          ImGui::GetItemRectMax(), kCurrentLine);
                if (d.pos.line > 0) ImGui::SetMouseCursor(ImGuiMouseCursor_Hand);
            }
            if (ImGui::IsItemClicked() && d.pos.line > 0) {
                if (in) {
                    // Opens the file it is in, at its place.
                    show_file(state.editor, state.doc, in->canonical);
                    follow_document(state, ed);
                }
                ed.jump = offset_of(ed.buffer, d.pos.line, d.pos.column);
                ed.scroll_to = d.pos.line;
            }
            note_item(label.c_str(), false);
        }
    }
    if (shown == 0) {
        const char* none = draft ? kCheckedWhenSaved : "No errors or warnings.";
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextDisabled("%s", none);
        ImGui::PopTextWrapPos();
        note_item(none, false);
    }
    ImGui::EndChild();
}

// The text as the document's base shows the blocks where its source map
// says: a pick in the image scrolls to the block picked, and a click in a
// block selects it. (With panel edits or a draft the offsets may differ.)
void follow_selection(AppState& state, TextEditorState& ed, bool clicked) {
    if (!ed.shown_file.empty() || ed.buffer != state.doc.text) return;
    if (clicked) {
        const Selection at = selection_at_offset(state, static_cast<std::size_t>(ed.cursor));
        if (at.kind != Selection::Kind::none && at != state.view.selection) select(state.view, at);
    } else if (state.view.reveal_selection) {
        if (const std::optional<int> line = selection_line(state)) ed.scroll_to = *line;
    }
}

// In an included file Ctrl+Z walks that file's typing (editor_files.hpp),
// in steps ended by a pause as in the scene file, not the scene's history.
void undo_keys(AppState& state, bool included) {
    const ImGuiIO& io = ImGui::GetIO();
    if (!io.KeyCtrl) return;
    const bool undo_key = ImGui::IsKeyPressed(keys::letter('Z'), false) && !io.KeyShift;
    const bool redo_key = (ImGui::IsKeyPressed(keys::letter('Z'), false) && io.KeyShift) ||
                          ImGui::IsKeyPressed(keys::letter('Y'), false);
    if (included) {
        if (undo_key) undo_included_typing(state.editor, state.doc);
        if (redo_key) redo_included_typing(state.editor, state.doc);
    } else {
        if (undo_key) undo(state);
        if (redo_key) redo(state);
    }
    if (ImGui::IsKeyPressed(keys::letter('S'), false)) save_scene(state);
}

// One button a file when the scene includes any: the scene file, then each
// included file once (and one typed in that the scene no longer reads).
void file_buttons(AppState& state, TextEditorState& ed, const std::string& main_name) {
    const EditorFiles& files = state.editor;
    const SceneDocument& doc = state.doc;
    const std::span<const SourceFile> readings = latest_readings(doc);
    if (readings.empty() && files.drafts.empty()) return;
    // A file read a thousand times is listed once: found once per change, not every frame.
    if (!ed.listed_once || ed.listed_revision != doc.revision ||
        ed.listed_generation != doc.file_generation || ed.listed_failed != doc.load_failed) {
        ed.listed_once = true;
        ed.listed_revision = doc.revision;
        ed.listed_generation = doc.file_generation;
        ed.listed_failed = doc.load_failed;
        ed.listed.clear();
        for (std::size_t i = 0; i < readings.size(); ++i)
            if (first_reading(readings, i)) ed.listed.push_back(i);
    }
    const auto file_button = [&](std::string_view name, const std::string& canonical, bool first) {
        const bool shown = files.shown == canonical;
        const bool typed = canonical.empty() ? has_unsaved_edits(state.doc)
                                             : draft_of(files, canonical) != nullptr;
        char label[320];
        std::snprintf(label, sizeof label, "%.*s%s", static_cast<int>(name.size()), name.data(),
                      typed ? " *" : "");
        if (!first) same_line_if_fits(label);
        if (shown)
            ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
        const bool clicked = ImGui::SmallButton(label);
        if (shown) ImGui::PopStyleColor();
        note_item(label, false);
        if (clicked && !shown) show_file(state.editor, state.doc, canonical);
    };
    static const std::string scene_file;
    file_button(main_name, scene_file, true);
    for (const std::size_t i : ed.listed)
        if (i < readings.size())
            file_button(short_file_name(doc, readings[i].name), readings[i].canonical, false);
    for (const IncludedDraft& d : files.drafts)
        if (reading_count(readings, d.canonical) == 0) file_button(d.name, d.canonical, false);
}

// The line under the file buttons for an included file: its name, how many
// times it is read, and what Save does.
void included_header(AppState& state, const std::string& canonical) {
    const IncludedDraft* draft = draft_of(state.editor, canonical);
    const SourceFile* read = reading_of(state.doc, canonical);
    const std::string_view name = read    ? short_file_name(state.doc, read->name)
                                  : draft ? std::string_view(draft->name)
                                          : std::string_view();
    ImGui::Text("%.*s%s", static_cast<int>(name.size()), name.data(), draft ? " *" : "");
    ImGui::SameLine();
    hint_text("Ctrl+S saves it and reloads the scene; Ctrl+Z undoes typing here",
              "Ctrl+S saves, Ctrl+Z undoes here", "text editor hint");
    // Lines of their own, wrapped: they come with a change of the file, not
    // with each keystroke.
    if (const int count = reading_count(latest_readings(state.doc), canonical); count > 1) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.9f, 0.75f, 0.3f, 1.0f));
        ImGui::TextWrapped("Included %d times: every object read from it changes", count);
        ImGui::PopStyleColor();
    }
    if (!read) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.7f, 0.3f, 1.0f));
        ImGui::TextWrapped("The scene no longer reads this file: Save scene still writes it");
        ImGui::PopStyleColor();
    }
    if (draft && button("Revert", "Drop what was typed in this file: show its text again"))
        revert_included_draft(state.editor, canonical);
}

}  // namespace

int offset_of(const std::string& text, int line, int column) {
    std::size_t at = 0;
    for (int l = 1; l < line; ++l) {
        const std::size_t newline = text.find('\n', at);
        if (newline == std::string::npos) return static_cast<int>(text.size());
        at = newline + 1;
    }
    const std::size_t end = std::min(text.find('\n', at), text.size());
    return static_cast<int>(std::min(at + static_cast<std::size_t>(std::max(column, 1) - 1), end));
}

void text_editor(AppState& state, TextEditorState& ed, float x0, float y0, float x1, float y1) {
    ImGui::SetNextWindowPos(ImVec2(x0, y0));
    ImGui::SetNextWindowSize(ImVec2(x1 - x0, y1 - y0));
    ImGui::Begin("Text", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoResize);
    note_window("text editor");
    const SceneDocument& doc = state.doc;
    const std::string name = doc.path.filename().string();
    if (!doc.loaded && doc.path.empty()) {
        ImGui::TextDisabled("No scene is open.");
        ImGui::End();
        return;
    }
    file_buttons(state, ed, name);
    // A file no longer read and no longer typed in shows the scene file.
    if (!state.editor.shown.empty() && !reading_of(doc, state.editor.shown) &&
        !draft_of(state.editor, state.editor.shown))
        state.editor.shown.clear();
    follow_document(state, ed);
    const bool included = !ed.shown_file.empty();
    if (ed.buffer.find('\0') != std::string::npos) {
        // The widget's text ends at the first NUL: editing would cut the rest.
        ImGui::TextWrapped(
            "%s holds NUL bytes: it is no text the editor can show. Diagnostics say what is "
            "wrong; the viewer reloads it when it changes.",
            name.c_str());
        ImGui::End();
        return;
    }
    if (ed.unshowable != std::string::npos) {
        const std::string_view before(ed.shown.data(), ed.unshowable);
        const long line = 1 + std::count(before.begin(), before.end(), '\n');
        const std::size_t column = ed.unshowable - (before.rfind('\n') + 1) + 1;
        ImGui::TextWrapped(
            "This text has a character at line %ld, column %zu that the editor cannot keep as "
            "it is: a byte that is not UTF-8 text, or one past U+FFFF (an emoji, say). Edit it "
            "in another editor; the viewer reloads it when it changes.",
            line, column);
        note_item("not UTF-8 text", false);
        ImGui::End();
        return;
    }
    if (ed.buffer.size() > kMaxEditableText) {
        ImGui::TextWrapped(
            "%s is %.1f MB: too large to edit here. Edit it in another editor; the "
            "viewer reloads it when it changes.",
            name.c_str(), static_cast<double>(ed.buffer.size()) / 1e6);
        ImGui::End();
        return;
    }
    const bool draft = doc.draft.has_value();
    if (included) {
        included_header(state, ed.shown_file);
    } else {
        ImGui::Text("%s%s", name.c_str(), has_unsaved_edits(doc) ? " *" : "");
        ImGui::SameLine();
        if (state.check.checker.in_flight())
            ImGui::TextDisabled("checking...");
        else if (draft) {
            // Before any good load there is no image to keep.
            const char* errors = doc.loaded ? "errors: showing the last good image"
                                            : "errors: no image until they are mended";
            ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", errors);
            note_item(errors, false);
        } else
            hint_text("Ctrl+Z undoes panel and text edits alike", "Ctrl+Z undoes all edits",
                      "text editor hint");
        if (doc.file_deleted) {
            ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.7f, 0.3f, 1.0f));
            ImGui::TextWrapped(
                "%s was deleted on disk: this is the viewer's copy; Save scene writes it again",
                name.c_str());
            ImGui::PopStyleColor();
        }
    }

    const float list_height = ImGui::GetTextLineHeightWithSpacing() * 5.0f + 8.0f;
    const float editor_height =
        std::max(ImGui::GetContentRegionAvail().y - list_height - ImGui::GetStyle().ItemSpacing.y,
                 ImGui::GetTextLineHeight() * 3.0f);
    push_monospace_font();
    const float line_h = ImGui::GetTextLineHeight();
    const int lines = line_count(ed.buffer);
    char widest[16];
    std::snprintf(widest, sizeof widest, "%d", lines);
    const float gutter = ImGui::CalcTextSize(widest).x + ImGui::CalcTextSize("  ").x;
    ImGui::BeginChild("##scroll", ImVec2(0, editor_height), true,
                      ImGuiWindowFlags_HorizontalScrollbar);
    // One view for every file: another file shown (opened, or an included
    // one) would keep the scroll of the one before, cut off at the left.
    if (doc.path.native() != ed.scrolled_path || ed.shown_file != ed.scrolled_file) {
        ed.scrolled_path = doc.path.native();
        ed.scrolled_file = ed.shown_file;
        ImGui::SetScrollX(0.0f);
        ImGui::SetScrollY(0.0f);
    }
    // Each file in a widget of its own: ImGui keeps a widget's undo history
    // while it is active, and one file's must never apply to another's text.
    ImGui::PushID(ed.shown_file.c_str());
    const ImGuiID widget = ImGui::GetID("##source");
    const bool active = ImGui::GetActiveID() == widget;
    if (active) undo_keys(state, included);
    follow_document(state, ed);  // an undo or a save just now shows at once
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const float pad_y = ImGui::GetStyle().FramePadding.y;
    const float pad_x = ImGui::GetStyle().FramePadding.x;
    ImGui::SetCursorPosX(ImGui::GetCursorPosX() + gutter);
    if (ed.jump && !active) ImGui::SetKeyboardFocusHere();
    // As wide as the widest line: the widget then never scrolls sideways
    // itself (the view does, below), so what is drawn over it lines up.
    const float char_w = ImGui::CalcTextSize("M").x;
    const float width =
        std::max(ImGui::GetContentRegionAvail().x,
                 static_cast<float>(widest_line(ed.buffer) + 4) * char_w + 2.0f * pad_x);
    // At least the view's height, so that a click anywhere below the text lands in it.
    const ImVec2 size(width, std::max(static_cast<float>(lines + 1) * line_h + 2.0f * pad_y,
                                      ImGui::GetContentRegionAvail().y));
    ImGui::PushStyleColor(ImGuiCol_FrameBg, IM_COL32(0, 0, 0, 0));
    const bool changed = ImGui::InputTextMultiline(
        "##source", &ed.buffer, size,
        ImGuiInputTextFlags_AllowTabInput | ImGuiInputTextFlags_CallbackAlways, on_input, &ed);
    ImGui::PopStyleColor();
    ImGui::PopID();
    note_item("text", false);
    const bool clicked =
        ImGui::IsMouseClicked(ImGuiMouseButton_Left) &&
        ImGui::IsMouseHoveringRect(ImGui::GetItemRectMin(), ImGui::GetItemRectMax());
    // The cursor a click puts is read in the callback of the frame after (the
    // widget runs no callback in the frame that activates it).
    follow_selection(state, ed, ed.select_at_cursor);
    ed.select_at_cursor = clicked && ImGui::GetActiveID() == widget;
    if (changed && ed.buffer != ed.shown) {
        ed.shown = ed.buffer;
        if (included) {
            // ImGui's clock, the frames' own: a pause between keys is one
            // in the frames' time (simulated in the headless tests).
            const auto now = std::chrono::steady_clock::time_point(
                std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                    std::chrono::duration<double>(ImGui::GetTime())));
            type_included_text(state.editor, state.doc, ed.buffer, now);
            // The draft now holds what the buffer holds.
            ed.shown_file_draft = draft_of(state.editor, ed.shown_file) != nullptr;
        } else {
            type_text(state, ed.buffer);
            ed.shown_draft = state.doc.draft;  // the document now holds what the buffer holds
        }
    }

    // Line numbers, the cursor's line and the marked lines, over the visible part only.
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const float scroll = ImGui::GetScrollY();
    const float view_h = ImGui::GetWindowHeight();
    const int first = std::max(1, static_cast<int>(scroll / line_h));
    const int last = std::min(lines, first + static_cast<int>(view_h / line_h) + 2);
    const float left = origin.x;
    const float right = origin.x + gutter + width;
    auto line_y = [&](int line) {
        return origin.y + pad_y + static_cast<float>(line - 1) * line_h;
    };
    ed.line1_x = left + gutter + pad_x;
    ed.line1_y = line_y(1);
    ed.line_height = line_h;
    if (ImGui::GetActiveID() == widget) {
        const int current = line_of(ed.buffer, ed.cursor);
        draw->AddRectFilled(ImVec2(left, line_y(current)), ImVec2(right, line_y(current) + line_h),
                            kCurrentLine);
    }
    // The numbers stay at the view's left edge when the text scrolls
    // sideways (the cursor at the end of a long line): they are what the
    // diagnostics point at. The text scrolled under them is covered, over
    // the text: the multiline widget draws it in a child window of its own,
    // which ImGui draws after this one.
    const float scroll_x = ImGui::GetScrollX();
    const float numbers_x = left + scroll_x;
    ImDrawList* numbers = draw;
    if (scroll_x > 0.0f) {
        char name[256];
        ImFormatString(name, sizeof name, "%s/%s_%08X", ImGui::GetCurrentWindow()->Name, "##source",
                       widget);
        if (const ImGuiWindow* text_window = ImGui::FindWindowByName(name)) {
            numbers = text_window->DrawList;
            const ImGuiWindow* view = ImGui::GetCurrentWindow();
            numbers->PushClipRect(view->InnerClipRect.Min, view->InnerClipRect.Max);
            ImVec4 background = ImGui::GetStyleColorVec4(ImGuiCol_WindowBg);
            background.w = 1.0f;
            numbers->AddRectFilled(ImVec2(view->InnerClipRect.Min.x, line_y(first)),
                                   ImVec2(numbers_x + gutter, line_y(last) + line_h),
                                   ImGui::ColorConvertFloat4ToU32(background));
        }
    }
    for (int line = first; line <= last; ++line) {
        char number[16];
        std::snprintf(number, sizeof number, "%*d", static_cast<int>(std::strlen(widest)), line);
        numbers->AddText(ImVec2(numbers_x, line_y(line)), kLineNumber, number);
    }
    if (numbers != draw) numbers->PopClipRect();
    {
        for (const Diagnostic& d : doc.diagnostics) {
            if (d.pos.line <= 0 || d.pos.line > lines || !marked(state, ed, d)) continue;
            const bool error = d.severity == Severity::error;
            const float y = line_y(d.pos.line);
            draw->AddRectFilled(ImVec2(left, y), ImVec2(right, y + line_h),
                                error ? kErrorLine : kWarningLine);
            const std::string_view content = line_text(ed.buffer, d.pos.line);
            const float end_x =
                ImGui::CalcTextSize(content.data(), content.data() + content.size()).x;
            const float x = left + gutter + pad_x + end_x + 2.0f * line_h;
            std::string& note = ed.label;  // kept from frame to frame, as the list's
            note.assign(error ? "<- " : "<- warning: ");
            note += d.message;
            draw->AddText(ImVec2(x, y), error ? kErrorText : IM_COL32(230, 190, 80, 255),
                          note.c_str());
            // The column, under the line.
            const std::string_view before = content.substr(
                0,
                std::min(content.size(), static_cast<std::size_t>(std::max(d.pos.column, 1) - 1)));
            const float cx = left + gutter + pad_x +
                             ImGui::CalcTextSize(before.data(), before.data() + before.size()).x;
            draw->AddLine(ImVec2(cx, y + line_h - 1), ImVec2(cx + line_h * 0.6f, y + line_h - 1),
                          kErrorText, 2.0f);
        }
    }
    if (ed.scroll_to) {
        const float y = static_cast<float>(*ed.scroll_to - 1) * line_h;
        if (y < scroll || y > scroll + view_h - 3 * line_h)
            ImGui::SetScrollY(std::max(0.0f, y - view_h / 3.0f));
        ed.scroll_to.reset();
    } else if (ImGui::GetActiveID() == widget) {
        // Typing past the bottom or top: the view follows the cursor, its
        // line and the next one in the part not under a scroll bar (a long
        // line brings one across the bottom).
        const ImRect visible = ImGui::GetCurrentWindow()->InnerClipRect;
        const float top = line_y(line_of(ed.buffer, ed.cursor));
        if (top < visible.Min.y)
            ImGui::SetScrollY(std::max(0.0f, scroll - (visible.Min.y - top)));
        else if (top + 2 * line_h > visible.Max.y)
            ImGui::SetScrollY(scroll + (top + 2 * line_h - visible.Max.y));
    }
    if (ImGui::GetActiveID() == widget) {
        // And sideways: the cursor's column stays in view.
        const int line = line_of(ed.buffer, ed.cursor);
        const int column_offset = ed.cursor - offset_of(ed.buffer, line, 1);
        const std::string_view before =
            line_text(ed.buffer, line).substr(0, static_cast<std::size_t>(column_offset));
        const float x =
            gutter + pad_x + ImGui::CalcTextSize(before.data(), before.data() + before.size()).x;
        const float scroll_x = ImGui::GetScrollX();
        const float view_w =
            ImGui::GetWindowContentRegionMax().x - ImGui::GetWindowContentRegionMin().x;
        const float margin = 4.0f * char_w;
        if (x < scroll_x + gutter + margin) ImGui::SetScrollX(std::max(0.0f, x - gutter - margin));
        if (x > scroll_x + view_w - margin) ImGui::SetScrollX(x - view_w + margin);
        ed.cursor_x = origin.x + x;
    }
    note_window("text view");
    ImGui::EndChild();
    pop_monospace_font();
    error_list(state, ed, list_height);
    ImGui::End();
}

}  // namespace jt::view
