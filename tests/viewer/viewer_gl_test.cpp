// The viewer's frame code in an offscreen OSMesa GL 3.3 context: what it shows
// is what the core renders, and edits, camera switches and reloads behave.

#include "app/headless.hpp"
#include "app/keys.hpp"
#include "app/viewer_frame.hpp"
#include "common/files.hpp"
#include "jtracer/parser.hpp"
#include "jtracer/render_job.hpp"
#include "model/app_actions.hpp"
#include "model/wakeup.hpp"
#include "viewer/viewer_test_files.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <fstream>
#include <sstream>
#include <thread>

#include <unistd.h>

namespace jt::view {
namespace {

namespace fs = std::filesystem;
using namespace jt::test;

// The image the core renders for `scene` through `camera`, without the viewer.
Image8 core_render(const Scene& scene, int camera) {
    RenderOptions options = render_options_for(scene);
    options.camera = camera;
    options.previews = false;
    RenderJob job(prepare_scene(scene).value(), options);
    job.run();
    return job.image();
}

class ViewerGl : public ::testing::Test {
  protected:
    void SetUp() override { ASSERT_TRUE(viewer.ok()) << viewer.error(); }
    HeadlessViewer viewer{320, 240};
    AppState state{test_config()};
};

TEST_F(ViewerGl, TextureAndScreenShowExactlyTheCoresImage) {
    state.view.show_ui = false;
    state.view.image_view = actual_pixels_view();
    open_scene(state, kScene);
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout)) << state.render.render_note;
    const Image8 expected = core_render(state.doc.scene, 0);
    EXPECT_EQ(state.render.display, expected);
    EXPECT_EQ(viewer.presenter().read_texture(), expected);

    // On screen, the image sits centred at one pixel per pixel.
    const Image8 screen = viewer.screenshot();
    const int x0 = (320 - 64) / 2, y0 = (240 - 48) / 2;  // bottom-up rows, like Image8
    int mismatches = 0;
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x)
            for (int c = 0; c < 3; ++c)
                mismatches += screen.pixel(x0 + x, y0 + y)[c] != expected.pixel(x, y)[c];
    EXPECT_EQ(mismatches, 0);
}

TEST_F(ViewerGl, OnHiDpiActualPixelsAreFramebufferPixels) {
    viewer.set_framebuffer_scale(2.0f);  // a 160x120 window on a 320x240 framebuffer
    state.view.show_ui = false;
    state.view.image_view = actual_pixels_view();
    open_scene(state, kScene);
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    const Image8 screen = viewer.screenshot();
    const Image8& expected = state.render.display;
    const int x0 = (320 - 64) / 2, y0 = (240 - 48) / 2;
    int mismatches = 0;
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x)
            for (int c = 0; c < 3; ++c)
                mismatches += screen.pixel(x0 + x, y0 + y)[c] != expected.pixel(x, y)[c];
    EXPECT_EQ(mismatches, 0);
}

TEST_F(ViewerGl, FitFillsTheAreaKeepingTheAspect) {
    state.view.show_ui = false;
    open_scene(state, kScene);
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    // 64x48 fitted into 320x240 is 320x240: every image pixel is a 5x5 block.
    const Image8 screen = viewer.screenshot();
    const Image8& image = state.render.display;
    for (int y : {0, 17, 47})
        for (int x : {0, 31, 63})
            for (int c = 0; c < 3; ++c)
                EXPECT_EQ(screen.pixel(x * 5 + 2, y * 5 + 2)[c], image.pixel(x, y)[c])
                    << "pixel " << x << "," << y;
}

TEST_F(ViewerGl, OnlyChangedRegionsAreUploadedAfterTheFirst) {
    open_scene(state, kScene);
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    const long long after_first = viewer.presenter().texels_uploaded();
    EXPECT_GE(after_first, 64 * 48);
    for (int i = 0; i < 5; ++i) viewer.frame(state);
    EXPECT_EQ(viewer.presenter().texels_uploaded(), after_first) << "nothing changed, nothing sent";
}

