// The monkey: random but valid UI events through the viewer's frame code in
// an OSMesa context, as a careless user at speed would make them: mouse moves,
// drags and wheel on the image, clicks and drags on every control the last
// frame drew, keys (Esc, Ctrl+Z, Ctrl+Shift+Z, Space, C, R, S, Ctrl+S,
// Ctrl+Q, ...), typing, camera changes, copy-to-scene, clicks that select in
// the image, Alt+drags that move an object or light (with Shift, with Esc
// half-way), the Objects filter, structure edits (add, duplicate, delete
// blocks, transform operations, cameras), text typed into the document
// (broken and mended), key sequences typed fast into the text editor
// through the window's KeyTaps, and the scene file
// rewritten, truncated, deleted, replaced by garbage or by a scene with fewer
// cameras while the viewer has it open. After every event it checks:
//
//   - no frame took ten seconds or more (no hang);
//   - the scene file on disk is whole: a text the monkey wrote, or a save of
//     the viewer that parses to exactly the viewer's scene; no temporary
//     file is left beside it; every image saved is a whole PNG;
//   - with no undo history (just loaded), the scene is the file's scene;
//   - keys typed fast come out in order, Ctrl+Z past the start of the
//     history changes nothing, and redo to the end gives the typing back;
//   - a click on the image selects something the scene has (or nothing);
//   - an Alt+drag that moved something is one undo step, which gives the
//     text before the drag back (and redo the moved one); one cancelled with
//     Esc, or that moved nothing, left the text as it was;
// and every few events, undoing everything gives back the scene the history
// started from (the loaded file's, when nothing was saved since) and redoing
// everything the scene before. Crashes and sanitizer reports end the run.
//
//   viewer_monkey --seed 7 --events 500     one run (replay a failure by its seed)
//   viewer_monkey --soak 2000               edit/reload cycles; resident memory bounded

#include "app/headless.hpp"
#include "app/keys.hpp"
#include "app/panels/panels.hpp"
#include "common/files.hpp"
#include "jtracer/parser.hpp"
#include "jtracer/png.hpp"
#include "jtracer/schema.hpp"
#include "model/ab_compare.hpp"
#include "model/app_actions.hpp"
#include "model/document_edits.hpp"
#include "model/picking.hpp"
#include "model/render_region.hpp"

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using namespace jt;
using namespace jt::view;
using jt::test::read_file;
using jt::test::write_file;

// A frame this long is a hang, not a slow frame. Under OSMesa every GL call
// is software rasterisation (llvmpipe), so a texture upload or a zoomed-in
// image takes 0.3-1 s of a frame here, more under the sanitizers on a busy
// machine: a tighter bound would time llvmpipe, not the viewer. How fast
// frames are is bench/viewer's figure (viewer_latency), never a test's.
constexpr double hang_frame_seconds = 10.0;

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

long resident_kib() {
    std::ifstream statm("/proc/self/statm");
    long pages = 0, resident = 0;
    statm >> pages >> resident;
    return resident * (::sysconf(_SC_PAGESIZE) / 1024);
}

class Monkey {
  public:
    Monkey(std::uint32_t seed, const fs::path& dir)
        : random_(seed), seed_(seed), dir_(dir), file_(dir / "scene.jts") {
        original_ = read_file(fs::path(JT_VIEWER_TEST_DIR) / "scenes" / "two_cameras.jts");
        texts_ = {
            original_,
            replaced(original_, "pigment: <0.9, 0.2, 0.1>;", "pigment: <0.2, 0.9, 0.1>;"),
            replaced(original_, "width: 64;", "width: 48;"),
            // One camera fewer: the selected one may be gone.
            replaced(original_,
                     "    perspective_camera {\n        name: \"top\";\n        position: <4, 6, "
                     "3>;\n        look_at: <0, 0, 0>;\n        aspect: 1.3333333333333333;\n  "
                     "      fov: 50;\n    }\n",
                     ""),
        };
        write_file(file_, original_);
        written_ = original_;
        state_.config.watch_interval = std::chrono::milliseconds(0);
        state_.config.render_threads = 1;  // the frames are what is tested
    }

    bool ok() const { return failures_ == 0; }
    bool verbose_ = false;

    bool start() {
        if (!viewer_.ok()) {
            std::fprintf(stderr, "monkey: no OSMesa context: %s\n", viewer_.error().c_str());
            return false;
        }
        open_scene(state_, file_);
        viewer_.frame(state_);
        return true;
    }

