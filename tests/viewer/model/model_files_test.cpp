// The model and image files a scene names, changed under the viewer: the
// display follows the new geometry or picture, a model that no longer loads
// is reported where the scene names it and keeps the last image, Reload model
// reads a file whose stamp did not move, and no unsaved scene edit is lost.

#include "common/files.hpp"
#include "common/scratch_dir.hpp"
#include "jtracer/png.hpp"
#include "model/app_actions.hpp"
#include "viewer/model/model_loop.hpp"
#include "viewer/viewer_test_files.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <thread>

namespace jt::view {
namespace {

namespace fs = std::filesystem;
using namespace jt::test;

// A square facing the camera, one tile of the image map over it.
const std::string kSceneText =
    R"(render_settings { width: 48; height: 32; ambient_light: <1, 1, 1>; }
cameras { perspective_camera { position: <0, 0, 5>; look_at: <0, 0, 0>; aspect: 1.5; } }
scene {
    mesh {
        file: "model.obj";
        material { image_map: "map.png"; ambient: <1, 1, 1>; diffuse: <0, 0, 0>; }
    }
}
)";
constexpr SourcePos kFileString{5, 15};  // where `"model.obj"` starts

std::string square_obj(double half) {
    const std::string h = std::to_string(half);
    return "v -" + h + " -" + h + " 0\nv " + h + " -" + h + " 0\nv " + h + " " + h + " 0\nv -" + h +
           " " + h + " 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\n";
}

Image8 flat_image(std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    Image8 image(2, 2);
    for (std::size_t i = 0; i < image.rgb.size(); i += 3) {
        image.rgb[i] = r;
        image.rgb[i + 1] = g;
        image.rgb[i + 2] = b;
    }
    return image;
}

// Written beside and renamed over, as editors save.
void save_as_editor(const fs::path& path, const std::string& bytes) {
    const fs::path temp = fs::path(path).concat(".tmp");
    write_file(temp, bytes);
    fs::rename(temp, path);
}

class ViewerModelFiles : public ::testing::Test {
  protected:
    void SetUp() override {
        write_file(dir.path() / "scene.jts", kSceneText);
        write_file(dir.path() / "model.obj", square_obj(1.0));
        ASSERT_TRUE(write_png(dir.path() / "map.png", flat_image(200, 40, 40)));
        open_scene(state, dir.path() / "scene.jts");
        ASSERT_TRUE(model.run_until_complete(state));
        first = state.render.display;
    }

    // What a fresh viewer shows for the files as they are now.
    Image8 fresh_render() {
        AppState other{test_config()};
        open_scene(other, dir.path() / "scene.jts");
        EXPECT_TRUE(model.run_until_complete(other));
        return other.render.display;
    }

    // Frames until the render that answers the change is complete.
    void run_after_change() {
        model.frame(state);  // the watcher sees the change
        ASSERT_TRUE(model.run_until_complete(state));
    }