TEST_F(ViewerGl, SwitchingCameraShowsThatCamerasRender) {
    open_scene(state, kScene);
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    const Image8 front = state.render.display;
    viewer.press_key(state, keys::letter('C'));
    EXPECT_EQ(state.view.camera_index, 1);
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    EXPECT_NE(state.render.display, front);
    EXPECT_EQ(state.render.display, core_render(state.doc.scene, 1));
    EXPECT_EQ(viewer.presenter().read_texture(), state.render.display);
}

TEST_F(ViewerGl, MaterialEditChangesTheImageToTheEditedScenesRender) {
    open_scene(state, kScene);
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    const Image8 before = state.render.display;
    edit_scene(state, [](Scene& s) { s.primitives[1].material.pigment = Colour(0.1, 0.3, 0.9); });
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    EXPECT_NE(state.render.display, before);
    EXPECT_EQ(state.render.display, core_render(state.doc.scene, 0));
    EXPECT_TRUE(state.history.undo.can_undo()) << "the edit is one undo step";
    viewer.press_key(state, keys::letter('Z'), /*ctrl=*/true);
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    EXPECT_EQ(state.render.display, before) << "undo restores the image";
    viewer.press_key(state, keys::letter('Z'), /*ctrl=*/true, /*shift=*/true);
    EXPECT_EQ(state.doc.scene.primitives[1].material.pigment, Colour(0.1, 0.3, 0.9));
}

TEST_F(ViewerGl, BrokenReloadKeepsTheLastImageAndListsDiagnostics) {
    const fs::path file = scene_copy("broken");
    open_scene(state, file);
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    const Image8 good = state.render.display;
    const Scene good_scene = state.doc.scene;
    const auto jobs = state.render.renderer.jobs_started();

    // Save by rename, as many editors do, with a missing ';' on line 3.
    write_file(fs::path(file).concat(".new"),
               "render_settings {\n    width: 64;\n    height: 48\n}\n");
    fs::rename(fs::path(file).concat(".new"), file);
    ASSERT_TRUE(viewer.run_until_loaded(state));

    EXPECT_TRUE(state.doc.load_failed);
    ASSERT_FALSE(state.doc.diagnostics.empty());
    EXPECT_EQ(state.doc.diagnostics[0].pos.line, 3);
    EXPECT_GT(state.doc.diagnostics[0].pos.column, 0);
    EXPECT_NE(format_diagnostics(state.doc).find("scene.jts:3:"), std::string::npos)
        << format_diagnostics(state.doc);
    EXPECT_EQ(state.doc.scene, good_scene);
    EXPECT_EQ(state.render.display, good);
    EXPECT_EQ(viewer.presenter().read_texture(), good);
    EXPECT_EQ(state.render.renderer.jobs_started(), jobs) << "no render of a broken scene";

    // Deleted, then garbage: still no crash, still the last image.
    fs::remove(file);
    ASSERT_TRUE(viewer.run_until_loaded(state));
    EXPECT_TRUE(state.doc.load_failed);
    write_file(file, std::string("\x00\xff\xfe garbage {{{", 16));
    ASSERT_TRUE(viewer.run_until_loaded(state));
    EXPECT_TRUE(state.doc.load_failed);
    EXPECT_EQ(state.render.display, good);

    // Fixed: it loads and renders again.
    fs::copy_file(kScene, file, fs::copy_options::overwrite_existing);
    ASSERT_TRUE(viewer.run_until_loaded(state));
    EXPECT_FALSE(state.doc.load_failed);
    EXPECT_TRUE(state.doc.diagnostics.empty());
}

