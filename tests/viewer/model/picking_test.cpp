// Picking in the model (no GL): a click selects what the core's pick says the
// pixel shows, a light's marker wins near it, the background clears, and a
// selection that no longer names anything reads as none.

#include "model/picking.hpp"
#include "model/app_actions.hpp"
#include "model/pixel_inspector.hpp"
#include "viewer/model/model_loop.hpp"
#include "viewer/viewer_test_files.hpp"

#include <gtest/gtest.h>

namespace jt::view {
namespace {

using namespace jt::test;
using Kind = Selection::Kind;

class Picking : public ::testing::Test {
  protected:
    void SetUp() override {
        open_scene(state, kScene);
        ASSERT_TRUE(model.run_until_complete(state));
    }
    ModelLoop model;
    AppState state{test_config()};
};

TEST_F(Picking, AClickSelectsWhatTheCoresPickSaysThePixelShows) {
    const std::shared_ptr<const PreparedFrame> frame = shown_frame(state);
    ASSERT_TRUE(frame);
    int on_sphere = 0, on_plane = 0, on_background = 0;
    for (int y = 0; y < state.render.display.height; ++y)
        for (int x = 0; x < state.render.display.width; ++x) {
            select_at(state, x + 0.5, y + 0.5, 0.0);
            const std::optional<PickedPrimitive> pick = pick_primitive(*frame, x, y);
            if (!pick) {
                EXPECT_EQ(state.view.selection.kind, Kind::none) << x << "," << y;
                ++on_background;
                continue;
            }
            EXPECT_EQ(state.view.selection, (Selection{Kind::primitive, pick->primitive}));
            EXPECT_TRUE(state.view.reveal_selection);
            (pick->primitive == 0 ? on_plane : on_sphere) += 1;
        }
    EXPECT_GT(on_sphere, 0);
    EXPECT_GT(on_plane, 0);
    EXPECT_GT(on_background, 0);
}

TEST_F(Picking, ALightsMarkerIsSelectedWithinItsRadius) {
    const std::vector<LightMarker> markers = light_markers(state);
    ASSERT_EQ(markers.size(), 1u);
    const ImagePoint at = markers[0].at;
    select_at(state, at.x + 1.5, at.y, 2.0);
    EXPECT_EQ(state.view.selection, (Selection{Kind::light, 0}));
    select_at(state, at.x + 3.0, at.y, 2.0);
    EXPECT_NE(state.view.selection.kind, Kind::light) << "beyond the radius";
}

TEST_F(Picking, ASelectionOfSomethingDeletedReadsAsNone) {
    select(state.view, {Kind::primitive, 1});
    EXPECT_EQ(current_selection(state.view, state.doc.scene), (Selection{Kind::primitive, 1}));
    edit_scene(state, [](Scene& s) { s.primitives.pop_back(); });
    EXPECT_EQ(current_selection(state.view, state.doc.scene).kind, Kind::none);
    EXPECT_FALSE(shown_frame(state)) << "the image still shows the old objects: no picking";
    ASSERT_TRUE(model.run_until_complete(state));
    EXPECT_TRUE(shown_frame(state));
}

}  // namespace
}  // namespace jt::view

namespace jt::view {
namespace {

// The inspector reads the display's own bytes, counts rows from the top as
// --region does, and names what the pick names.
TEST_F(Picking, TheInspectorGivesThePixelsBytesAndWhatItShows) {
    const std::shared_ptr<const PreparedFrame> frame = shown_frame(state);
    ASSERT_TRUE(frame);
    const Image8& image = state.render.display;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const std::optional<PixelReport> r = inspect_pixel(state, x, y);
            ASSERT_TRUE(r);
            EXPECT_EQ(r->x, x);
            EXPECT_EQ(r->y, image.height - 1 - y) << "from the top, as --region counts";
            EXPECT_TRUE(std::equal(r->rgb.begin(), r->rgb.end(), image.pixel(x, y)));
            const std::optional<PickedPrimitive> pick = pick_primitive(*frame, x, y);
            ASSERT_EQ(r->hit.has_value(), pick.has_value());
            if (pick) {
                EXPECT_EQ(r->hit->primitive, pick->primitive);
                EXPECT_EQ(r->hit->distance, pick->distance);
            }
        }
    EXPECT_FALSE(inspect_pixel(state, -1, 0));
    EXPECT_FALSE(inspect_pixel(state, image.width, 0));
    PixelReport r{3, 4, {230, 51, 0}, PickedPrimitive{1, 5.25}};
    EXPECT_EQ(describe(r, state.doc.scene),
              "x 3, y 4   RGB 230 51 0 = 0.902 0.200 0.000\nsphere 2 at distance 5.25");
    r.hit.reset();
    EXPECT_EQ(describe(r, state.doc.scene),
              "x 3, y 4   RGB 230 51 0 = 0.902 0.200 0.000\nbackground");
}

// Until the current render's first pass shows, the display
// holds the render before (another view, perhaps): the inspector names no
// hit of the current view over it.
TEST_F(Picking, TheInspectorDescribesNoHitOverAPixelOfTheRenderBefore) {
    ASSERT_TRUE(inspect_pixel(state, 32, 30)->hit) << "the sphere, in the finished render";
    state.render.display_complete = false;  // as just after a new render started
    state.render.passes_shown = 0;
    const std::optional<PixelReport> r = inspect_pixel(state, 32, 30);
    ASSERT_TRUE(r);
    EXPECT_TRUE(r->earlier_render);
    EXPECT_FALSE(r->hit);
    EXPECT_NE(describe(*r, state.doc.scene).find("rendering"), std::string::npos);
}

}  // namespace
}  // namespace jt::view