    void run(int events) {
        for (int i = 0; i < events && failures_ < 5; ++i) {
            event_ = i;
            keep_paths_in_scratch();
            const auto started = std::chrono::steady_clock::now();
            random_event();
            if (verbose_)
                std::fprintf(stderr, "%4d %-40s %5.0f ms  %s | %s\n", i, last_event_.c_str(),
                             std::chrono::duration<double, std::milli>(
                                 std::chrono::steady_clock::now() - started)
                                 .count(),
                             state_.message.c_str(), render_status(state_).c_str());
            check_after_event();
            if (i % 25 == 24) check_undo_round_trip();
        }
        std::fprintf(stderr,
                     "monkey: seed %u: %d events, %d frames, slowest %.0f ms (%.0f ms less waits "
                     "for a core), %d saves checked, %d undo round trips, %zu cameras, %d "
                     "failures\n",
                     seed_, events, frames_, viewer_.slowest_frame() * 1000.0,
                     viewer_.slowest_unqueued_frame() * 1000.0, saves_checked_, round_trips_,
                     state_.doc.scene.cameras.size(), failures_);
    }

    // Edit, then the file changes on disk and is reloaded (the edit dropped
    // at the prompt), over and over: memory must not grow with the cycles.
    void soak(int cycles) {
        state_.view.show_ui = false;  // the cycles, not the panels, are what is measured
        long after_warm_up = 0;
        const int warm_up = std::min(200, cycles / 4);
        for (int i = 0; i < cycles; ++i) {
            edit_scene(state_, [i](Scene& s) {
                s.primitives[1].material.pigment = Colour(0.1 + 0.8 * ((i * 37) % 100) / 100.0);
            });
            viewer_.frame(state_);
            rewrite_scene(texts_[static_cast<std::size_t>(i) % 2]);
            wait_for_load();
            if (state_.files.pending_reload) resolve_reload(state_, ReloadChoice::drop_edits);
            viewer_.frame(state_);
            if (has_unsaved_edits(state_.doc)) fail("edits left after drop_edits");
            if (i + 1 == warm_up) after_warm_up = resident_kib();
        }
        const long end = resident_kib();
        const long growth = end - after_warm_up;
        std::fprintf(stderr,
                     "monkey: soak: %d edit/reload cycles, resident %ld KiB after %d, %ld KiB at "
                     "the end (%+ld KiB), slowest frame %.0f ms\n",
                     cycles, after_warm_up, warm_up, end, growth, viewer_.slowest_frame() * 1000.0);
#if defined(__SANITIZE_ADDRESS__)
        // AddressSanitizer keeps freed memory in quarantine: resident size says
        // nothing here. Leaks are its own report at exit.
#else
        constexpr long bound_kib = 16 * 1024;
        if (growth > bound_kib) fail("resident memory grew by " + std::to_string(growth) + " KiB");
#endif
        if (viewer_.slowest_unqueued_frame() >= hang_frame_seconds)
            fail("a frame took ten seconds or more");
    }

  private:
    int pick(int n) {
        return std::uniform_int_distribution<int>(0, n - 1)(random_);
    }
    float uniform(float a, float b) {
        return std::uniform_real_distribution<float>(a, b)(random_);
    }

    void fail(const std::string& what) {
        ++failures_;
        std::fprintf(stderr, "monkey: FAILED (seed %u, event %d: %s): %s\n", seed_, event_,
                     last_event_.c_str(), what.c_str());
    }

    void frame() {
        viewer_.frame(state_);
        ++frames_;
    }

    void rewrite_scene(const std::string& text) {
        if (pick(2) == 0) {
            write_file(file_, text);
        } else {  // as editors save: a new file renamed over the old
            write_file(dir_ / "editor.tmp", text);
            fs::rename(dir_ / "editor.tmp", file_);
        }
        written_ = text;
        file_deleted_ = false;
    }

    // The next frame notices the change on disk and starts its load; this
    // waits for the loader to finish it (its own event, however long a loaded
    // machine takes: a hang is the test's timeout) instead of running frames
    // against the clock, and the frame after takes it in.
    void wait_for_load() {
        frame();
        state_.files.loader.wait();
        frame();
    }

    // Whatever the monkey typed, the viewer writes only inside the scratch folder.
    void keep_paths_in_scratch() {
        state_.fields.save_image_path = (dir_ / "shot.png").string();
        state_.fields.save_scene_path = (dir_ / (pick(2) ? "copy.jts" : "scene.jts")).string();
        state_.fields.open_path_input = (pick(4) ? file_ : dir_ / "copy.jts").string();
    }

