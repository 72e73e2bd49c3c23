#pragma once
// Everything the viewer knows between frames. Plain data plus the few objects
// that own threads (loader, checker, render); behaviour lives in
// app_actions.hpp (what a command does). No GL, no ImGui: the frame code
// (viewer/app) draws this state and keeps the texture itself.

#include "jtracer/pick.hpp"
#include "jtracer/region.hpp"
#include "jtracer/scene_info.hpp"
#include "model/drag_geometry.hpp"
#include "model/editor_files.hpp"
#include "model/file_watcher.hpp"
#include "model/free_camera.hpp"
#include "model/image_layout.hpp"
#include "model/primitive_ids.hpp"
#include "model/recent_files.hpp"
#include "model/render_controller.hpp"
#include "model/scene_document.hpp"
#include "model/scene_loader.hpp"
#include "model/scene_time.hpp"
#include "model/text_checker.hpp"
#include "model/undo_stack.hpp"
#include "model/viewer_settings.hpp"
#include "model/wakeup.hpp"

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace jt::view {

// What the user has selected: one primitive or one light of the scene, by its
// index in Scene::primitives or Scene::lights.
struct Selection {
    enum class Kind { none, primitive, light };
    Kind kind = Kind::none;
    int index = -1;
    bool operator==(const Selection&) const = default;
};

// The frame the image on screen is rendered from (prepared scene, camera,
// size), for picking in it; remade only when the render's prepared scene or
// view changes (picking.hpp).
struct ShownFrame {
    std::shared_ptr<const PreparedScene> scene;
    int width = 0, height = 0, camera = -1;
    std::shared_ptr<const PreparedFrame> frame;
};

struct ViewerConfig {
    std::filesystem::path recent_files;   // empty: remember nothing between runs
    std::filesystem::path settings_file;  // the panel width (viewer_settings.hpp); empty: none
    std::chrono::milliseconds watch_interval{200};
    int render_threads = 0;  // 0: every core
    // The render's threads below the frame loop's priority (RenderOptions::background).
    bool render_in_background = true;
    // How long the frame that starts a render may wait for its first pass, so
    // that the pass shows in this frame rather than the next. A coarse first
    // pass takes a few milliseconds; a frame on a GPU takes one or two, so the
    // frame still makes its vsync. 0: never wait.
    std::chrono::milliseconds first_pass_wait{6};
    // The same for the render of a scene just opened, which renders the
    // preparation the loader made ahead (prepared_ahead.hpp). The loader hands
    // such an open over once that preparation is done (prepared_ahead_hold),
    // so this frame shows the first preview with the new scene's panels; on a
    // busy machine the pass can take longer than first_pass_wait, and a frame
    // drawn before it (with software OpenGL 10-30 ms of a core) would delay
    // it by that frame. A preparation still under way is waited for as long.
    std::chrono::milliseconds opened_first_pass_wait{50};
    int max_pixels = 4096 * 4096;  // larger images are refused, not allocated
};

// What the current render was started from; a new render starts when this
// changes. Cheap to make and compare every frame: the scene is named by its
// revision, and copied for the render only when one starts.
struct RenderRequest {
    std::uint64_t scene_revision = 0;       // SceneDocument::revision
    std::optional<FreeCamera> free_camera;  // renders instead of a scene camera
    std::size_t primitive_count = 0;        // of the scene rendered (picking's check)
    RenderOptions options;
    bool operator==(const RenderRequest& other) const {
        return scene_revision == other.scene_revision && free_camera == other.free_camera &&
               options.width == other.options.width && options.height == other.options.height &&
               options.samples == other.options.samples && options.camera == other.options.camera &&
               options.region == other.options.region;
    }
};

// A command that would throw unsaved edits away, held until the user answers
// Save / Discard / Cancel.
struct GuardedCommand {
    enum class Kind { quit, open } kind = Kind::quit;
    std::filesystem::path path;  // for open
};

// A mouse drag on the image: only a press on the image starts one, and each
// frame moves the camera by the motion since the last (the first: since the
// press), never by motion made before the press.
// A press that is let go before moving more than a few units is a click (it
// selects what it is on) and moves nothing.
struct ImageDrag {
    // What a drag does, chosen at the press by its button and modifiers.
    enum class Mode {
        orbit,        // left: the free camera orbits
        camera_pan,   // right: the free camera pans
        image_pan,    // middle, or Space + left: the image view pans (the camera stays)
        region,       // Ctrl + left: a rectangle to render alone (render_region.hpp)
        move_object,  // Alt + left: the selected object or light moves (object_drag.hpp)
    };
    int button = -1;  // ImGuiMouseButton, -1 when no drag
    Mode mode = Mode::orbit;
    float last_x = 0, last_y = 0;
    float press_x = 0, press_y = 0;
    bool moved = false;  // beyond a click's slack: the camera follows
    // Shift as last seen with the button down: a slow frame can take in the
    // button and Shift let go together, and the move keeps the axis it showed.
    bool one_axis = false;
};

// An object or light being moved by a drag (object_drag.hpp): what moves,
// in which plane, from which value, and the document to go back to.
struct ObjectDrag {
    Selection target;  // a primitive or a light
    // The frame the drag started on: its camera maps the cursor to rays
    // while the render restarts with each move.
    std::shared_ptr<const PreparedFrame> frame;
    ImagePoint press;  // where the drag started, image pixels
    DragPlane plane;   // facing the camera, through the point grabbed
    // A plane primitive moves along its unit world normal alone.
    std::optional<Vec3> only_along;
    double pixel_size = 0.0;  // of one image pixel on the plane: the step of the numbers
    // The value the drag moves: the light's position, or the vector of the
    // primitive's last transform operation, a translate (zero when the drag
    // adds that translate, at its first move).
    Vec3 start{0.0};
    bool adds_translate = false;
    Vec3 written{0.0};             // the value the document holds now
    bool changed = false;          // the drag has changed the document
    DocumentVersion before;        // the document at the press: what undo and Esc give back
    std::uint64_t generation = 0;  // scene_generation after the drag's last write
    std::chrono::steady_clock::time_point last_write;
};

// The figures of the mesh the Objects panel shows (scene_info.hpp), worked
// out once per selection and scene revision, not every frame.
struct MeshFigures {
    int primitive = -1;
    std::uint64_t revision = 0;           // SceneDocument::revision
    Expected<MeshInfo> info = Error{""};  // or why its model does not load
};

// How the image shows against a snapshot A (ab_compare.hpp).
enum class CompareMode {
    live,        // the live image alone
    split,       // A left of the split line, live right
    a,           // A alone (toggled against live with the A key)
    difference,  // the per-pixel difference of A and live, as jtracer-cli diff draws it
};
struct CompareState {
    std::optional<Image8> a;      // the snapshot, when one was kept
    std::uint64_t a_version = 0;  // bumped by each snapshot, so the texture follows
    CompareMode mode = CompareMode::live;
    float split = 0.5f;  // where the line is, across the image (0: all live, 1: all A)
};

// The one block a panel's fields edit: the render settings, or one camera,
// object or light of the scene.
struct EditedBlock {
    enum class Kind { settings, camera, primitive, light };
    Kind kind = Kind::settings;
    std::size_t index = 0;  // into Scene::cameras, ::primitives or ::lights
    bool operator==(const EditedBlock&) const = default;
};
// A copy of such a block's value.
struct BlockCopy {
    EditedBlock block;
    std::variant<RenderSettings, Camera, Primitive, PointLight> value;
};

// The undo history, and what tells a panel edit from a command's: one undo
// step per continuous panel edit (a whole drag is one step).
struct EditHistory {
    SnapshotStack<DocumentVersion> undo;  // one history for panel, structure and text edits
    bool typing = false;  // a burst of typing whose undo step is recorded is going on
    // The block the panel edit in progress changes, as it was before the edit
    // (one undo step per drag).
    std::optional<BlockCopy> edit_base;
    // The blocks the panels show, as they were at settled_revision while no
    // edit was in progress: the edit_base of the next panel edit. A field can
    // change its value in the frame it becomes active (ImGui's colour picker
    // does), so the copy is taken before the fields are drawn, once per change
    // of the scene and one block at a time (settle_block), never the scene.
    std::vector<BlockCopy> settled;
    std::optional<std::uint64_t> settled_revision;
    // Bumped by every command that replaces the scene and keeps the undo stack
    // itself (open, reload, undo, redo, scripted edits), so that the change is
    // not mistaken for a widget edit.
    std::uint64_t scene_generation = 0;
};

// The checks of the text typed in the editor and of the edited scene.
struct CheckState {
    TextChecker checker;         // checks the text editor's draft once typing pauses
    std::uint64_t draft_id = 0;  // of the newest draft sent to the checker
    // The files the check of a draft with errors read or tried to read
    // through `include`: when one changes or appears, the draft is checked
    // again (reload_if_changed), as a loaded file's includes are reloaded.
    std::vector<std::filesystem::path> draft_reads;
    // The revision of the scene the diagnostics were last checked for (check_edits).
    std::optional<std::uint64_t> checked_revision;
    // The revision of the scene that validation last found free of errors: while
    // checked_revision is that one too, a render of the scene need not validate
    // it again (update_render).
    std::optional<std::uint64_t> error_free_revision;
};

// The file on disk: watching it and the files it names, loading, saving, and
// the questions they leave for the user.
struct FileState {
    explicit FileState(const ViewerConfig& config)
        : asset_watcher(config.watch_interval),
          include_watcher(config.watch_interval),
          draft_watcher(config.watch_interval) {}
    FileWatcher watcher;
    FileSetWatcher asset_watcher;    // the model and image files the scene names
    FileSetWatcher include_watcher;  // the files the scene includes (SceneDocument::included_files)
    FileSetWatcher
        draft_watcher;   // the files a draft with errors includes (CheckState::draft_reads)
    SceneLoader loader;  // opens and reloads off the UI thread
    RecentFiles recent;
    LoadTimes last_load_times;  // of the last open or reload taken in
    // A newer text of the file, loaded while there were unsaved edits: held
    // until the user chooses (resolve_reload) so that neither is lost unasked.
    std::optional<LoadAttempt> pending_reload;
    std::string reapply_problem;  // why the edits cannot be re-applied to it, or empty
    // The file it reads differently (changed_on_disk): the scene file, or an
    // included file; empty when it reads the same and only drops the edits.
    std::string changed_on_disk;
    // Why the last Save scene was refused (the file changed on disk), or empty;
    // save_scene_anyway overwrites it.
    std::string save_conflict;
    // The included files typed in whose change refused it (canonical), or
    // none when the scene file's did: reloading would keep their drafts, so
    // the choice offered is to drop them (revert_conflicting_drafts).
    std::vector<std::string> save_conflict_drafts;
    std::optional<GuardedCommand> unsaved_prompt;
    std::string save_as_conflict;  // the file Save scene as would replace, until confirmed
    // The unsaved work there was when the open under way was asked for: none,
    // or what the user agreed to discard. Work done while the file loads is
    // asked about when it arrives (take_finished_load).
    struct UnsavedStamp {
        std::uint64_t history = 0;  // EditHistory::undo's changes()
        // The draft, or the base text when there is none: a draft that
        // parses becomes the base text unchanged, which is no edit.
        std::string text;
        std::vector<std::string> included;  // the included files' drafts
        bool operator==(const UnsavedStamp&) const = default;
    };
    std::optional<UnsavedStamp> open_requested_over;
};

// The render: what it was started from, the job, and its pixels as shown.
struct RenderState {
    RenderController renderer;
    std::optional<RenderRequest> started;   // the request the current render answers
    std::string converging;                 // what its passes refine (converging_effects)
    std::string render_note;                // why nothing renders, when so
    std::optional<RenderRequest> rejected;  // an edited scene that failed validation
    std::string rejected_reason;
    bool paused = false;
    bool edit_waiting = false;  // paused, and the scene or view changed since the render started
    bool display_complete = false;  // the display holds every pixel of the finished render
    int passes_shown = 0;           // passes of the current render whose pixels are in the texture
    Image8 display;                 // the render's pixels as the UI shows them
    // The part of `display` changed since the frame code last took it
    // (take_display_changes): what it sends to the texture.
    std::optional<PixelRect> display_changed;
};

// What the user looks at and through: the camera, the selection, the image's
// zoom and pan, the region rendered alone, the compare view, the sidebar.
struct ViewState {
    // Which camera renders: one of the scene's, or the free camera.
    int camera_index = 0;
    bool free_camera_active = false;
    FreeCamera free_camera;

    Selection selection;                      // read through current_selection (picking.hpp)
    bool reveal_selection = false;            // its panel opens and scrolls to it in the next frame
    std::string inspected;                    // what the pixel under the mouse holds, or empty
    ShownFrame shown_frame;                   // what picking picks in
    PrimitiveIds primitive_ids;               // what every pixel shows, for the selection's outline
    std::optional<MeshFigures> mesh_figures;  // forgotten when a model file changes

    ImageView image_view;       // zoom and pan of the image (image_layout.hpp)
    bool space_panned = false;  // Space is held for a pan: its release does not pause
    // The part of the image that renders alone, as jtracer-cli --region counts it.
    std::optional<FrameRegion> render_region;
    // The view the rest of the image shows while the region renders alone
    // (render_region.hpp): the camera, whatever its name, and the image size.
    struct RegionView {
        Camera camera;
        int width = 0, height = 0;
        bool operator==(const RegionView&) const = default;
    };
    std::optional<RegionView> region_view;
    CompareState compare;
    bool show_ui = true;
    // When (ImGui's time, seconds) an Esc with nothing open and nothing
    // unsaved asked for a second one to quit.
    std::optional<double> escape_to_quit_at;
    float sidebar_width = kDefaultPanelWidth;  // in font heights, so that it scales with the font
    ViewerSettings saved_settings;             // as in config.settings_file
};

// The mouse drags in progress.
struct Drags {
    ImageDrag image;
    std::optional<ObjectDrag> object;  // while an Alt+drag moves something
};

// What the UI's text fields hold as typed, before a command takes it.
struct TextFields {
    // The selected scene camera's name field (renamed on Enter).
    std::string camera_name_input;
    int camera_name_for = -1;
    bool camera_name_editing = false;
    std::string new_camera_name = "viewer";
    std::string object_filter;  // the Objects panel lists the objects whose name holds it
    // The objects object_filter lets through, worked out again only when the
    // filter or the scene changes: at 100,000 objects the list is 400 kB.
    std::string filtered_for;
    std::uint64_t filtered_revision = 0;  // SceneDocument::revision
    std::vector<int> filtered;
    std::string open_path_input;
    std::string new_mesh_file;  // the Add object menu's model file field
    std::string save_image_path = "jtracer-view.png";
    std::string save_scene_path;  // the Save scene as field
};

// The result of the last command, for the status line. A message that says
// the files hold the work shown ("Saved scene.jts", "Opened scene.jts")
// claims so (claim_saved, claim_read), and the status line shows it only
// while no edit since has outdated it (shown_message); after one it shows
// `when_edited`: a user reading "Saved" takes the edit on screen for saved.
// Any other message set later drops the claim with the text it replaces.
struct StatusMessage : std::string {
    StatusMessage& operator=(std::string text) {
        std::string::operator=(std::move(text));
        when_edited.clear();
        return *this;
    }
    void clear() { *this = std::string(); }
    void claim_saved(std::string text) {
        *this = std::move(text);
        when_edited = "Edited since the save: Ctrl+S saves the edits";
    }
    // `text` says the file `name` was just read: the scene shown is its own.
    void claim_read(std::string text, std::string_view verb, const std::string& name) {
        *this = std::move(text);
        when_edited = "Edited since ";
        when_edited += verb;
        when_edited += " " + name + ": Ctrl+S saves the edits";
    }
    bool claims() const { return !when_edited.empty(); }
    // Made when the claim is, not each frame: an idle frame allocates nothing.
    std::string when_edited;
};

// Everything the viewer knows between frames, in parts with one job each; a
// command takes the parts it changes (app_actions.hpp), or the whole state
// when it orchestrates several.
struct AppState {
    explicit AppState(ViewerConfig config = {}) : config(std::move(config)), files(this->config) {
        files.loader.set_wakeup(&wakeup);
        render.renderer.set_wakeup(&wakeup);
        check.checker.set_wakeup(&wakeup);
        view.saved_settings = read_viewer_settings(this->config.settings_file);
        view.sidebar_width = view.saved_settings.panel_width;
    }

    ViewerConfig config;
    // Before the loader and the renderer: their threads notify it until they end.
    Wakeup wakeup;
    SceneDocument doc;
    EditorFiles editor;  // the files the text editor shows, and what is typed in included ones
    EditHistory history;
    CheckState check;
    FileState files;
    RenderState render;
    ViewState view;
    TimeState time;  // the time slider and play (scene_time.hpp)
    Drags drags;
    TextFields fields;
    StatusMessage message;
    bool quit = false;
};

}  // namespace jt::view
