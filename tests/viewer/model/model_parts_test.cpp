// The viewer model's parts: file watching, the free camera, undo, image
// placement, image files, recent files, remembered settings, edit tracking.

#include "common/files.hpp"
#include "common/image_header.hpp"
#include "common/scratch_dir.hpp"
#include "model/app_actions.hpp"
#include "model/file_watcher.hpp"
#include "model/free_camera.hpp"
#include "model/image_files.hpp"
#include "model/image_layout.hpp"
#include "model/latest_wins_worker.hpp"
#include "model/recent_files.hpp"
#include "model/undo_stack.hpp"
#include "model/viewer_settings.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <atomic>
#include <chrono>
#include <fstream>
#include <future>
#include <thread>

namespace jt::view {
namespace {

namespace fs = std::filesystem;

using test::make_scratch_dir;
using test::write_file;

// The loader skips the preparation ahead of an open whose result will be
// dropped: a request being run sees a newer one waiting.
TEST(LatestWinsWorker, ARunningRequestSeesThatANewerOneWaits) {
    std::promise<void> started;
    std::promise<void> go;
    const std::shared_future<void> may_go = go.get_future().share();
    std::atomic<bool> first_superseded{false};
    LatestWinsWorker<int, bool>* self = nullptr;
    LatestWinsWorker<int, bool> worker([&](int n) {
        if (n == 1) {
            started.set_value();
            may_go.wait();
            first_superseded = self->superseded();
        }
        return self->superseded();
    });
    self = &worker;
    worker.submit(1);
    started.get_future().wait();
    EXPECT_FALSE(worker.superseded()) << "nothing newer yet";
    worker.submit(2);
    EXPECT_TRUE(worker.superseded());
    go.set_value();
    worker.wait();
    EXPECT_TRUE(first_superseded) << "the first request, run, saw the second waiting";
    const std::optional<bool> newest = worker.take();
    ASSERT_TRUE(newest);
    EXPECT_FALSE(*newest) << "the newest is not superseded";
}

TEST(FileWatcher, SeesAnInPlaceWriteThatChangesTheSize) {
    const fs::path file = make_scratch_dir("watch1") / "a.jts";
    write_file(file, "one");
    FileWatcher watcher(std::chrono::milliseconds(0));
    watcher.watch(file);
    EXPECT_FALSE(watcher.poll());
    write_file(file, "three");
    EXPECT_TRUE(watcher.poll());
    EXPECT_FALSE(watcher.poll()) << "a change is reported once";
}

TEST(FileWatcher, SeesASaveByRenameEvenWithTheSameSizeAndTime) {
    const fs::path dir = make_scratch_dir("watch2");
    write_file(dir / "a.jts", "abc");
    FileWatcher watcher(std::chrono::milliseconds(0));
    watcher.watch(dir / "a.jts");
    write_file(dir / "a.jts.new", "xyz");
    fs::last_write_time(dir / "a.jts.new", fs::last_write_time(dir / "a.jts"));
    fs::rename(dir / "a.jts.new", dir / "a.jts");
    EXPECT_TRUE(watcher.poll()) << "the inode changed";
}

TEST(FileWatcher, SeesDeletionAndReappearance) {
    const fs::path file = make_scratch_dir("watch3") / "a.jts";
    write_file(file, "abc");
    FileWatcher watcher(std::chrono::milliseconds(0));
    watcher.watch(file);
    fs::remove(file);
    EXPECT_TRUE(watcher.poll());
    EXPECT_FALSE(file_stamp(file).exists);
    write_file(file, "abc");
    EXPECT_TRUE(watcher.poll());
}

TEST(FileWatcher, AcknowledgedChangesAreNotReported) {
    const fs::path file = make_scratch_dir("watch4") / "a.jts";
    write_file(file, "abc");
    FileWatcher watcher(std::chrono::milliseconds(0));
    watcher.watch(file);
    write_file(file, "abcd");
    watcher.acknowledge();
    EXPECT_FALSE(watcher.poll());
}

TEST(FileSetWatcher, AcknowledgedChangesAreNotReportedButLaterOnesAre) {
    const fs::path dir = make_scratch_dir("watch6");
    write_file(dir / "a.jts", "abc");
    write_file(dir / "b.jts", "abc");
    FileSetWatcher watcher(std::chrono::milliseconds(0));
    watcher.watch({dir / "a.jts", dir / "b.jts"});
    write_file(dir / "a.jts", "abcd");
    write_file(dir / "b.jts", "abcde");
    watcher.acknowledge();  // the viewer wrote them itself
    EXPECT_TRUE(watcher.poll().empty());
    write_file(dir / "b.jts", "x");
    EXPECT_EQ(watcher.poll(), std::vector<fs::path>{dir / "b.jts"});
}

TEST(FileWatcher, ChecksTheDiskAtMostOncePerInterval) {
    const fs::path file = make_scratch_dir("watch5") / "a.jts";
    write_file(file, "abc");
    FileWatcher watcher(std::chrono::hours(1));
    watcher.watch(file);
    write_file(file, "abcdef");
    EXPECT_FALSE(watcher.poll());
    EXPECT_TRUE(watcher.poll(FileWatcher::Clock::now() + std::chrono::hours(2)));
}

Camera test_camera() {
    Camera c;
    c.position = Vec3(0, 1, 5);
    c.look_at = Vec3(0, 1, 0);
    c.fov = 40;
    c.aspect = 1.5;
    return c;
}

TEST(FreeCamera, RoundTripsASceneCamera) {
    const Camera c = test_camera();
    const Camera back = camera_from(free_camera_from(c), "copy");
    EXPECT_EQ(back.name, "copy");
    EXPECT_EQ(back.position, c.position);
    EXPECT_EQ(back.look_at, c.look_at);
    EXPECT_EQ(back.fov, c.fov);
    EXPECT_EQ(back.aspect, c.aspect);
}

TEST(FreeCamera, OrbitKeepsTheDistanceAndTheTarget) {
    FreeCamera f = free_camera_from(test_camera());
    orbit(f, 100, 0, 400);  // a quarter of the view height: pi/4 around up
    EXPECT_NEAR(glm::length(f.position - f.look_at), 5.0, 1e-9);
    EXPECT_EQ(f.look_at, Vec3(0, 1, 0));
    EXPECT_NEAR(f.position.y, 1.0, 1e-9) << "a horizontal drag turns about up only";
    EXPECT_NEAR(std::abs(f.position.x), 5.0 * std::sin(3.14159265358979 / 4), 1e-9);
}

TEST(FreeCamera, OrbitStopsShortOfThePole) {
    FreeCamera f = free_camera_from(test_camera());
    orbit(f, 0, 100000, 400);  // drag far down: tilt over the top
    const Vec3 dir = glm::normalize(f.look_at - f.position);
    EXPECT_LT(std::abs(glm::dot(dir, f.up)), 0.99999) << "view never parallel to up";
    EXPECT_NEAR(glm::length(f.position - f.look_at), 5.0, 1e-9);
}

TEST(FreeCamera, PanMovesPositionAndTargetTogether) {
    FreeCamera f = free_camera_from(test_camera());
    pan(f, 50, 0, 100);
    EXPECT_NEAR(f.position.x - 0.0, f.look_at.x - 0.0, 1e-12);
    EXPECT_LT(f.look_at.x, 0.0) << "dragging right moves the scene right: the camera left";
    EXPECT_NEAR(glm::length(f.position - f.look_at), 5.0, 1e-9);
}

TEST(FreeCamera, DollyApproachesButNeverReachesTheTarget) {
    FreeCamera f = free_camera_from(test_camera());
    dolly(f, 1);
    EXPECT_NEAR(glm::length(f.position - f.look_at), 4.5, 1e-9);
    dolly(f, 1000);
    EXPECT_GT(glm::length(f.position - f.look_at), 0.0);
    dolly(f, -2);
    EXPECT_GT(glm::length(f.position - f.look_at), 1e-3);
}

TEST(UndoStack, UndoAndRedoWalkTheSnapshots) {
    SnapshotStack<Scene> stack;
    Scene a, b, c;
    b.settings.width = 1;
    c.settings.width = 2;
    stack.record(a);  // a -> b
    stack.record(b);  // b -> c
    auto back = stack.undo(c);
    ASSERT_TRUE(back);
    EXPECT_EQ(*back, b);
    back = stack.undo(b);
    ASSERT_TRUE(back);
    EXPECT_EQ(*back, a);
    EXPECT_FALSE(stack.undo(a));
    auto forward = stack.redo(a);
    ASSERT_TRUE(forward);
    EXPECT_EQ(*forward, b);
    stack.record(b);  // a new edit drops the redo history
    EXPECT_FALSE(stack.can_redo());
}

TEST(UndoStack, KeepsAtMostItsCapacity) {
    SnapshotStack<Scene> stack(3);
    for (int i = 0; i < 10; ++i) {
        Scene s;
        s.settings.width = i;
        stack.record(s);
    }
    EXPECT_EQ(stack.size(), 3u);
}

TEST(PlaceImage, FitKeepsTheAspectAndCentres) {
    const ScreenRect r = place_image(200, 100, ScreenRect{0, 0, 400, 400}, 1.0f, ImageView{});
    EXPECT_FLOAT_EQ(r.width(), 400);
    EXPECT_FLOAT_EQ(r.height(), 200);
    EXPECT_FLOAT_EQ(r.y0, 100);
}

TEST(PlaceImage, ActualPixelsIsOneImagePixelPerFramebufferPixelOnHiDpi) {
    const ScreenRect r =
        place_image(200, 100, ScreenRect{0, 0, 400, 400}, 2.0f, actual_pixels_view());
    EXPECT_FLOAT_EQ(r.width(), 100);  // 100 window units = 200 framebuffer pixels
    EXPECT_FLOAT_EQ(r.height(), 50);
}

TEST(PlaceImage, NothingToPlaceGivesAnEmptyRect) {
    EXPECT_EQ(place_image(0, 10, ScreenRect{0, 0, 10, 10}, 1, ImageView{}).width(), 0);
}

TEST(ImageFiles, WritesAPngWithTheImageSize) {
    const fs::path file = make_scratch_dir("png") / "out.png";
    Image8 image(7, 3);
    image.pixel(0, 0)[0] = 255;
    const Expected<void> saved = save_image(file, image);
    ASSERT_TRUE(saved) << saved.error().message;
    const std::string bytes = test::read_file(file);
    ASSERT_GT(bytes.size(), 24u);
    EXPECT_EQ(bytes.substr(1, 3), "PNG");
    EXPECT_EQ(test::png_size(bytes).width, 7u);
    EXPECT_EQ(test::png_size(bytes).height, 3u);
}

TEST(ImageFiles, RefusesUnknownExtensionsAndEmptyImagesWithoutWriting) {
    const fs::path dir = make_scratch_dir("bad");
    const Expected<void> jpg = save_image(dir / "out.jpg", Image8(2, 2));
    ASSERT_FALSE(jpg);
    EXPECT_NE(jpg.error().message.find(".png"), std::string::npos);
    EXPECT_FALSE(save_image(dir / "out.png", Image8()));
    EXPECT_TRUE(fs::is_empty(dir));
}

TEST(ImageFiles, AFailedWriteLeavesTheOldFile) {
    const fs::path dir = make_scratch_dir("keep");
    write_file(dir / "a.txt", "old");
    const Expected<void> written = write_text_atomically(dir / "missing-dir" / "a.txt", "new");
    ASSERT_FALSE(written);
    EXPECT_FALSE(written.error().message.empty());
    std::ifstream in(dir / "a.txt");
    std::string text;
    in >> text;
    EXPECT_EQ(text, "old");
}

TEST(RecentFiles, NewestFirstWithoutDuplicatesAndPersisted) {
    const fs::path store = make_scratch_dir("recent") / "sub" / "recent.txt";
    {
        RecentFiles recent;
        recent.load(store);
        recent.add("/x/a.jts");
        recent.add("/x/b.jts");
        recent.add("/x/a.jts");
        ASSERT_EQ(recent.paths().size(), 2u);
        EXPECT_EQ(recent.paths()[0], "/x/a.jts");
    }
    RecentFiles again;
    again.load(store);
    ASSERT_EQ(again.paths().size(), 2u);
    EXPECT_EQ(again.paths()[1], "/x/b.jts");
}

TEST(PassLabel, NamesThePassAsAUserReadsIt) {
    const auto label = [](const char* name, int samples) {
        RenderProgress p;
        p.pass_name = name;
        return pass_label(p, samples);
    };
    EXPECT_EQ(label("preview 1/8", 16), "preview 1/8");
    EXPECT_EQ(label("1 sample", 1), "full resolution");
    EXPECT_EQ(label("1 sample", 16), "full resolution");
    EXPECT_EQ(label("4 samples", 16), "sample 4 of 16");
}

// The status line says what the passes refine.
TEST(PassLabel, SaysWhatIsConverging) {
    const auto label = [](const char* name, int samples, const char* converging) {
        RenderProgress p;
        p.pass_name = name;
        return pass_label(p, samples, converging);
    };
    EXPECT_EQ(label("preview 1/8", 64, "soft shadows and lens"),
              "preview 1/8 (hard shadows, sharp)");
    EXPECT_EQ(label("preview 1/4", 64, "soft shadows"), "preview 1/4 (hard shadows)");
    EXPECT_EQ(label("preview 1/2", 64, "lens"), "preview 1/2 (sharp)");
    EXPECT_EQ(label("1 sample", 64, "soft shadows and lens"),
              "soft shadows and lens: sample 1 of 64");
    EXPECT_EQ(label("8 samples", 64, "lens"), "lens: sample 8 of 64");
    EXPECT_EQ(label("1 sample", 1, "soft shadows"), "full resolution with soft shadows");
    EXPECT_EQ(label("8 samples", 64, ""), "sample 8 of 64");
}

TEST(PassLabel, TheSoftShadowsAndTheLensAreFoundInTheSceneRendered) {
    Scene scene;
    scene.cameras.resize(2);
    scene.lights.resize(2);
    RenderRequest request;
    request.options.samples = 16;
    request.options.camera = 1;
    EXPECT_EQ(converging_effects(scene, request), "");
    scene.lights[1].radius = 0.5;
    EXPECT_EQ(converging_effects(scene, request), "soft shadows");
    scene.cameras[0].aperture = 0.1;
    EXPECT_EQ(converging_effects(scene, request), "soft shadows") << "another camera's lens";
    scene.cameras[1].aperture = 0.1;
    EXPECT_EQ(converging_effects(scene, request), "soft shadows and lens");
    scene.lights[1].radius = 0.0;
    EXPECT_EQ(converging_effects(scene, request), "lens");
    request.options.samples = 1;
    EXPECT_EQ(converging_effects(scene, request), "") << "one sample: the lens's centre alone";
}

TEST(ViewerSettings, WrittenWholeAndReadBack) {
    const fs::path store = make_scratch_dir("settings") / "sub" / "viewer-settings.txt";
    EXPECT_EQ(read_viewer_settings(store), ViewerSettings{}) << "missing: the defaults";
    ASSERT_TRUE(write_viewer_settings(store, ViewerSettings{41.25f}));
    EXPECT_EQ(read_viewer_settings(store).panel_width, 41.25f);
    ASSERT_TRUE(write_viewer_settings(store, ViewerSettings{12.5f}));
    EXPECT_EQ(read_viewer_settings(store).panel_width, 12.5f);
    for (const auto& entry : fs::directory_iterator(store.parent_path()))
        EXPECT_EQ(entry.path().filename(), "viewer-settings.txt") << "no temporary left";
}

TEST(ViewerSettings, ABrokenFileGivesTheDefaultsForWhatItCannotSay) {
    const fs::path store = make_scratch_dir("settings-broken") / "viewer-settings.txt";
    const auto width_from = [&](const std::string& text) {
        write_file(store, text);
        return read_viewer_settings(store).panel_width;
    };
    for (const char* broken :
         {"", "panel_width", "panel_width =", "panel_width = abc", "panel_width = 31x",
          "panel_width = nan", "panel_width = inf", "panel_width = -5", "panel_width = 1e30",
          "panel_width = 3", "\x89PNG\r\n\x1a\n\0\0 garbage", "width = 50"})
        EXPECT_EQ(width_from(broken), kDefaultPanelWidth) << broken;
    EXPECT_EQ(width_from("junk\n= 3\n  panel_width\t=  44.5 \r\n"), 44.5f);
    EXPECT_EQ(width_from(std::string(1 << 20, 'x') + "\npanel_width = 44\n"), kDefaultPanelWidth)
        << "a megabyte is not a settings file";
    // A folder where the file should be: no settings, and writing fails cleanly.
    fs::remove(store);
    fs::create_directories(store / "x");
    EXPECT_EQ(read_viewer_settings(store), ViewerSettings{});
    EXPECT_FALSE(write_viewer_settings(store, ViewerSettings{40.0f}));
}

TEST(ViewerSettings, ConfigFolderFollowsXdgThenHome) {
    const char* xdg = std::getenv("XDG_CONFIG_HOME");
    const char* home = std::getenv("HOME");
    const std::string saved_xdg = xdg ? xdg : "", saved_home = home ? home : "";
    ::setenv("XDG_CONFIG_HOME", "/cfg", 1);
    EXPECT_EQ(default_settings_path(), fs::path("/cfg/jtracer/viewer-settings.txt"));
    EXPECT_EQ(default_recent_files_path(), fs::path("/cfg/jtracer/recent-scenes.txt"));
    ::setenv("XDG_CONFIG_HOME", "", 1);
    ::setenv("HOME", "/home/u", 1);
    EXPECT_EQ(default_settings_path(), fs::path("/home/u/.config/jtracer/viewer-settings.txt"));
    ::unsetenv("HOME");
    EXPECT_TRUE(default_settings_path().empty());
    if (xdg)
        ::setenv("XDG_CONFIG_HOME", saved_xdg.c_str(), 1);
    else
        ::unsetenv("XDG_CONFIG_HOME");
    if (home) ::setenv("HOME", saved_home.c_str(), 1);
}

}  // namespace
}  // namespace jt::view