TEST_F(ViewerGl, SaveSceneWritesOnlyTheEditedValues) {
    const fs::path file = scene_copy("save");
    open_scene(state, file);
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    state.doc.scene.primitives[1].material.pigment = Colour(0.25, 0.5, 0.75);
    state.doc.scene.settings.samples = 2;
    note_scene_changed(state.doc);  // as a panel field announces its change
    viewer.frame(state);
    viewer.press_key(state, keys::letter('S'), /*ctrl=*/true);
    EXPECT_FALSE(has_unsaved_edits(state.doc)) << state.message;

    std::string expected = read_file(kScene);
    auto replace = [&](std::string_view from, std::string_view to) {
        const std::size_t at = expected.find(from);
        ASSERT_NE(at, std::string::npos);
        expected.replace(at, from.size(), to);
    };
    replace("pigment: <0.9, 0.2, 0.1>;   # red", "pigment: <0.25, 0.5, 0.75>;   # red");
    replace("    ambient_light: <0.2, 0.2, 0.2>;\n}",
            "    ambient_light: <0.2, 0.2, 0.2>;\n    samples: 2;\n}");
    EXPECT_EQ(read_file(file), expected);
    for (const auto& entry : fs::directory_iterator(file.parent_path()))
        EXPECT_EQ(entry.path().filename(), "scene.jts") << "no temporary file left";

    // Our own save is not a change from outside: no reload, no new render.
    const auto jobs = state.render.renderer.jobs_started();
    for (int i = 0; i < 3; ++i) viewer.frame(state);
    EXPECT_EQ(state.render.renderer.jobs_started(), jobs);
}

TEST_F(ViewerGl, FreeCameraCopiedIntoTheSceneIsSavedAsANewCamera) {
    const fs::path file = scene_copy("camera");
    open_scene(state, file);
    viewer.frame(state);
    use_free_camera(state.view, state.doc.scene);
    orbit(state.view.free_camera, 40, 10, 240);
    copy_free_camera_to_scene(state, "mine");
    ASSERT_EQ(state.doc.scene.cameras.size(), 3u);
    EXPECT_EQ(state.view.camera_index, 2);
    ASSERT_TRUE(save_scene(state)) << state.message;
    ParseResult saved = parse_scene(read_file(file));
    ASSERT_TRUE(saved.ok());
    ASSERT_EQ(saved.scene.cameras.size(), 3u);
    EXPECT_EQ(saved.scene.cameras[2].name, "mine");
    EXPECT_EQ(saved.scene.cameras[2].position, state.doc.scene.cameras[2].position);
}

TEST_F(ViewerGl, SaveImageWritesTheCurrentRender) {
    open_scene(state, kScene);
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    const fs::path out = scene_copy("image").parent_path() / "render.bmp";
    ASSERT_TRUE(save_image(state, out)) << state.message;
    const std::string bytes = read_file(out);
    ASSERT_GT(bytes.size(), 54u);
    EXPECT_EQ(bytes.substr(0, 2), "BM");
}

TEST_F(ViewerGl, ResumeContinuesThePausedRenderWhereItStopped) {
    open_scene(state, fs::path(JT_SOURCE_DIR) / "scenes" / "showcase.jts");
    state.doc.scene.settings.width = 128;
    state.doc.scene.settings.height = 72;
    state.doc.scene.settings.samples = 128;  // passes up to 128 samples: time to pause
    note_scene_changed(state.doc);
    viewer.frame(state);
    const auto deadline = std::chrono::steady_clock::now() + kTimeout;
    while (state.render.renderer.progress().samples_done < 2 &&
           std::chrono::steady_clock::now() < deadline)
        viewer.frame(state);
    viewer.press_key(state, keys::space);
    ASSERT_TRUE(state.render.paused);
    const RenderProgress at_pause = state.render.renderer.progress();
    ASSERT_FALSE(at_pause.finished) << "the render finished before the test could pause it";
    ASSERT_GE(at_pause.samples_done, 2);
    // Tiles under way when the pause came may still land; once they have,
    // nothing renders and the image stays.
    while (!state.render.renderer.settled() && std::chrono::steady_clock::now() < deadline)
        viewer.frame(state);
    ASSERT_TRUE(state.render.renderer.settled());
    viewer.frame(state);
    const Image8 paused_image = state.render.display;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    for (int i = 0; i < 3; ++i) viewer.frame(state);
    EXPECT_EQ(state.render.renderer.progress().pass, at_pause.pass);
    EXPECT_EQ(state.render.display, paused_image);
    EXPECT_FALSE(render_complete(state.render));

    const auto jobs = state.render.renderer.jobs_started();
    viewer.press_key(state, keys::space);
    EXPECT_FALSE(state.render.paused);
    EXPECT_GE(state.render.renderer.progress().samples_done, at_pause.samples_done)
        << "samples already accumulated are kept";
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    EXPECT_EQ(state.render.renderer.jobs_started(), jobs) << "the same job continued";
    // Only the passes left at the pause ran (the interrupted one again).
    EXPECT_EQ(state.render.renderer.passes_since_start(), at_pause.pass_count - at_pause.pass);
    EXPECT_EQ(viewer.presenter().read_texture(), core_render(state.doc.scene, 0));
}