    ScratchDir dir{"model_files"};
    ModelLoop model;
    AppState state{test_config()};
    Image8 first;
};

int count_colour(const Image8& image, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    int n = 0;
    for (std::size_t i = 0; i < image.rgb.size(); i += 3)
        n += image.rgb[i] == r && image.rgb[i + 1] == g && image.rgb[i + 2] == b;
    return n;
}

TEST_F(ViewerModelFiles, AChangedModelFileShowsTheNewGeometry) {
    const int covered = count_colour(first, 200, 40, 40);
    ASSERT_GT(covered, 0) << "the square shows the map's colour";
    save_as_editor(dir.path() / "model.obj", square_obj(0.5));
    run_after_change();
    EXPECT_NE(state.render.display, first);
    EXPECT_EQ(state.render.display, fresh_render());
    const int now = count_colour(state.render.display, 200, 40, 40);
    EXPECT_GT(now, 0);
    EXPECT_LT(now, covered / 2) << "half the edge: about a quarter of the pixels";
    EXPECT_FALSE(has_unsaved_edits(state.doc));
}

TEST_F(ViewerModelFiles, AChangedImageMapShowsTheNewPicture) {
    ASSERT_TRUE(write_png(dir.path() / "map.png.tmp", flat_image(30, 90, 220)));
    fs::rename(dir.path() / "map.png.tmp", dir.path() / "map.png");
    run_after_change();
    EXPECT_EQ(count_colour(state.render.display, 200, 40, 40), 0);
    EXPECT_EQ(count_colour(state.render.display, 30, 90, 220), count_colour(first, 200, 40, 40));
    EXPECT_EQ(state.render.display, fresh_render());
}

// Opened while paused, the scene's preparation made ahead waits unused; an
// image map changed meanwhile must not show as it was when that was made.
TEST_F(ViewerModelFiles, AnImageMapChangedBeforeTheFirstRenderShowsTheNewPicture) {
    AppState paused{test_config()};
    toggle_pause(paused);
    open_scene(paused, dir.path() / "scene.jts");
    ASSERT_TRUE(paused.doc.loaded) << paused.message;
    model.frame(paused);  // the watcher looks at the files as the open found them
    EXPECT_EQ(paused.render.renderer.jobs_started(), 0u);
    ASSERT_TRUE(write_png(dir.path() / "map.png.tmp", flat_image(30, 90, 220)));
    fs::rename(dir.path() / "map.png.tmp", dir.path() / "map.png");
    model.frame(paused);  // and sees the change
    toggle_pause(paused);
    ASSERT_TRUE(model.run_until_complete(paused));
    EXPECT_EQ(count_colour(paused.render.display, 200, 40, 40), 0) << "not the old picture";
    EXPECT_EQ(paused.render.display, fresh_render());
}

TEST_F(ViewerModelFiles, ABrokenModelIsLocatedAndKeepsTheLastImage) {
    static_cast<void>(take_display_changes(state.render));  // shown
    save_as_editor(dir.path() / "model.obj", "v 0 0 0\nf 1 2 3 oops\n\x01\x02garbage");
    model.frame(state);
    for (int i = 0; i < 5; ++i) model.frame(state);
    ASSERT_FALSE(state.doc.diagnostics.empty());
    const Diagnostic& d = state.doc.diagnostics.front();
    EXPECT_EQ(d.severity, Severity::error);
    EXPECT_EQ(d.pos, kFileString) << d.message;
    EXPECT_NE(d.message.find("model.obj"), std::string::npos) << d.message;
    EXPECT_EQ(state.render.display, first);
    EXPECT_FALSE(take_display_changes(state.render)) << "nothing new to show";
    EXPECT_NE(state.render.render_note.find("Not rendered"), std::string::npos)
        << state.render.render_note;

    save_as_editor(dir.path() / "model.obj", square_obj(1.0));  // fixed
    run_after_change();
    // No error is left; the square has no normals, which is only a warning
    // (docs/language.md §14.4).
    for (const Diagnostic& left : state.doc.diagnostics)
        EXPECT_EQ(left.severity, Severity::warning) << left.message;
    EXPECT_EQ(state.render.display, first);
}

TEST_F(ViewerModelFiles, ReloadModelReadsAFileWhoseStampDidNotMove) {
    // Same size, same time, same inode: a copy tool that keeps the time.
    const fs::path file = dir.path() / "model.obj";
    const auto time = fs::last_write_time(file);
    const std::string smaller = square_obj(0.5);
    ASSERT_EQ(smaller.size(), square_obj(1.0).size());
    {
        std::ofstream out(file, std::ios::binary | std::ios::in | std::ios::out);
        out << smaller;
    }
    fs::last_write_time(file, time);
    for (int i = 0; i < 3; ++i) model.frame(state);
    ASSERT_TRUE(state.render.started.has_value());
    EXPECT_EQ(state.render.display, first) << "the watcher cannot tell";

    reload_model(state, 0);
    ASSERT_TRUE(model.run_until_complete(state));
    EXPECT_NE(state.render.display, first);
    EXPECT_LT(count_colour(state.render.display, 200, 40, 40),
              count_colour(first, 200, 40, 40) / 2);
}

TEST_F(ViewerModelFiles, AModelChangeKeepsTheUnsavedEdits) {
    edit_scene(state,
               [](Scene& s) { s.primitives[0].material.finish.edit().ambient = Colour(0.5); });
    ASSERT_TRUE(model.run_until_complete(state));
    const Scene edited = state.doc.scene;
    const Image8 before = state.render.display;
    save_as_editor(dir.path() / "model.obj", square_obj(0.5));
    run_after_change();
    EXPECT_EQ(state.doc.scene, edited);
    EXPECT_TRUE(has_unsaved_edits(state.doc));
    EXPECT_FALSE(state.files.pending_reload) << "nothing to choose: the scene text did not change";
    EXPECT_NE(state.render.display, before);
    EXPECT_EQ(count_colour(state.render.display, 100, 20, 20),
              count_colour(fresh_render(), 200, 40, 40));
}

// Found in the real window: a scene whose sky map was not there yet opened
// with "cannot read 'sky.png'"; the file then made changed nothing until
// Reload. The scene's files were watched only once it had loaded. So with a
// scene that loaded and then named a missing sky map in another editor.
const std::string kSkyScene =
    R"(render_settings { width: 16; height: 12; background_map: "sky.png"; }
cameras { perspective_camera { aspect: 1.3333333333333333; } }
scene { sphere { center: <0, 0, -5>; } }
)";

