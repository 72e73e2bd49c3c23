// The viewer's model renders with no GL context: the display it keeps is the
// core's image, and the rectangles it reports as changed are where it changed.

#include "jtracer/render_job.hpp"
#include "model/app_actions.hpp"
#include "viewer/model/model_loop.hpp"
#include "viewer/viewer_test_files.hpp"

#include <gtest/gtest.h>

namespace jt::view {
namespace {

using namespace jt::test;

Image8 core_render(const Scene& scene) {
    RenderOptions options = render_options_for(scene);
    options.previews = false;
    RenderJob job(prepare_scene(scene).value(), options);
    job.run();
    return job.image();
}

bool inside(const PixelRect& r, int x, int y) {
    return x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1;
}

TEST(ModelRender, TheDisplayIsTheCoresImageAndEveryChangeIsReported) {
    AppState state(test_config());
    open_scene(state, kScene);
    ASSERT_TRUE(state.doc.loaded) << state.message;
    // What a texture fed only the reported rectangles would hold.
    Image8 mirror;
    int reports = 0;
    const auto frame = [&] {
        model_frame(state);
        const std::optional<PixelRect> changed = take_display_changes(state.render);
        if (!changed) return;
        ++reports;
        if (mirror.width != state.render.display.width ||
            mirror.height != state.render.display.height)
            mirror = Image8(state.render.display.width, state.render.display.height);
        for (int y = 0; y < mirror.height; ++y)
            for (int x = 0; x < mirror.width; ++x)
                if (inside(*changed, x, y))
                    std::copy_n(state.render.display.pixel(x, y), 3, mirror.pixel(x, y));
                else
                    EXPECT_TRUE(std::equal(mirror.pixel(x, y), mirror.pixel(x, y) + 3,
                                           state.render.display.pixel(x, y)))
                        << "pixel " << x << "," << y << " changed outside the reported rectangle";
    };
    ASSERT_TRUE(run_frames_until_complete(state, frame, kTimeout, 2));
    EXPECT_GE(reports, 1);
    EXPECT_EQ(state.render.display, core_render(state.doc.scene));
    EXPECT_EQ(mirror, state.render.display);
    EXPECT_FALSE(take_display_changes(state.render)) << "taken: nothing new until the next pass";

    // An edit renders again; the changes since are reported again.
    edit_scene(state, [](Scene& s) { s.primitives[1].material.pigment = Colour(0.1, 0.8, 0.2); });
    reports = 0;
    ASSERT_TRUE(run_frames_until_complete(state, frame, kTimeout, 2));
    EXPECT_GE(reports, 1);
    EXPECT_EQ(state.render.display, core_render(state.doc.scene));
    EXPECT_EQ(mirror, state.render.display);
}

}  // namespace
}  // namespace jt::view