TEST_F(ViewerGl, EditsWhilePausedRenderAfresh) {
    open_scene(state, kScene);
    viewer.frame(state);
    viewer.press_key(state, keys::space);
    edit_scene(state, [](Scene& s) { s.primitives[1].material.pigment = Colour(0, 1, 0); });
    viewer.frame(state);
    const auto jobs = state.render.renderer.jobs_started();
    viewer.press_key(state, keys::space);
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    EXPECT_EQ(state.render.renderer.jobs_started(), jobs + 1);
    EXPECT_EQ(viewer.presenter().read_texture(), core_render(state.doc.scene, 0));
}

TEST_F(ViewerGl, AnEditCancelsTheRunningRenderAndRestartsAtOnce) {
    open_scene(state, fs::path(JT_SOURCE_DIR) / "scenes" / "showcase.jts");
    edit_scene(state, [](Scene& s) { s.settings.samples = 1024; });  // minutes of work
    viewer.frame(state);
    const auto jobs = state.render.renderer.jobs_started();
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    const auto before = std::chrono::steady_clock::now();
    edit_scene(state, [](Scene& s) { s.lights[0].intensity = Colour(0.5, 0.5, 0.5); });
    viewer.frame(state);
    const auto latency = std::chrono::steady_clock::now() - before;
    EXPECT_EQ(state.render.renderer.jobs_started(), jobs + 1);
    // The old render has minutes of work left: a frame that waited for it
    // would take that long. Software GL makes any frame slow, so the bound
    // is a hang's, not a latency figure (bench/viewer has those).
    EXPECT_LT(latency, std::chrono::seconds(5)) << "cancel + restart waited for the old render";
    EXPECT_FALSE(render_complete(state.render));
}

TEST_F(ViewerGl, TitleShowsTheFileAndTheProgress) {
    open_scene(state, kScene);
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    EXPECT_EQ(window_title(state).rfind("JTracer - two_cameras.jts - done", 0), 0u)
        << window_title(state);
    edit_scene(state, [](Scene& s) { s.settings.recurse_depth = 3; });
    EXPECT_NE(window_title(state).find("two_cameras.jts *"), std::string::npos);
}

TEST_F(ViewerGl, MouseOnTheImageDrivesTheFreeCamera) {
    state.view.show_ui = false;  // the image fills the window: 320x240 for a 64x48 image
    open_scene(state, kScene);
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    const Image8 scene_view = state.render.display;
    const Camera scene_camera = state.doc.scene.cameras[0];

    viewer.drag(state, 0, 160, 120, 220, 120);  // left: orbit
    ASSERT_TRUE(state.view.free_camera_active);
    const FreeCamera orbited = state.view.free_camera;
    EXPECT_NE(orbited.position, scene_camera.position);
    EXPECT_EQ(orbited.look_at, scene_camera.look_at);
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    EXPECT_NE(state.render.display, scene_view);

    viewer.drag(state, 1, 160, 120, 160, 60);  // right: pan
    EXPECT_NE(state.view.free_camera.look_at, orbited.look_at);
    const double distance =
        glm::length(state.view.free_camera.position - state.view.free_camera.look_at);
    viewer.scroll(state, 160, 120, 2);  // wheel: dolly closer
    EXPECT_LT(glm::length(state.view.free_camera.position - state.view.free_camera.look_at),
              distance);
    EXPECT_EQ(state.doc.scene.cameras[0], scene_camera) << "the scene's camera is untouched";

    viewer.press_key(state, keys::letter('C'));  // back to a scene camera
    EXPECT_FALSE(state.view.free_camera_active);
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    EXPECT_EQ(state.render.display, scene_view);
}

