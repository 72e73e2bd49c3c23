// prepare_scene_edit: a material edit patches the previous prepared scene
// instead of preparing the whole scene again, and renders the same bytes as a
// fresh preparation.

#include "render/prepared_scene.hpp"
#include "scene_builder.hpp"

#include <gtest/gtest.h>

namespace jt::test {
namespace {

// Rows of spheres over a floor; each row shares one material, so that the
// prepared scene merges it into one entry (the case a patch must split).
Scene rows_scene(int rows = 6, int columns = 8) {
    Scene s = scene_with_camera(camera_at({0, 5, 12}, {0, 0.5, 0}, {0, 1, 0}, 45.0, 1.0), 64, 64);
    s.settings.recurse_depth = 3;
    s.settings.background = {0.1, 0.1, 0.2};
    s.settings.ambient_light = {0.2, 0.2, 0.2};
    Material floor = matte({0.7, 0.7, 0.7});
    floor.finish.edit().reflection = 0.3;
    s.primitives.push_back(plane({0, 1, 0}, 0.0, floor));
    for (int r = 0; r < rows; ++r) {
        Material m = matte({0.2 + 0.12 * r, 0.8 - 0.1 * r, 0.5});
        m.finish.edit().specular = {0.4, 0.4, 0.4};
        for (int c = 0; c < columns; ++c)
            s.primitives.push_back(sphere({c - columns / 2.0 + 0.5, 0.4, r - rows / 2.0}, 0.4, m));
    }
    s.lights.push_back({{5, 8, 5}, {0.7, 0.6, 0.5}});
    s.lights.push_back({{-6, 5, 2}, {0.2, 0.3, 0.6}});
    return s;
}

Image8 render(const std::shared_ptr<const PreparedScene>& prepared, const Scene& scene) {
    RenderOptions options = render_options_for(scene);
    options.threads = 2;
    return render_image(prepared, options);
}

struct Patched {
    std::shared_ptr<const PreparedScene> scene;
    Image8 image;
};

// Edits `before` with `change`, patches `previous`, and checks the image
// against a fresh preparation of the edited scene.
Patched edit_and_compare(const Scene& before, const std::shared_ptr<const PreparedScene>& previous,
                         Scene& after) {
    auto patched = prepare_scene_edit(before, after, previous);
    EXPECT_TRUE(patched);
    if (!patched) return {};
    Image8 image = render(*patched, after);
    EXPECT_EQ(image, render(prepare_scene(after).value(), after));
    return {*patched, std::move(image)};
}

TEST(PrepareEdit, RecolouringOneObjectPatchesOnlyItsMaterial) {
    const Scene before = rows_scene();
    const auto previous = prepare_scene(before).value();
    ASSERT_EQ(previous->materials_gathered, before.primitives.size());
    const Image8 old_image = render(previous, before);

    // The middle of a row: its entry is shared, so the patch must split it off.
    Scene after = before;
    after.primitives[12].material.pigment = {0.95, 0.1, 0.1};
    const Patched patched = edit_and_compare(before, previous, after);
    ASSERT_TRUE(patched.scene);
    EXPECT_NE(patched.image, old_image);  // the edit shows
    EXPECT_EQ(patched.scene->materials_gathered, 1u);
    EXPECT_EQ(patched.scene->geometry, previous->geometry);
    EXPECT_EQ(patched.scene->light_tables, previous->light_tables);

    // The same object again: it is alone in its entry now, which is reused.
    Scene again = after;
    again.primitives[12].material.pigment = {0.1, 0.95, 0.1};
    const Patched second = edit_and_compare(after, patched.scene, again);
    ASSERT_TRUE(second.scene);
    EXPECT_EQ(second.scene->materials_gathered, 1u);
    EXPECT_EQ(second.scene->materials.size(), patched.scene->materials.size());
    EXPECT_EQ(second.scene->geometry, previous->geometry);
}

TEST(PrepareEdit, ManyMaterialsLightsAndSettingsAreStillAPatch) {
    const Scene before = rows_scene();
    const auto previous = prepare_scene(before).value();
    Scene after = before;
    after.primitives[1].material.pigment = {0.1, 0.1, 0.9};          // first of a row
    after.primitives[8].material.pigment = {0.9, 0.9, 0.1};          // last of a row
    after.primitives[20].material.finish.edit().transmission = 0.7;  // shadows look past it now
    after.primitives[20].material.finish.edit().ior = 1.4;
    after.primitives[0].material.finish.edit().reflection = 0.0;  // the floor
    after.lights[1].position = {-4, 6, 3};
    after.settings.background = {0.3, 0.1, 0.1};
    const Patched patched = edit_and_compare(before, previous, after);
    ASSERT_TRUE(patched.scene);
    EXPECT_EQ(patched.scene->materials_gathered, 4u);
    EXPECT_EQ(patched.scene->geometry, previous->geometry);
    EXPECT_TRUE(patched.scene->has_transmission);
    EXPECT_NE(patched.image, render(previous, before));

    // Taking the transmission away again clears it.
    Scene back = after;
    back.primitives[20].material.finish.edit().transmission = 0.0;
    const Patched undone = edit_and_compare(after, patched.scene, back);
    ASSERT_TRUE(undone.scene);
    EXPECT_FALSE(undone.scene->has_transmission);
    EXPECT_EQ(undone.scene->materials_gathered, 1u);
}

TEST(PrepareEdit, AnythingButMaterialsPreparesTheWholeScene) {
    const Scene before = rows_scene();
    const auto previous = prepare_scene(before).value();

    Scene moved = before;
    moved.primitives[5].transforms = {translate({0, 1, 0})};
    const Patched m = edit_and_compare(before, previous, moved);
    ASSERT_TRUE(m.scene);
    EXPECT_EQ(m.scene->materials_gathered, moved.primitives.size());
    EXPECT_NE(m.scene->geometry, previous->geometry);

    Scene added = before;
    added.primitives.push_back(sphere({0, 2, 0}, 0.5, matte({1, 1, 1})));
    const Patched a = edit_and_compare(before, previous, added);
    ASSERT_TRUE(a.scene);
    EXPECT_EQ(a.scene->materials_gathered, added.primitives.size());

    // A first pattern needs each primitive's pattern space.
    Scene checkered = before;
    checkered.primitives[3].material.finish.edit().checker = Colour(0.0);
    const Patched c = edit_and_compare(before, previous, checkered);
    ASSERT_TRUE(c.scene);
    EXPECT_EQ(c.scene->materials_gathered, checkered.primitives.size());
    EXPECT_EQ(c.scene->geometry, previous->geometry);  // prepare_scene still reuses the BVH

    // Once there are pattern spaces, patterns are patched too.
    Scene second = checkered;
    second.primitives[30].material.finish.edit().checker = Colour(0.2, 0.2, 0.9);
    const Patched s = edit_and_compare(checkered, c.scene, second);
    ASSERT_TRUE(s.scene);
    EXPECT_EQ(s.scene->materials_gathered, 1u);
}

TEST(PrepareEdit, WithoutAPreviousSceneItPreparesTheWholeScene) {
    const Scene scene = rows_scene(2, 2);
    auto prepared = prepare_scene_edit(scene, scene, nullptr);
    ASSERT_TRUE(prepared);
    EXPECT_EQ((*prepared)->materials_gathered, scene.primitives.size());
}

}  // namespace
}  // namespace jt::test