    void random_event() {
        ImGuiIO& io = ImGui::GetIO();
        const float w = static_cast<float>(viewer_.width()),
                    h = static_cast<float>(viewer_.height());
        const int kind = pick(112);
        if (kind >= 110) {
            key_sequence_in_the_text();
        } else if (kind >= 106) {
            move_object_event(w, h);
        } else if (kind >= 100) {
            image_tool_event(w, h);
        } else if (kind < 12) {
            last_event_ = "mouse move";
            io.MousePos = ImVec2(uniform(0, w), uniform(0, h));
            frame();
        } else if (kind < 24) {
            const int button = pick(3);
            last_event_ = "drag with button " + std::to_string(button);
            viewer_.drag(state_, button, uniform(0, w), uniform(0, h), uniform(0, w),
                         uniform(0, h));
            frames_ += 6;
        } else if (kind < 28) {
            last_event_ = "wheel";
            viewer_.scroll(state_, uniform(0, w), uniform(0, h), uniform(-3, 3));
            frames_ += 2;
        } else if (kind < 48) {
            click_some_item();
        } else if (kind < 56) {
            drag_some_item();
        } else if (kind < 74) {
            press_some_key();
        } else if (kind < 78) {
            last_event_ = "typing";
            const char* text = pick(2) ? "abc" : "x 1";
            for (const char* c = text; *c; ++c) io.AddInputCharacter(static_cast<unsigned>(*c));
            frame();
        } else if (kind < 82) {
            last_event_ = "camera";
            if (pick(2)) {
                select_camera(state_, pick(4) - 1);
            } else {
                use_free_camera(state_.view, state_.doc.scene);
                orbit(state_.view.free_camera, uniform(-50, 50), uniform(-50, 50), 240);
            }
            frame();
        } else if (kind < 84) {
            last_event_ = "copy to scene";
            copy_free_camera_to_scene(state_, "monkey" + std::to_string(pick(3)));
            frame();
        } else if (kind < 88) {
            last_event_ = "click to select";
            const float x = uniform(0, w), y = uniform(0, h);
            const Selection before = state_.view.selection;
            viewer_.drag(state_, 0, x, y, x, y);
            frames_ += 6;
            check_selection(before);
        } else if (kind < 89) {
            last_event_ = "object filter";
            const char* filters[] = {"", "sphere", "plane 1", "zzz"};
            state_.fields.object_filter = filters[pick(4)];
            frame();
        } else if (kind < 92) {
            structure_edit();
            frame();
        } else if (kind < 94) {
            type_into_the_text();
            frame();
        } else {
            change_the_file();
        }
    }

    // The image view and its tools: zoom, pan, Render region, A/B compare.
    void image_tool_event(float w, float h) {
        ImGuiIO& io = ImGui::GetIO();
        switch (pick(6)) {
            case 0:
                last_event_ = "Ctrl+wheel";
                viewer_.scroll(state_, uniform(0, w), uniform(0, h), uniform(-4, 4), true);
                frames_ += 2;
                break;
            case 1: {
                static const int zoom_keys[] = {keys::equal, keys::minus, keys::digit('1'),
                                                keys::letter('F'), keys::letter('A')};
                last_event_ = "zoom or compare key";
                viewer_.press_key(state_, zoom_keys[pick(5)]);
                frames_ += 2;
                break;
            }
            case 2: {
                const bool space = pick(2);
                last_event_ = space ? "Space+drag" : "middle drag";
                io.KeysDown[keys::space] = space;
                viewer_.drag(state_, space ? 0 : 2, uniform(0, w), uniform(0, h), uniform(0, w),
                             uniform(0, h));
                io.KeysDown[keys::space] = false;
                frame();
                frames_ += 7;
                break;
            }
            case 3:
                last_event_ = "Ctrl+drag region";
                viewer_.drag(state_, 0, uniform(0, w), uniform(0, h), uniform(0, w), uniform(0, h),
                             kCtrl);
                frames_ += 6;
                break;
            case 4:
                last_event_ = "clear region";
                clear_render_region(state_);
                frame();
                break;
            default: {
                last_event_ = "compare";
                const int what = pick(4);
                if (what == 0) snapshot_a(state_);
                if (what == 1) state_.view.compare.mode = static_cast<CompareMode>(pick(4));
                if (what == 2) state_.view.compare.split = uniform(-0.2f, 1.2f);
                if (what == 3) clear_snapshot_a(state_.view.compare);
                frame();
                break;
            }
        }
        check_image_view();
    }