TEST_F(ViewerGl, ResizingTheRenderResizesTheTexture) {
    open_scene(state, kScene);
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    edit_scene(state, [](Scene& s) {
        s.settings.width = 40;
        s.settings.height = 30;
    });
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    EXPECT_EQ(state.render.display.width, 40);
    EXPECT_EQ(viewer.presenter().width(), 40);
    EXPECT_EQ(viewer.presenter().read_texture(), core_render(state.doc.scene, 0));
}

TEST_F(ViewerGl, ShortcutsReloadAndSaveTheImage) {
    const fs::path file = scene_copy("keys");
    open_scene(state, file);
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    state.fields.save_image_path = (file.parent_path() / "key.png").string();
    viewer.press_key(state, keys::letter('S'));
    EXPECT_TRUE(fs::exists(file.parent_path() / "key.png")) << state.message;

    edit_scene(state, [](Scene& s) { s.settings.recurse_depth = 0; });
    viewer.press_key(state, keys::letter('R'));  // with unsaved edits: asks first
    ASSERT_TRUE(viewer.run_until_loaded(state));
    ASSERT_TRUE(state.files.pending_reload.has_value()) << state.message;
    EXPECT_EQ(state.doc.scene.settings.recurse_depth, 0);
    viewer.frame(state);
    EXPECT_EQ(find_item(viewer.ui_items(), "Reload, re-apply my edits"), nullptr)
        << "the same text: nothing to re-apply the edits to";
    EXPECT_NE(find_item(viewer.ui_items(), "Keep mine"), nullptr);
    resolve_reload(state, ReloadChoice::drop_edits);
    EXPECT_EQ(state.doc.scene.settings.recurse_depth, 2);
    EXPECT_FALSE(state.history.undo.can_undo());
}

TEST_F(ViewerGl, AnEditThatMakesTheSceneInvalidKeepsTheImageAndSaysWhy) {
    open_scene(state, kScene);
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    const Image8 good = state.render.display;
    const auto jobs = state.render.renderer.jobs_started();
    edit_scene(state, [](Scene& s) { shape_as<Plane>(s.primitives[0].shape).normal = Vec3(0); });
    for (int i = 0; i < 3; ++i) viewer.frame(state);
    EXPECT_EQ(state.render.renderer.jobs_started(), jobs);
    EXPECT_NE(state.render.render_note.find("normal"), std::string::npos)
        << state.render.render_note;
    EXPECT_EQ(state.render.display, good);
    undo(state);
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    EXPECT_TRUE(state.render.render_note.empty()) << state.render.render_note;
}

TEST_F(ViewerGl, OpeningAMissingFileExplainsAndKeepsWhatIsOpen) {
    open_scene(state, "/nonexistent/nothing.jts");
    viewer.frame(state);
    EXPECT_FALSE(state.doc.loaded);
    ASSERT_FALSE(state.doc.diagnostics.empty());
    EXPECT_NE(state.doc.diagnostics[0].message.find("no such file"), std::string::npos);
    open_scene(state, kScene);
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    const Image8 good = state.render.display;
    open_scene(state, "/nonexistent/other.jts");
    viewer.frame(state);
    EXPECT_TRUE(state.doc.loaded);
    EXPECT_EQ(state.doc.path, kScene) << "the open scene stays";
    EXPECT_EQ(state.render.display, good);
}

// The Diagnostics panel after a failed open of another file: its errors,
// under a line saying the open failed and which file is still shown, not
// that the last good scene shows until the file is fixed.
TEST_F(ViewerGl, AFailedOpenOfAnotherFileSaysWhichFileIsShown) {
    const fs::path file = scene_copy("failed-open");
    const fs::path other = file.parent_path() / "other.jts";
    write_file(other, "render_settings {\n    width: 64\n}\n");
    open_scene(state, file);
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    open_scene(state, other);
    for (int i = 0; i < 3; ++i) viewer.frame(state);
    const std::string said = "Could not open other.jts: still showing scene.jts.";
    EXPECT_NE(find_item(viewer.ui_items(), said), nullptr) << said;
    for (const UiItem& item : viewer.ui_items())
        EXPECT_EQ(item.label.find("last good"), std::string::npos) << item.label;
    const auto listed = [&](const std::string& start) {
        for (const UiItem& item : viewer.ui_items())
            if (item.label.rfind(start, 0) == 0) return true;
        return false;
    };
    EXPECT_TRUE(listed("other.jts:2:14: error: ")) << "the other file's error, quoted";
    // An edit of the file shown: its own diagnostics again (none), listed so.
    edit_scene(state, [](Scene& s) { s.settings.width = 60; });
    for (int i = 0; i < 3; ++i) viewer.frame(state);
    EXPECT_FALSE(listed("other.jts:")) << "the panel follows the diagnostics";
    EXPECT_EQ(find_item(viewer.ui_items(), said), nullptr);
    fs::remove_all(file.parent_path());
}