bool run_until(ModelLoop& model, AppState& state, const std::function<bool()>& done) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (!done()) {
        if (std::chrono::steady_clock::now() > until) return false;
        model.frame(state);
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return true;
}

TEST(ViewerSkyMapFile, AMissingSkyMapAppearingLoadsTheScene) {
    ScratchDir dir{"sky_appears"};
    ModelLoop model;
    AppState state{test_config()};
    write_file(dir.path() / "scene.jts", kSkyScene);
    open_scene(state, dir.path() / "scene.jts");
    ASSERT_FALSE(state.doc.loaded);
    const std::string shown = format_diagnostics(state.doc);
    EXPECT_NE(shown.find("sky.png': no such file"), std::string::npos) << shown;
    model.frame(state);
    ASSERT_TRUE(write_png(dir.path() / "sky.png", flat_image(30, 90, 220)));
    EXPECT_TRUE(run_until(model, state, [&] { return state.doc.loaded; }))
        << "the file appearing loads the scene: " << state.message;
    ASSERT_TRUE(model.run_until_complete(state));
    EXPECT_GT(count_colour(state.render.display, 30, 90, 220), 0) << "the sky is shown";
}

TEST(ViewerSkyMapFile, ASkyMapNamedBeforeItExistsIsReadWhenItAppears) {
    ScratchDir dir{"sky_named"};
    ModelLoop model;
    AppState state{test_config()};
    ASSERT_TRUE(write_png(dir.path() / "sky.png", flat_image(30, 90, 220)));
    write_file(dir.path() / "scene.jts", kSkyScene);
    open_scene(state, dir.path() / "scene.jts");
    ASSERT_TRUE(state.doc.loaded) << format_diagnostics(state.doc);
    ASSERT_TRUE(model.run_until_complete(state));
    std::string named = kSkyScene;
    named.replace(named.find("sky.png"), 7, "new.png");
    save_as_editor(dir.path() / "scene.jts", named);
    ASSERT_TRUE(run_until(model, state, [&] { return state.doc.load_failed; })) << state.message;
    model.frame(state);  // the file is missing a frame or more, as the user makes it
    ASSERT_TRUE(write_png(dir.path() / "new.png", flat_image(200, 40, 40)));
    EXPECT_TRUE(run_until(model, state, [&] { return !state.doc.load_failed; }))
        << "the file appearing reloads: " << state.message;
    EXPECT_EQ(state.doc.scene.settings.background_map, "new.png");
    ASSERT_TRUE(model.run_until_complete(state));
    EXPECT_GT(count_colour(state.render.display, 200, 40, 40), 0) << "the new sky is shown";
}

}  // namespace
}  // namespace jt::view
