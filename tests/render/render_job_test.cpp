// The progressive RenderJob: passes, determinism across threads, cancel,
// fetch_updates, regions, and BVH reuse.

#include "scene_builder.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <optional>
#include <thread>

namespace jt::test {
namespace {

// A busy scene: a grid of spheres over a mirror floor under three lights.
Scene busy_scene(int width, int height, int grid = 8) {
    Scene s = scene_with_camera(
        camera_at({0, 4, 12}, {0, 0.5, 0}, {0, 1, 0}, 40.0, double(width) / height), width, height);
    s.settings.recurse_depth = 4;
    s.settings.background = {0.1, 0.1, 0.2};
    s.settings.ambient_light = {0.2, 0.2, 0.2};
    Material floor = matte({0.7, 0.7, 0.7});
    floor.finish.edit().reflection = 0.4;
    s.primitives.push_back(plane({0, 1, 0}, 0.0, floor));
    for (int i = 0; i < grid; ++i)
        for (int j = 0; j < grid; ++j) {
            Material m = matte({0.2 + 0.1 * i, 0.9 - 0.1 * j, 0.5});
            m.finish.edit().specular = {0.5, 0.5, 0.5};
            m.finish.edit().reflection = (i + j) % 3 == 0 ? 0.6 : 0.0;
            Primitive p = (i + j) % 2 ? sphere({i - grid / 2.0, 0.45, j - grid / 2.0}, 0.45, m)
                                      : cylinder(0.3, 0.9, m);
            if ((i + j) % 2 == 0)
                p.transforms = {rotate(TransformKind::zrotate, 10.0 * i),
                                translate({i - grid / 2.0, 0.0, j - grid / 2.0})};
            s.primitives.push_back(p);
        }
    s.lights.push_back({{5, 8, 5}, {0.6, 0.5, 0.4}});
    s.lights.push_back({{-6, 5, 2}, {0.2, 0.3, 0.6}});
    s.lights.push_back({{0, 3, 10}, {0.3, 0.3, 0.3}});
    return s;
}

RenderOptions options_for(const Scene& s, int samples, int threads, bool previews) {
    RenderOptions o = render_options_for(s);
    o.samples = samples;
    o.threads = threads;
    o.previews = previews;
    return o;
}

TEST(RenderJob, ThreadCountNeverChangesTheImage) {
    Scene s = busy_scene(97, 61);
    auto prepared = prepare_scene(s).value();
    for (int samples : {1, 5}) {
        Image8 one = render_image(prepared, options_for(s, samples, 1, false));
        Image8 two = render_image(prepared, options_for(s, samples, 2, false));
        Image8 many = render_image(prepared, options_for(s, samples, 7, false));
        EXPECT_TRUE(one == two) << samples << " samples";
        EXPECT_TRUE(one == many) << samples << " samples";
    }
}

TEST(RenderJob, PreviewsDoNotChangeTheFinalImage) {
    Scene s = busy_scene(70, 50);
    auto prepared = prepare_scene(s).value();
    RenderJob job(prepared, options_for(s, 3, 0, true));
    std::vector<std::string> names;
    while (job.run_pass()) names.push_back(job.progress().pass_name);
    EXPECT_EQ(names, (std::vector<std::string>{"preview 1/4", "preview 1/2", "1 sample",
                                               "2 samples", "3 samples", "3 samples"}))
        << "pass_name reports the pass about to run, then the last one";
    RenderProgress p = job.progress();
    EXPECT_TRUE(p.finished);
    EXPECT_EQ(p.pass_count, 6);
    EXPECT_EQ(p.samples_done, 3);
    EXPECT_DOUBLE_EQ(p.fraction, 1.0);
    EXPECT_GT(p.rays, 70u * 50u * 3u);
    EXPECT_TRUE(job.image() == render_image(prepared, options_for(s, 3, 0, false)));
}

TEST(RenderJob, PreviewPassesFillWholeBlocks) {
    Scene s = busy_scene(61, 43);
    RenderJob job(prepare_scene(s).value(), options_for(s, 1, 0, true));
    for (int block : {8, 4, 2}) {
        ASSERT_TRUE(job.run_pass());
        Image8 image = job.image();
        int distinct_blocks = 0;
        for (int y = 0; y < 43; ++y)
            for (int x = 0; x < 61; ++x) {
                Rgb corner = at(image, x / block * block, y / block * block);
                ASSERT_EQ(at(image, x, y), corner) << "block " << block << " at " << x << "," << y;
                if (x % block == 0 && y % block == 0 && !(corner == Rgb{0, 0, 0}))
                    ++distinct_blocks;
            }
        EXPECT_GT(distinct_blocks, 0);
    }
}

TEST(RenderJob, OneSampleIsThePixelCentre) {
    Scene s = busy_scene(40, 30);
    auto prepared = prepare_scene(s).value();
    Image8 single = render_image(prepared, options_for(s, 1, 0, false));
    RenderJob job(prepared, options_for(s, 4, 0, false));
    ASSERT_TRUE(job.run_pass());  // the 1-sample pass
    EXPECT_EQ(job.progress().samples_done, 1);
    EXPECT_TRUE(job.image() == single);
    job.run();
    EXPECT_FALSE(job.image() == single) << "4 samples smooth the edges";
}

TEST(RenderJob, FetchUpdatesCopiesWhatChanged) {
    Scene s = busy_scene(80, 40);
    RenderJob job(prepare_scene(s).value(), options_for(s, 1, 0, false));
    Image8 display;
    auto first = job.fetch_updates(display);
    ASSERT_TRUE(first);
    EXPECT_EQ(*first, (PixelRect{0, 0, 80, 40}));
    EXPECT_EQ(display.width, 80);
    EXPECT_FALSE(job.fetch_updates(display)) << "nothing rendered since";
    job.run();
    auto changed = job.fetch_updates(display);
    ASSERT_TRUE(changed);
    EXPECT_EQ(*changed, (PixelRect{0, 0, 80, 40}));
    EXPECT_TRUE(display == job.image());
    EXPECT_FALSE(job.fetch_updates(display));
}

TEST(RenderJob, RegionRendersExactlyThosePixels) {
    Scene s = busy_scene(90, 60);
    auto prepared = prepare_scene(s).value();
    Image8 full = render_image(prepared, options_for(s, 2, 0, false));
    RenderOptions o = options_for(s, 2, 0, true);
    o.region = PixelRect{13, 7, 71, 45};
    RenderJob job(prepared, o);
    job.run();
    Image8 part = job.image();
    ASSERT_EQ(part.width, 90);
    for (int y = 0; y < 60; ++y)
        for (int x = 0; x < 90; ++x) {
            bool inside = x >= 13 && x < 71 && y >= 7 && y < 45;
            ASSERT_EQ(at(part, x, y), (inside ? at(full, x, y) : Rgb{0, 0, 0})) << x << "," << y;
        }
}

TEST(RenderJob, TakeImageMovesTheFinalImageOut) {
    Scene s = busy_scene(64, 36);
    auto prepared = prepare_scene(s).value();
    for (const std::optional<PixelRect> region :
         {std::optional<PixelRect>(), std::optional(PixelRect{5, 3, 40, 30})}) {
        RenderOptions o = options_for(s, 1, 0, false);
        o.region = region;
        RenderJob job(prepared, o);
        job.run();
        const Image8 shown = job.image();
        Image8 display;
        const Image8 taken = job.take_image();
        EXPECT_EQ(taken.width, 64);
        EXPECT_EQ(taken.height, 36);
        EXPECT_TRUE(taken == shown) << "the same pixels as a copy";
        EXPECT_TRUE(job.image().rgb.empty()) << "the job keeps none";
        EXPECT_TRUE(job.region_image().rgb.empty());
        EXPECT_FALSE(job.fetch_updates(display));
    }
}

TEST(RenderJob, CancelReturnsPromptly) {
    Scene s = busy_scene(1600, 1200, 20);
    RenderJob job(prepare_scene(s).value(), options_for(s, 64, 0, true));
    std::thread worker([&] { job.run(); });
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    auto start = std::chrono::steady_clock::now();
    job.cancel();
    worker.join();
    double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    // A bound that only a job ignoring the flag would miss: the whole render
    // takes minutes. Typically a few ms; the figure is printed below.
    EXPECT_LT(ms, 2000.0);
    RecordProperty("cancel_ms", std::to_string(ms));
    std::printf("cancel returned after %.2f ms\n", ms);
    RenderProgress p = job.progress();
    EXPECT_TRUE(p.cancelled);
    EXPECT_FALSE(p.finished);
    EXPECT_LT(p.fraction, 1.0);
    EXPECT_FALSE(job.run_pass()) << "a cancelled job stays cancelled";
}

TEST(RenderJob, ReusesGeometryWhenOnlyMaterialsChange) {
    Scene s = busy_scene(60, 40);
    auto first = prepare_scene(s).value();
    Scene recoloured = s;
    recoloured.primitives[3].material.pigment = {1, 0, 0};
    recoloured.lights[0].intensity = {1, 1, 1};
    auto second = prepare_scene(recoloured, first).value();
    auto fresh = prepare_scene(recoloured).value();
    EXPECT_TRUE(render_image(second, options_for(s, 1, 0, false)) ==
                render_image(fresh, options_for(s, 1, 0, false)));
    EXPECT_FALSE(render_image(second, options_for(s, 1, 0, false)) ==
                 render_image(first, options_for(s, 1, 0, false)));
    Scene moved = recoloured;
    moved.primitives[3].transforms.push_back(translate({0, 1, 0}));
    auto third = prepare_scene(moved, second).value();
    EXPECT_FALSE(render_image(third, options_for(s, 1, 0, false)) ==
                 render_image(second, options_for(s, 1, 0, false)));
}

TEST(RenderJob, EmptyImageFinishesAtOnce) {
    Scene s = busy_scene(0, 0);
    RenderJob job(prepare_scene(s).value(), options_for(s, 1, 0, true));
    job.run();
    EXPECT_TRUE(job.progress().finished);
    EXPECT_EQ(job.image().width, 0);
}

}  // namespace
}  // namespace jt::test