// A scale component dragged to 0 in the transform panel leaves the primitive
// out by the core's one rule, even with a rotation after it (whose rounding
// once kept it in as speckles): the viewer shows the scene without it.
TEST_F(ViewerGl, ScaleEditedToZeroLeavesThePrimitiveOut) {
    open_scene(state, kScene);
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    edit_scene(state, [](Scene& s) {
        s.primitives[1].transforms = {{TransformKind::yrotate, Vec3(0.0), 150.0},
                                      {TransformKind::scale, Vec3(1.0), 0.0},
                                      {TransformKind::yrotate, Vec3(0.0), 60.0}};
    });
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    const Image8 shown = state.render.display;
    edit_scene(state, [](Scene& s) { s.primitives[1].transforms[1].vector.x = 0.0; });
    ASSERT_TRUE(viewer.run_until_complete(state, kTimeout));
    Scene without = state.doc.scene;
    without.primitives.erase(without.primitives.begin() + 1);
    EXPECT_EQ(state.render.display, core_render(without, 0));
    EXPECT_NE(state.render.display, shown);
}

TEST_F(ViewerGl, EscapeTwiceQuits) {
    open_scene(state, kScene);
    viewer.press_key(state, keys::escape);
    EXPECT_FALSE(state.quit);
    viewer.press_key(state, keys::escape);
    EXPECT_TRUE(state.quit);
}

using Clock = std::chrono::steady_clock;

// The window's loop, as main.cpp runs it: frames, and sleeps while waiting
// for the workers. The frame after the render's wakeup shows its first pass.
TEST(Wakeup, FrameAfterTheRendersWakeupShowsTheFirstPass) {
    HeadlessViewer viewer(320, 240);
    ASSERT_TRUE(viewer.ok()) << viewer.error();
    AppState state(test_config());
    request_open(state, kScene);
    const auto deadline = Clock::now() + kTimeout;
    int frames = 0;
    // The frame that starts the render waits a few milliseconds for the first
    // pass and may show some of its tiles already; the test is about the pass.
    while (state.render.passes_shown < 1 && Clock::now() < deadline) {
        const std::uint64_t seen = state.wakeup.count();
        if (waiting_for_workers(state.files, state.render)) {
            ASSERT_TRUE(state.wakeup.wait(seen, deadline));
            EXPECT_FALSE(waiting_for_workers(state.files, state.render))
                << "woken with something to show";
        }
        viewer.frame(state);
        ++frames;
    }
    ASSERT_GE(state.render.passes_shown, 1);
    EXPECT_TRUE(viewer.presenter().has_image());
    EXPECT_GT(state.render.renderer.passes_since_start(), 0);
    EXPECT_LE(frames, 3) << "one frame takes the load in, the next shows the first pass";
    EXPECT_FALSE(waiting_for_workers(state.files, state.render));
}

TEST(Wakeup, FrameThatStartsTheRenderShowsAFirstPassDoneWithinTheWait) {
    HeadlessViewer viewer(320, 240);
    ASSERT_TRUE(viewer.ok()) << viewer.error();
    ViewerConfig config = test_config();
    config.first_pass_wait = std::chrono::minutes(1);  // long enough for any machine
    AppState state(config);
    open_scene(state, kScene);
    viewer.frame(state);
    EXPECT_EQ(state.render.renderer.jobs_started(), 1u);
    EXPECT_GT(state.render.renderer.passes_since_start(), 0);
    EXPECT_TRUE(viewer.presenter().has_image()) << "in the texture in the frame that started it";
    EXPECT_GE(state.render.passes_shown, 1);
}

}  // namespace
}  // namespace jt::view