    // Alt+drag (with Shift half the time) from anywhere to anywhere, Esc
    // pressed half-way in a quarter of them.
    void move_object_event(float w, float h) {
        const bool shift = pick(2), escape = pick(4) == 0;
        last_event_ = std::string("Alt+") + (shift ? "Shift+" : "") + "drag" +
                      (escape ? " cancelled by Esc" : "");
        const std::string before = document_text(state_.doc);
        const std::size_t steps = state_.history.undo.size();
        const auto loaded_before = state_.files.last_load_times.taken;
        // Pressed near the middle of the image (where the test scene's sphere
        // is, and no control) half the time: the text check below needs a
        // press that no control took.
        const ScreenRect r = viewer_.image_rect(), area = viewer_.image_area();
        const bool on_image = pick(2) && r.width() > 0 && area.width() > 0;
        const float cx = (std::max(r.x0, area.x0) + std::min(r.x1, area.x1)) / 2;
        const float cy = (std::max(r.y0, area.y0) + std::min(r.y1, area.y1)) / 2;
        const float reach = std::min(r.width(), area.width()) / 6;
        const float x0 = on_image ? cx + uniform(-reach, reach) : uniform(0, w);
        const float y0 = on_image ? cy + uniform(-reach, reach) : uniform(0, h);
        const float x1 = uniform(0, w), y1 = uniform(0, h);
        const bool prompt = state_.files.unsaved_prompt.has_value();
        // "Moved ..." below must be this drag's, not left by an earlier one.
        state_.message.clear();
        viewer_.press_mouse(state_, 0, x0, y0, kAlt | (shift ? kShift : kNoModifier));
        viewer_.move_mouse(state_, (x0 + x1) / 2, (y0 + y1) / 2);
        if (escape) {
            viewer_.press_key(state_, keys::escape, false, shift);
            frames_ += 2;
        }
        viewer_.move_mouse(state_, x1, y1);
        viewer_.release_mouse(state_, 0);
        frames_ += 5;
        if (state_.drags.object) fail("the drag is still going on after the mouse was let go");
        const bool moved = state_.message.rfind("Moved ", 0) == 0;
        if (!moved) {
            const bool undisturbed = on_image && !prompt && !load_may_arrive() &&
                                     state_.files.last_load_times.taken == loaded_before;
            if (undisturbed && document_text(state_.doc) != before)
                fail("an Alt+drag that moved nothing changed the text");
            return;
        }
        if (escape) fail("an Alt+drag cancelled by Esc moved something");
        const std::size_t at_most = state_.history.undo.capacity();
        if (state_.history.undo.size() != std::min(steps + 1, at_most))
            fail("an Alt+drag made " + std::to_string(state_.history.undo.size() - steps) +
                 " undo steps");
        const std::string after = document_text(state_.doc);
        undo(state_);
        if (document_text(state_.doc) != before) fail("undo of an Alt+drag is not the text before");
        redo(state_);
        if (document_text(state_.doc) != after) fail("redo of an Alt+drag is not the moved text");
        frame();
    }

    // The image cannot be lost: along each axis a zoomed image larger than its
    // area covers it, a smaller one is centred; a region render stays inside its frame.
    void check_image_view() {
        const ScreenRect r = viewer_.image_rect(), area = viewer_.image_area();
        if (r.width() > 0 && area.width() > 0) {
            const auto check_axis = [&](float lo, float hi, float area_lo, float area_hi,
                                        const char* axis) {
                const bool covers = lo <= area_lo + 1 && hi >= area_hi - 1;
                const bool centred = std::abs((lo + hi) - (area_lo + area_hi)) <= 2;
                if (!covers && !centred) fail(std::string("the image left its area along ") + axis);
            };
            check_axis(r.x0, r.x1, area.x0, area.x1, "x");
            check_axis(r.y0, r.y1, area.y0, area.y1, "y");
        }
        if (state_.render.started && state_.render.started->options.region) {
            const PixelRect& region = *state_.render.started->options.region;
            if (region.x0 < 0 || region.y0 < 0 ||
                region.x1 > state_.render.started->options.width ||
                region.y1 > state_.render.started->options.height || region.empty())
                fail("a region render outside its frame");
        }
    }