namespace jt::view {
namespace {

TEST(EditTracking, AWholeDragIsOneUndoStep) {
    AppState state;
    state.doc.loaded = true;
    const Scene start = state.doc.scene;
    const EditedBlock settings{EditedBlock::Kind::settings, 0};
    for (int frame = 0; frame < 5; ++frame) {  // the widget stays active while dragging
        const EditMark before = begin_edit_tracking(state.history, state.doc);
        settle_block(state.history, state.doc, settings);  // as the panel does
        state.doc.scene.settings.width += 10;
        note_block_edited(state.history, state.doc, settings);
        track_edits(state.history, state.doc, before, /*widget_active=*/true);
    }
    EXPECT_FALSE(state.history.undo.can_undo()) << "recorded when the drag ends";
    track_edits(state.history, state.doc, begin_edit_tracking(state.history, state.doc),
                /*widget_active=*/false);
    EXPECT_EQ(state.history.undo.size(), 1u);
    const EditMark before_undo = begin_edit_tracking(state.history, state.doc);
    undo(state);
    EXPECT_EQ(state.doc.scene, start);
    track_edits(state.history, state.doc, before_undo, false);  // the frame in which undo ran
    EXPECT_TRUE(state.history.undo.can_redo()) << "undo is not mistaken for an edit";
    redo(state);
    EXPECT_EQ(state.doc.scene.settings.width, 50);
}

}  // namespace
}  // namespace jt::view
