// What makes the viewer's first picture quick (issue 6): a coarse first
// preview on large images, a render that yields to the frames, a frame loop
// woken by the workers instead of the next tick, and a material edit that
// reuses the prepared geometry. None of it may change the final pixels.

#include "common/scenes.hpp"
#include "common/scratch_dir.hpp"
#include "jtracer/parser.hpp"
#include "jtracer/render_job.hpp"
#include "jtracer/scene_file.hpp"
#include "jtracer/validate.hpp"
#include "model/app_actions.hpp"
#include "model/model_frame.hpp"
#include "model/prepared_ahead.hpp"
#include "model/scene_loader.hpp"
#include "model/text_checker.hpp"
#include "model/wakeup.hpp"
#include "render/prepared_scene.hpp"
#include "viewer/viewer_test_files.hpp"

#include <gtest/gtest.h>

#include <sys/resource.h>

#include <cerrno>
#include <chrono>
#include <fstream>
#include <future>
#include <iterator>
#include <memory>
#include <sstream>
#include <thread>

namespace jt::view {
namespace {

using namespace jt::test;
using Clock = std::chrono::steady_clock;

RenderOptions options_for(const Scene& scene, bool previews) {
    RenderOptions options = render_options_for(scene);
    options.previews = previews;
    return options;
}

// Every block x block square (clipped at the edges) holds one colour.
bool made_of_blocks(const Image8& image, int block) {
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c)
                if (image.pixel(x, y)[c] != image.pixel(x / block * block, y / block * block)[c])
                    return false;
    return true;
}

TEST(FirstPreview, LargeImageStartsAtOneSixteenthAndEndsWithTheSamePixels) {
    // 768x432 at 1/8 would be 96 x 54 = 5184 rays: over the 4096 of a first preview.
    const Scene scene = showcase_at(768, 432);
    const auto prepared = prepare_scene(scene).value();
    RenderJob job(prepared, options_for(scene, true));
    EXPECT_EQ(job.progress().pass_name, "preview 1/16");
    ASSERT_TRUE(job.run_pass());
    const Image8 first = job.image();
    EXPECT_TRUE(made_of_blocks(first, 16));
    EXPECT_FALSE(made_of_blocks(first, 32)) << "the blocks are 16 pixels, not larger";
    EXPECT_EQ(job.progress().pass_name, "preview 1/8");
    job.run();
    EXPECT_TRUE(job.progress().finished);
    EXPECT_EQ(job.image(), render_image(prepared, options_for(scene, false)));
}

TEST(FirstPreview, SmallImageStartsAtOneEighth) {
    const Scene scene = showcase_at(512, 288);  // 64 x 36 = 2304 rays at 1/8
    RenderJob job(prepare_scene(scene).value(), options_for(scene, true));
    EXPECT_EQ(job.progress().pass_name, "preview 1/8");
    EXPECT_EQ(job.progress().pass_count, 4);
}

TEST(FirstPreview, BackgroundJobRunsLowerAndRendersTheSamePixels) {
    const Scene scene = showcase_at(96, 54);
    const auto prepared = prepare_scene(scene).value();
    RenderOptions options = options_for(scene, true);
    options.threads = 1;  // only the calling thread: the test's own workers stay as they are
    options.background = true;
    errno = 0;
    if (const int nice = getpriority(PRIO_PROCESS, 0); errno == 0 && nice >= 10)
        GTEST_SKIP() << "the tests run at nice " << nice << ": a lowering to 10 cannot show";
    Image8 image;
    int nice_before = 0, nice_after = 0;
    std::thread worker([&] {
        nice_before = getpriority(PRIO_PROCESS, 0);
        RenderJob job(prepared, options);
        job.run();
        image = job.image();
        nice_after = getpriority(PRIO_PROCESS, 0);
    });
    worker.join();
    EXPECT_LT(nice_before, 10);
    EXPECT_GE(nice_after, 10);
    EXPECT_EQ(image, render_image(prepared, options_for(scene, false)));
}

TEST(Wakeup, WaitEndsOnANotifyMadeAfterTheCountWasTaken) {
    Wakeup wakeup;
    int callbacks = 0;
    wakeup.set_callback([&] { ++callbacks; });
    const std::uint64_t seen = wakeup.count();
    EXPECT_FALSE(wakeup.wait(seen, Clock::now() + std::chrono::milliseconds(5)));
    wakeup.notify();  // before the wait: not missed
    EXPECT_TRUE(wakeup.wait(seen, Clock::now() + std::chrono::minutes(1)));
    EXPECT_EQ(callbacks, 1);
    std::thread later([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        wakeup.notify();
    });
    EXPECT_TRUE(wakeup.wait(seen + 1, Clock::now() + std::chrono::minutes(1)));
    later.join();
    EXPECT_EQ(wakeup.count(), seen + 2);
}

TEST(Wakeup, FinishedLoadWakesTheLoopAndEndsTheWait) {
    AppState state(test_config());
    const std::uint64_t seen = state.wakeup.count();
    request_open(state, kScene);
    ASSERT_TRUE(state.wakeup.wait(seen, Clock::now() + kTimeout));
    EXPECT_FALSE(state.files.loader.in_flight());
    EXPECT_TRUE(state.files.loader.busy()) << "the result waits to be taken in";
    EXPECT_FALSE(waiting_for_workers(state.files, state.render))
        << "the next frame has a load to take in";
    EXPECT_TRUE(take_finished_load(state));
    EXPECT_TRUE(state.doc.loaded);
}

// While a file loads and no render runs, nothing on screen changes until the
// loader wakes the loop: the loop sleeps as long as when idle, leaving the
// cores to the load (with software OpenGL a frame costs tens of ms of CPU).
TEST(Wakeup, ALoadWithNoRenderRunningSleepsAsLongAsIdle) {
    const std::filesystem::path file = make_scratch_dir("jt_wakeup_load") / "spheres.jts";
    std::string text = "cameras { perspective_camera { } }\nscene {\n";
    for (int i = 0; i < 40'000; ++i)
        text += "sphere { center: <" + std::to_string(i) + ", 0, 0>; radius: 1; }\n";
    std::ofstream(file) << text << "}\n";
    AppState state(test_config());
    EXPECT_EQ(workers_frame_wait(state), worker_frame_wait);
    request_open(state, file);
    // Checked at once: parsing 40,000 spheres takes tens of milliseconds.
    ASSERT_TRUE(state.files.loader.in_flight());
    EXPECT_TRUE(waiting_for_workers(state.files, state.render));
    // The clock playing wants its frames meanwhile.
    state.time.playing = true;
    EXPECT_EQ(workers_frame_wait(state), worker_frame_wait);
    state.time.playing = false;
    // Still loading, so the check above was made during the load too.
    EXPECT_EQ(workers_frame_wait(state), idle_frame_wait);
    EXPECT_GT(idle_frame_wait, worker_frame_wait);
    state.files.loader.wait();
}

// The render of a scene just opened adopts the loader's preparation made
// ahead, and its first pass comes only once that ends: the frame that takes
// the load in waits for it (opened_first_pass_wait), so that the first preview
// shows in that frame rather than after one more frame drawn beside the
// preparation. Any other render waits no longer than first_pass_wait.
TEST(FirstPreview, TheFrameThatTakesAnOpenInShowsItsFirstPass) {
    ViewerConfig config = test_config();
    config.first_pass_wait = std::chrono::milliseconds(0);
    config.opened_first_pass_wait = std::chrono::minutes(1);  // long enough for any machine
    AppState state(config);
    const std::filesystem::path file = scene_copy("jt_first_preview_reload");
    request_open(state, file);
    state.files.loader.wait();
    model_frame(state);  // takes the load in and starts the render
    ASSERT_TRUE(state.doc.loaded) << state.message;
    ASSERT_EQ(state.render.renderer.jobs_started(), 1u) << state.render.render_note;
    EXPECT_TRUE(state.render.renderer.renders_adopted());
    EXPECT_GT(state.render.renderer.passes_since_start(), 0);
    EXPECT_GE(state.render.passes_shown, 1) << "fetched in the frame that took the load in";

    // A reload is not prepared ahead, nor is an edit: they wait as before.
    // (The file changes: a reload of the scene shown would keep its render.)
    std::string text;
    {
        std::ifstream in(file, std::ios::binary);
        text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    text.replace(text.find("recurse_depth: 2;"), 17, "recurse_depth: 3;");
    std::ofstream(file, std::ios::binary) << text;
    model_frame(state);  // the change is seen: a reload
    state.files.loader.wait();
    model_frame(state);
    ASSERT_EQ(state.render.renderer.jobs_started(), 2u) << state.render.render_note;
    EXPECT_FALSE(state.render.renderer.renders_adopted());
    edit_scene(state, [](Scene& s) { s.primitives[0].material.pigment = Colour(0.2, 0.4, 0.6); });
    model_frame(state);
    ASSERT_EQ(state.render.renderer.jobs_started(), 3u) << state.render.render_note;
    EXPECT_FALSE(state.render.renderer.renders_adopted());
    std::filesystem::remove_all(file.parent_path());
}

TEST(FirstPreview, AnOpenedSceneIsNotValidatedAgainBeforeItsRender) {
    // The "top" camera's aspect no longer matches the image: a warning, so
    // that the diagnostics the loader found are not trivially empty.
    const std::filesystem::path file = scene_copy("jt_first_preview_validated");
    std::string text;
    {
        std::ifstream in(file);
        text.assign(std::istreambuf_iterator<char>(in), {});
    }
    const std::string aspect = "aspect: 1.3333333333333333;\n        fov: 50;";
    ASSERT_NE(text.find(aspect), std::string::npos);
    text.replace(text.find(aspect), aspect.size(), "aspect: 2;\n        fov: 50;");
    std::ofstream(file, std::ios::trunc) << text;

    AppState state(test_config());
    open_scene(state, file);
    ASSERT_TRUE(state.doc.loaded) << state.message;
    EXPECT_EQ(state.check.checked_revision, state.doc.revision)
        << "the loader's diagnostics describe the scene taken in";
    EXPECT_EQ(state.check.error_free_revision, state.doc.revision) << "and it has no errors";
    const std::vector<Diagnostic> loaded = state.doc.diagnostics;
    ASSERT_EQ(loaded.size(), 1u);
    EXPECT_EQ(loaded[0].severity, Severity::warning);

    model_frame(state);
    EXPECT_EQ(state.render.renderer.jobs_started(), 1u) << state.render.render_note;
    // What a check of the scene finds now is what the loader found.
    state.check.checked_revision.reset();
    check_edits(state.check, state.doc, state.files);
    EXPECT_EQ(state.doc.diagnostics, loaded);
}

// Starts `scene` and waits for its last pass: the picture the render ends on.
Image8 render_to_the_end(RenderController& renderer, std::shared_ptr<const Scene> scene,
                         const RenderOptions& options) {
    renderer.start(std::move(scene), options);
    const auto deadline = Clock::now() + kTimeout;
    while (!renderer.finished() && Clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    EXPECT_TRUE(renderer.finished());
    Image8 image;
    renderer.fetch(image);
    return image;
}

TEST(RenderReuse, MaterialEditReusesTheGeometryAndRendersTheEditedScene) {
    Scene scene = showcase_at(160, 90);
    const RenderOptions options = options_for(scene, true);
    RenderController renderer;
    auto render = [&](const Scene& s) {
        return render_to_the_end(renderer, std::make_shared<const Scene>(s), options);
    };
    render(scene);
    const auto first = renderer.prepared();
    ASSERT_TRUE(first);

    scene.primitives[0].material.pigment = Colour(0.2, 0.7, 0.3);
    scene.lights[0].intensity = Colour(0.5, 0.5, 0.9);
    const Image8 edited = render(scene);
    const auto second = renderer.prepared();
    ASSERT_TRUE(second);
    EXPECT_NE(second, first);
    EXPECT_EQ(second->geometry, first->geometry) << "materials and lights leave the BVH as it was";
    EXPECT_EQ(second->materials_gathered, 1u) << "only the recoloured object's material is new";
    EXPECT_EQ(edited, render_image(prepare_scene(scene).value(), options_for(scene, false)))
        << "and the picture is that of the edited scene prepared from scratch";

    shape_as<Sphere>(scene.primitives[2].shape).radius *= 0.5;
    render(scene);
    EXPECT_NE(renderer.prepared()->geometry, first->geometry) << "a shape edit builds anew";
}

// More distinct materials than a preparation copies (a colour an object, as
// in a generated scene of 100,000 spheres): the render reads them where its
// scene holds them, and a colour edit of one object still patches the
// preparation rather than gathering every material again.
TEST(RenderReuse, ManyColoursAreReadInPlaceAndAColourEditPatches) {
    // The showcase's cameras and lights over a wall of small balls (no
    // pattern: a pattern's pictures are parallel to a gathered list).
    Scene scene = showcase_at(160, 90);
    scene.primitives.clear();
    constexpr int kColumns = 200, kRows = 100;
    for (int i = 0; i < kColumns * kRows; ++i) {
        Sphere sphere;
        sphere.center = Vec3(-3.0 + 0.03 * (i % kColumns), 0.02 * (i / kColumns), 0.0);
        sphere.radius = 0.012;
        if (i == 0) {  // the one recoloured, large and in the middle of the picture
            sphere.center = Vec3(0.0, 1.0, 0.5);
            sphere.radius = 0.5;
        }
        Primitive p;
        p.shape = sphere;
        p.material.pigment = Colour(double(i) / (kColumns * kRows), 0.5, 0.5);
        p.material.finish.edit().ambient = Colour(0.2, 0.2, 0.2);
        p.material.finish.edit().diffuse = Colour(0.8, 0.8, 0.8);
        scene.primitives.push_back(p);
    }
    const RenderOptions options = options_for(scene, true);
    RenderController renderer;
    auto render = [&](const Scene& s) {
        return render_to_the_end(renderer, std::make_shared<const Scene>(s), options);
    };
    const Image8 before = render(scene);
    const auto first = renderer.prepared();
    ASSERT_TRUE(first);
    EXPECT_TRUE(first->scene) << "read in place, not copied";
    EXPECT_TRUE(first->materials.empty());

    scene.primitives[0].material.pigment = Colour(0.2, 0.7, 0.3);
    const Image8 edited = render(scene);
    const auto second = renderer.prepared();
    ASSERT_TRUE(second);
    EXPECT_EQ(second->materials_gathered, 1u) << "the scene was not prepared again as a whole";
    EXPECT_EQ(second->geometry, first->geometry);
    EXPECT_TRUE(second->scene);
    EXPECT_NE(edited, before) << "the edit shows";
    EXPECT_EQ(edited, render_image(prepare_scene(scene).value(), options_for(scene, false)))
        << "the same bytes as the edited scene prepared from scratch";
}

TEST(RenderReuse, ColourEditInTheViewerPatchesThePreparedScene) {
    AppState state(test_config());
    open_scene(state, kScene);
    ASSERT_TRUE(state.doc.loaded) << state.message;
    const auto frame = [&] { model_frame(state); };
    ASSERT_TRUE(run_frames_until_complete(state, frame, kTimeout, 2));
    const auto opened = state.render.renderer.prepared();
    ASSERT_TRUE(opened);
    EXPECT_EQ(opened->materials_gathered, state.doc.scene.primitives.size());
    const Image8 before = state.render.display;

    edit_scene(state, [](Scene& s) { s.primitives[1].material.pigment = Colour(0.1, 0.8, 0.2); });
    ASSERT_TRUE(run_frames_until_complete(state, frame, kTimeout, 2));
    const auto edited = state.render.renderer.prepared();
    ASSERT_TRUE(edited);
    EXPECT_NE(edited, opened);
    EXPECT_EQ(edited->materials_gathered, 1u) << "the scene was not prepared again as a whole";
    EXPECT_EQ(edited->geometry, opened->geometry);
    EXPECT_NE(state.render.display, before) << "the edit shows";
    RenderOptions options = render_options_for(state.doc.scene);
    options.previews = false;
    EXPECT_EQ(state.render.display, render_image(prepare_scene(state.doc.scene).value(), options))
        << "the same bytes as the edited scene prepared from scratch";

    // Moving the object is not a material edit: the whole scene is prepared.
    edit_scene(state, [](Scene& s) { s.primitives[1].transforms.push_back({}); });
    ASSERT_TRUE(run_frames_until_complete(state, frame, kTimeout, 2));
    EXPECT_EQ(state.render.renderer.prepared()->materials_gathered,
              state.doc.scene.primitives.size());
}

TEST(RenderReuse, AnAdoptedPreparationRendersItsSceneWithoutPreparingAgain) {
    const auto scene = std::make_shared<const Scene>(showcase_at(160, 90));
    const RenderOptions options = options_for(*scene, true);
    AheadPreparer preparer;
    const PreparedAhead ahead = preparer.start(scene);
    RenderController renderer;
    renderer.adopt_prepared(ahead);
    auto render = [&](std::shared_ptr<const Scene> s) {
        return render_to_the_end(renderer, std::move(s), options);
    };
    const Image8 image = render(scene);
    ASSERT_TRUE(ahead.prepared.get());
    EXPECT_EQ(renderer.prepared(), *ahead.prepared.get())
        << "the very scene prepared ahead renders with that preparation";
    EXPECT_EQ(image, render_image(prepare_scene(*scene).value(), options_for(*scene, false)))
        << "and the picture is that of the scene prepared by the render";

    // Rendered again (the same scene, or an equal one), it goes through the
    // usual reuse, which looks at the files it reads again.
    render(scene);
    EXPECT_NE(renderer.prepared(), *ahead.prepared.get());
    EXPECT_EQ(renderer.prepared()->geometry, (*ahead.prepared.get())->geometry);
}

// The loader copies an opened scene for the document beside its validation:
// attempt_load hands the parsed scene over before validating it, and only
// when the parse found no error.
TEST(FirstPreview, AttemptLoadHandsOverTheParsedSceneBeforeValidating) {
    const std::filesystem::path dir = make_scratch_dir("jt_first_preview_parsed");
    const std::string settings = "render_settings { width: 8; height: 8; }\n";
    const std::string sphere =
        "scene { sphere { center: <0, 0, 0>; radius: 1; material { pigment: <1, 0, 0>; } } }\n";
    // Parses, but the camera looks nowhere: an error only validation finds.
    std::ofstream(dir / "invalid.jts")
        << settings
        << "cameras { perspective_camera { position: <0, 0, 0>; look_at: <0, 0, 0>; } }\n"
        << sphere;
    std::ofstream(dir / "broken.jts") << settings << "scene { sphere { center: <0, 0 } }\n";

    std::vector<const Scene*> handed;
    const ParsedScene note = [&](const std::shared_ptr<const Scene>& scene) {
        handed.push_back(scene.get());
    };
    const LoadAttempt good = attempt_load(kScene, {}, note);
    ASSERT_TRUE(good.ok);
    ASSERT_EQ(handed.size(), 1u);
    EXPECT_EQ(handed[0], good.scene.get()) << "the attempt's scene itself";

    handed.clear();
    const LoadAttempt invalid = attempt_load(dir / "invalid.jts", {}, note);
    EXPECT_TRUE(invalid.read);
    EXPECT_FALSE(invalid.ok);
    EXPECT_EQ(handed.size(), 1u) << "handed over before the validation found the error";

    handed.clear();
    const LoadAttempt broken = attempt_load(dir / "broken.jts", {}, note);
    EXPECT_TRUE(broken.read);
    EXPECT_FALSE(broken.ok);
    EXPECT_TRUE(handed.empty()) << "a text with parse errors is not handed over";
}

TEST(FirstPreview, AnOpenWithoutErrorsIsPreparedByTheLoader) {
    SceneLoader loader;
    loader.request(kScene, LoadPurpose::open);
    loader.wait();
    std::optional<FinishedLoad> opened = loader.take();
    ASSERT_TRUE(opened && opened->attempt.ok);
    ASSERT_TRUE(opened->ahead) << "an open without errors is prepared while it is taken in";
    EXPECT_EQ(opened->ahead->scene, opened->attempt.scene) << "the scene itself, not a copy";
    ASSERT_TRUE(opened->attempt.scene_copy);
    EXPECT_EQ(*opened->attempt.scene_copy, *opened->attempt.scene);
    EXPECT_TRUE(opened->ahead->prepared.get());

    loader.request(kScene, LoadPurpose::reload);
    loader.wait();
    const std::optional<FinishedLoad> reloaded = loader.take();
    ASSERT_TRUE(reloaded && reloaded->attempt.ok);
    EXPECT_FALSE(reloaded->ahead) << "a reload reuses the geometry prepared already";
}

// The loader hands an open over once its preparation made ahead is done, so
// that the frame taking it in shows the first preview (prepared_ahead_hold);
// a newer request ends that hold.
TEST(FirstPreview, AnOpenIsHandedOverOnceItsPreparationIsDone) {
    const std::filesystem::path file = make_scratch_dir("jt_first_preview_hold") / "spheres.jts";
    // Tens of milliseconds to prepare: more than the loader's copy of the scene.
    std::string text =
        "render_settings { width: 64; height: 48; }\n"
        "cameras { perspective_camera { } }\nscene {\n";
    for (int i = 0; i < 40'000; ++i)
        text += "sphere { center: <" + std::to_string(i % 200) + ", " + std::to_string(i / 200) +
                ", 0>; radius: 0.4; }\n";
    std::ofstream(file) << text << "}\n";
    // A hold longer than any machine takes, so that only the hold decides; a
    // newer request must still end it at once (the end of the test).
    SceneLoader loader(std::chrono::minutes(10));
    loader.request(file, LoadPurpose::open);
    loader.wait();
    const std::optional<FinishedLoad> opened = loader.take();
    ASSERT_TRUE(opened);
    ASSERT_TRUE(opened->attempt.ok) << opened->attempt.diagnostics.front().message;
    ASSERT_TRUE(opened->ahead);
    EXPECT_EQ(opened->ahead->prepared.wait_for(std::chrono::seconds(0)), std::future_status::ready)
        << "handed over with its preparation done";
    EXPECT_TRUE(opened->ahead->prepared.get());
    // Meanwhile it made the copies of the text the document keeps.
    ASSERT_TRUE(opened->attempt.text_copies);
    EXPECT_EQ(opened->attempt.text_copies->diagnostics_source, opened->attempt.text);
    EXPECT_EQ(opened->attempt.text_copies->disk_text, opened->attempt.text);
    EXPECT_FALSE(opened->attempt.text_copies->uses_clock);

    // Overtaken by a newer request, maybe while it waits: the newer one is handed over.
    loader.request(file, LoadPurpose::open);
    loader.request(kScene, LoadPurpose::open);
    loader.wait();
    const std::optional<FinishedLoad> newest = loader.take();
    ASSERT_TRUE(newest && newest->attempt.ok);
    EXPECT_EQ(newest->path, kScene);
}

// An open, and a check of the editor's text, validate a large scene in chunks
// on TBB's threads and take the parser's range checks as made: they still
// find what the whole checks on one thread find, errors and warnings, at the
// same places and in the same order.
TEST(FirstPreview, AnOpenFindsWhatTheWholeChecksFind) {
    const std::filesystem::path file = make_scratch_dir("jt_first_preview_checks") / "checked.jts";
    // Several of the validation's chunks (8192 primitives each), with
    // findings in each, and the parser's one unchecked default last.
    constexpr int primitives = 40'000;
    std::string text =
        "render_settings { width: 40; height: 20; }\n"
        "cameras { perspective_camera { aspect: 1; } }\n"
        "scene {\n";
    for (int i = 0; i < primitives - 1; ++i) {
        if (i % 5'000 == 17)
            text += "triangle { a: <0, 0, 0>; b: <1, 1, 1>; c: <2, 2, 2>; }\n";
        else if (i % 7'000 == 3)
            text += "cylinder { transform { scale: <1, 0, 1>; } }\n";
        else
            text += "sphere { center: <" + std::to_string(i) + ", 0, 0>; radius: 1; }\n";
    }
    text += "mesh { }\n}\n";
    std::ofstream(file) << text;

    const Expected<LoadedScene> loaded = load_scene_file(file, {.source_map = true});
    ASSERT_TRUE(loaded);
    std::vector<Diagnostic> whole = loaded->parsed.diagnostics;
    for (const Diagnostic& d : validate_scene(loaded->parsed.scene, loaded->parsed.source))
        whole.push_back(d);
    // The aspect's warning, 8 triangles, 6 cylinders and the mesh's error.
    ASSERT_EQ(whole.size(), 16u);
    EXPECT_EQ(whole.back().severity, Severity::error);

    const LoadAttempt opened = attempt_load(file);
    EXPECT_TRUE(opened.read);
    EXPECT_FALSE(opened.ok);
    EXPECT_TRUE(opened.diagnostics == whole) << opened.diagnostics.size() << " findings";

    const CheckedText checked = check_text(1, text, file, {});
    EXPECT_FALSE(checked.ok);
    EXPECT_TRUE(checked.diagnostics == whole) << checked.diagnostics.size() << " findings";
}

}  // namespace
}  // namespace jt::view