    // A panel command that rewrites the text, on a block that may or may not exist.
    void structure_edit() {
        const std::size_t objects = state_.doc.scene.primitives.size() + 1;
        const std::size_t any = static_cast<std::size_t>(pick(static_cast<int>(objects)));
        const BlockKind kinds[] = {BlockKind::camera, BlockKind::primitive, BlockKind::light};
        const BlockRef block{kinds[pick(3)], static_cast<std::size_t>(pick(4))};
        switch (pick(10)) {
            case 0:
                last_event_ = "add object";
                add_object(state_, kShapeKinds[static_cast<std::size_t>(
                                       pick(static_cast<int>(kShapeKinds.size())))]);
                break;
            case 1:
                last_event_ = "add light";
                add_light(state_);
                break;
            case 2:
                last_event_ = "duplicate";
                duplicate_block(state_, block);
                break;
            case 3:
                last_event_ = "delete";
                delete_block(state_, block);
                break;
            case 4:
                last_event_ = "add transform op";
                add_transform_op(state_, any,
                                 transform_ops()[static_cast<std::size_t>(pick(5))].kind);
                break;
            case 5:
                last_event_ = "move transform op";
                move_transform_op(state_, any, static_cast<std::size_t>(pick(3)),
                                  static_cast<std::size_t>(pick(3)));
                break;
            case 6:
                last_event_ = "remove transform op";
                remove_transform_op(state_, any, static_cast<std::size_t>(pick(3)));
                break;
            case 7:
                last_event_ = "add camera";
                add_camera(state_);
                break;
            case 8:
                last_event_ = "rename camera";
                rename_camera(state_, static_cast<std::size_t>(pick(3)),
                              "m" + std::to_string(pick(3)));
                break;
            default:
                last_event_ = "add material block";
                add_material_block(state_, any);
                break;
        }
    }

    // Typing in the text editor: a character in or out somewhere, which may
    // break the text or mend it; sometimes the check is waited for.
    void type_into_the_text() {
        last_event_ = "text typed";
        if (!state_.doc.loaded) return;
        std::string text = document_text(state_.doc);
        const std::size_t at =
            text.empty() ? 0 : static_cast<std::size_t>(pick(static_cast<int>(text.size())));
        if (pick(2) && !text.empty())
            text.erase(at, 1);
        else
            text.insert(at, 1, " ;x1<{}"[pick(7)]);
        type_text(state_, text);
        if (pick(2)) state_.check.checker.wait();
    }

    static std::string near(const std::string& text, int at) {
        const std::size_t from = static_cast<std::size_t>(std::max(at - 12, 0));
        return text.substr(std::min(from, text.size()), 24);
    }

    // Keys as a keyboard sends them, through the window's KeyTaps, into the
    // text editor at a random place, from the start of the undo history:
    // Backspaces and characters typed fast at a random frame rate come out in
    // order (issue 27 item 11); then Ctrl+Z back to the start, and twice more,
    // gives the text before the typing (ImGui's own undo once went on past it,
    // item 10), and Ctrl+Shift+Z back to the end gives the typing again.
    void key_sequence_in_the_text() {
        last_event_ = "key sequence in the text";
        if (!state_.doc.loaded || !state_.view.show_ui || state_.files.unsaved_prompt ||
            state_.drags.object || ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId))
            return;
        TextEditorState& editor = viewer_.text_editor();
        if (!editor.open) viewer_.press_key(state_, keys::letter('T'));  // as a user opens it
        frames_ += 2;
        if (!editor.open) return;
        const double frame_ms = uniform(4, 150);
        const auto ctrl_z = [&](bool shift) {
            constexpr int ctrl_mod = 0x0002, shift_mod = 0x0001;
            const int mods = ctrl_mod | (shift ? shift_mod : 0);
            std::vector<KeyEvent> keys_down = {{keys::left_ctrl, 0, kKeyPress, ctrl_mod, 0}};
            if (shift) keys_down.push_back({keys::left_shift, 0, kKeyPress, mods, 0});
            keys_down.push_back({keys::letter('Z'), 0, kKeyPress, mods, 0});
            keys_down.push_back({keys::letter('Z'), 0, kKeyRelease, mods, 0});
            if (shift) keys_down.push_back({keys::left_shift, 0, kKeyRelease, ctrl_mod, 0});
            keys_down.push_back({keys::left_ctrl, 0, kKeyRelease, 0, 0});
            viewer_.key_events(state_, keys_down, uniform(2, 40), frame_ms);
            frames_ += 4;
        };
        const auto undo_all = [&] {
            for (int i = 0; i < 200 && state_.history.undo.can_undo(); ++i) undo(state_);
            frame();
        };
        // A load asked before (R, a file changed) would replace the text
        // mid-typing: that of a document without edits is taken in as it is.
        state_.files.loader.wait();
        frame();
        undo_all();
        const std::string before = editor.buffer;
        const int at = pick(static_cast<int>(before.size()) + 1);
        editor.jump = at;
        frame();
        frame();
        if (editor.cursor != at || editor.buffer != before) return;  // not in the editor
        std::vector<KeyEvent> events;
        const int backspaces = pick(4);
        for (int i = 0; i < backspaces; ++i) {
            events.push_back({keys::backspace, 0, kKeyPress, 0, 0});
            events.push_back({keys::backspace, 0, kKeyRelease, 0, 0});
        }
        std::string typed;
        for (int i = pick(5); i > 0; --i) typed += "1x ;{"[pick(5)];
        for (char c : typed) {
            const int code = c == 'x' ? 'X' : c;
            events.push_back({code, 0, kKeyPress, 0, 0});
            events.push_back(typed_character(static_cast<unsigned char>(c)));
            events.push_back({code, 0, kKeyRelease, 0, 0});
        }
        const double event_ms = uniform(2, 40);
        viewer_.key_events(state_, events, event_ms, frame_ms);
        frames_ += 4;
        // A Backspace deletes one character, all its UTF-8 bytes (a file
        // of random bytes may hold some that are whole characters).
        std::size_t from = static_cast<std::size_t>(at);
        for (int i = 0; i < backspaces && from > 0; ++i) {
            --from;
            while (from > 0 && (static_cast<unsigned char>(before[from]) & 0xC0) == 0x80) --from;
        }
        std::string expected = before;
        expected.replace(from, static_cast<std::size_t>(at) - from, typed);
        if (document_text(state_.doc) != expected) {
            fail("typed " + std::to_string(backspaces) + " Backspaces and '" + typed + "' " +
                 std::to_string(event_ms) + " ms apart, a frame every " + std::to_string(frame_ms) +
                 " ms at byte " + std::to_string(at) + ": the text differs (near it: '" +
                 near(document_text(state_.doc), at) + "', expected '" + near(expected, at) + "')");
            return;
        }
        if (load_may_arrive()) return;
        for (int i = 0; i < 8 && state_.history.undo.can_undo(); ++i) ctrl_z(false);
        ctrl_z(false);
        ctrl_z(false);
        if (load_may_arrive()) return;
        if (document_text(state_.doc) != before)
            fail(
                "Ctrl+Z to the start of the history and past it does not give the text before "
                "the typing (near it: '" +
                near(document_text(state_.doc), at) + "', before '" + near(before, at) + "')");
        // Keys that changed nothing (no characters, Backspace at the start)
        // record no step: the redo history is still the one undo_all left,
        // and redo to its end gives those edits back, not the typing.
        if (expected == before) return;
        for (int i = 0; i < 8 && state_.history.undo.can_redo(); ++i) ctrl_z(true);
        if (!load_may_arrive() && document_text(state_.doc) != expected)
            fail("Ctrl+Shift+Z to the end does not give the typing back (" +
                 std::to_string(backspaces) + " Backspaces and '" + typed + "' " +
                 std::to_string(event_ms) + " ms apart, a frame every " + std::to_string(frame_ms) +
                 " ms at byte " + std::to_string(at) + "; near it: '" +
                 near(document_text(state_.doc), at) + "', expected '" + near(expected, at) + "')");
    }

    // One of the controls the last frame drew, or nullopt (after a frame) when none.
    std::optional<UiItem> some_item() {
        if (viewer_.ui_items().empty()) {
            frame();
            return std::nullopt;
        }
        const UiItems& items = viewer_.ui_items();
        return items[static_cast<std::size_t>(pick(static_cast<int>(items.size())))];
    }

    void click_some_item() {
        const std::optional<UiItem> some = some_item();
        if (!some) return;
        const UiItem& item = *some;
        last_event_ = "click \"" + item.label + "\"";
        ImGuiIO& io = ImGui::GetIO();
        io.MousePos =
            ImVec2(uniform(item.rect.x0, item.rect.x1), uniform(item.rect.y0, item.rect.y1));
        frame();
        io.MouseDown[0] = true;
        frame();
        io.MouseDown[0] = false;
        frame();
    }

    // A drag across a control: a number or colour edit, the panel's edge.
    void drag_some_item() {
        const std::optional<UiItem> some = some_item();
        if (!some) return;
        const UiItem& item = *some;
        last_event_ = "drag \"" + item.label + "\"";
        const float x = uniform(item.rect.x0, item.rect.x1);
        const float y = uniform(item.rect.y0, item.rect.y1);
        viewer_.drag(state_, 0, x, y, x + uniform(-80, 80), y + uniform(-4, 4));
        frames_ += 6;
    }

    void press_some_key() {
        struct Key {
            int code;
            bool ctrl, shift;
            const char* name;
        };
        static const Key keys_pressed[] = {
            {keys::escape, false, false, "Esc"},
            {keys::letter('Z'), true, false, "Ctrl+Z"},
            {keys::letter('Z'), true, true, "Ctrl+Shift+Z"},
            {keys::letter('S'), true, false, "Ctrl+S"},
            {keys::letter('Q'), true, false, "Ctrl+Q"},
            {keys::letter('S'), false, false, "S"},
            {keys::letter('R'), false, false, "R"},
            {keys::letter('C'), false, false, "C"},
            {keys::letter('F'), false, false, "F"},
            {keys::letter('H'), false, false, "H"},
            {keys::space, false, false, "Space"},
            {keys::enter, false, false, "Enter"},
            {keys::tab, false, false, "Tab"},
        };
        const Key& key = keys_pressed[pick(static_cast<int>(std::size(keys_pressed)))];
        last_event_ = std::string("key ") + key.name;
        viewer_.press_key(state_, key.code, key.ctrl, key.shift);
        frames_ += 2;
    }

    void change_the_file() {
        const int kind = pick(6);
        if (kind == 0) {
            last_event_ = "file deleted";
            fs::remove(file_);
            written_.clear();
            file_deleted_ = true;
        } else if (kind == 1) {
            last_event_ = "file truncated";
            rewrite_scene(written_.empty() ? original_.substr(0, 100)
                                           : written_.substr(0, written_.size() / 2));
        } else if (kind == 2) {
            last_event_ = "file garbage";
            std::string garbage(200, '\0');
            for (char& c : garbage) c = static_cast<char>(pick(256));
            rewrite_scene(garbage);
        } else {
            const std::size_t which =
                static_cast<std::size_t>(pick(static_cast<int>(texts_.size())));
            last_event_ = "file rewritten (text " + std::to_string(which) + ")";
            rewrite_scene(texts_[which]);
        }
        wait_for_load();
    }

    void check_after_event() {
        if (state_.quit) {  // the user confirmed quitting: start again, as a user would
            state_.quit = false;
            last_quit_ = event_;
        }
        if (viewer_.slowest_unqueued_frame() > slowest_reported_) {
            slowest_reported_ = viewer_.slowest_unqueued_frame();
            if (slowest_reported_ >= hang_frame_seconds)
                fail("a frame took " + std::to_string(slowest_reported_) + " s");
        }
        check_files();
        check_saves();
        const bool mid_edit = ImGui::IsAnyItemActive() || state_.history.edit_base.has_value();
        if (!state_.history.undo.can_undo() && !state_.history.undo.can_redo() && !mid_edit &&
            state_.doc.loaded && has_unsaved_edits(state_.doc) && !saved_since_history_start_)
            fail("no undo history, yet the scene differs from the file's");
        if (state_.doc.loaded) {
            const int selected = selected_camera(state_.view, state_.doc.scene);
            if (state_.view.camera_index < 0 ||
                state_.view.camera_index >= static_cast<int>(state_.doc.scene.cameras.size()))
                fail("camera_index " + std::to_string(state_.view.camera_index) + " of " +
                     std::to_string(state_.doc.scene.cameras.size()) + " cameras");
            (void)selected;
        }
        if (!state_.history.undo.can_undo() && !state_.history.undo.can_redo()) {
            saved_since_history_start_ = false;
            history_dropped_ = false;
        }
        // A full history drops its oldest step with the next record.
        if (state_.history.undo.size() >= state_.history.undo.capacity()) history_dropped_ = true;
    }

    // Every file in the folder is whole: the scene is a text the monkey wrote
    // or one the viewer saved; images are whole PNGs; no temporary is left.
    // A click selects an object or light the scene has now, or nothing: never
    // an index of a scene the image no longer shows. (A click that misses the
    // image, on a panel, beside a zoomed-out image, changes nothing, and an
    // earlier selection may name an object deleted since: current_selection
    // reads it as none.)
    void check_selection(const Selection& before) {
        if (state_.view.selection != before &&
            state_.view.selection != current_selection(state_.view, state_.doc.scene))
            fail("a click selected " + std::to_string(state_.view.selection.index) + " of " +
                 std::to_string(state_.doc.scene.primitives.size()) + " objects");
    }

    void check_files() {
        for (const auto& entry : fs::directory_iterator(dir_)) {
            const std::string name = entry.path().filename().string();
            if (name.find(".tmp-") != std::string::npos) fail("temporary file left: " + name);
            if (entry.path().extension() == ".png") {
                const std::string bytes = read_file(entry.path());
                const Expected<Image8> image =
                    decode_png({reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()});
                if (!image) fail(name + " is not a whole PNG: " + image.error().message);
            }
        }
        std::error_code ec;
        if (!fs::exists(file_, ec)) return;
        const std::string text = read_file(file_);
        if (text == written_) return;
        ParseResult parsed = parse_scene(text);
        if (!parsed.ok()) fail("scene.jts is neither the monkey's text nor a whole save");
    }

    // A save just reported: the file parses to exactly the viewer's scene.
    void check_saves() {
        const std::string saved = "Saved " + state_.doc.path.string();
        const bool new_message = state_.message != last_message_;
        last_message_ = state_.message;
        if (state_.message != saved || !new_message) return;
        ParseResult parsed = parse_scene(read_file(state_.doc.path));
        if (!parsed.ok() || parsed.scene != state_.doc.scene)
            fail("the saved file does not parse to the viewer's scene");
        if (state_.doc.path == file_) written_ = read_file(file_);
        saved_since_history_start_ = true;
        ++saves_checked_;
    }

    // A load in flight may be taken by the frames in between (a reload of the
    // unmodified document replaces it and its history): the round trip is
    // only checked when none can arrive.
    bool load_may_arrive() const {
        return state_.files.loader.busy() || state_.files.pending_reload.has_value();
    }

    void check_undo_round_trip() {
        if (ImGui::IsAnyItemActive() || state_.history.edit_base || !state_.history.undo.can_undo())
            return;
        if (load_may_arrive()) return;
        const Scene now = state_.doc.scene;
        int steps = 0;
        while (state_.history.undo.can_undo()) {
            undo(state_);
            ++steps;
        }
        frame();
        if (!saved_since_history_start_ && !history_dropped_ &&
            state_.doc.scene != *state_.doc.original)
            fail("undo back to the start (" + std::to_string(steps) +
                 " steps) does not give the file's scene");
        const bool undisturbed = !load_may_arrive();
        for (int i = 0; i < steps; ++i) redo(state_);
        frame();
        if (undisturbed && !load_may_arrive() && state_.doc.scene != now)
            fail("redo back does not give the scene before");
        state_.message.clear();
        ++round_trips_;
    }

    std::mt19937 random_;
    std::uint32_t seed_;
    fs::path dir_, file_;
    HeadlessViewer viewer_{640, 400};
    AppState state_;  // after the viewer: its texture goes first
    std::string original_, written_;
    std::vector<std::string> texts_;
    bool file_deleted_ = false;
    bool saved_since_history_start_ = false;
    // The history was full since it started: its first steps may be gone.
    bool history_dropped_ = false;
    double slowest_reported_ = 0.0;
    std::string last_event_ = "start", last_message_;
    int event_ = 0, last_quit_ = -1, frames_ = 0, failures_ = 0, saves_checked_ = 0,
        round_trips_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
    // Mesa's software rasteriser draws on this thread: a frame then never
    // waits for rasteriser threads that a busy machine leaves without a core.
    ::setenv("LP_NUM_THREADS", "0", 0);
    std::uint32_t seed = 1;
    int events = 500, soak = 0;
    bool verbose = false;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string flag = argv[i];
        const long value = std::strtol(argv[i + 1], nullptr, 10);
        if (flag == "--seed")
            seed = static_cast<std::uint32_t>(value);
        else if (flag == "--events")
            events = static_cast<int>(value);
        else if (flag == "--verbose")
            verbose = value != 0;
        else if (flag == "--soak")
            soak = static_cast<int>(value);
        else {
            std::fprintf(stderr, "usage: viewer_monkey [--seed N] [--events N] [--soak N]\n");
            return 2;
        }
    }
    const fs::path dir = fs::temp_directory_path() / ("jtracer-monkey-" + std::to_string(seed) +
                                                      "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    bool ok = false;
    {
        Monkey monkey(seed, dir);
        monkey.verbose_ = verbose;
        if (monkey.start()) {
            if (soak > 0)
                monkey.soak(soak);
            else
                monkey.run(events);
            ok = monkey.ok();
        }
    }
    fs::remove_all(dir);
    return ok ? 0 : 1;
}
