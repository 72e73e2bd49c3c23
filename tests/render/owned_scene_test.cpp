// prepare_scene(Scene&&): a scene handed over is not kept; its materials are
// moved into the prepared scene and its primitives freed before the BVH is
// built, and it renders the same bytes as a preparation that copies. A scene
// shared (prepare_scene(std::shared_ptr<const Scene>)) is kept, and read in
// place once a copy would be large.

#include "random_scene.hpp"
#include "render/prepared_scene.hpp"
#include "scene_builder.hpp"

#include <gtest/gtest.h>

#include <cstdint>

namespace jt::test {
namespace {

Image8 render_prepared(const std::shared_ptr<const PreparedScene>& prepared, const Scene& scene) {
    RenderOptions options = render_options_for(scene);
    options.threads = 2;
    return render_image(prepared, options);
}

// Mirrors, glass and plain spheres of distinct colours over a reflective
// floor: every material term the tracer reads, and shadow rays that look past
// transmitting surfaces.
Scene mixed_scene() {
    Scene s = scene_with_camera(camera_at({0, 4, 10}, {0, 0.5, 0}, {0, 1, 0}, 45.0, 1.0), 48, 48);
    s.settings.recurse_depth = 4;
    s.settings.background = {0.1, 0.15, 0.3};
    s.settings.ambient_light = {0.2, 0.2, 0.2};
    Material floor = matte({0.6, 0.6, 0.6});
    floor.finish.edit().reflection = 0.4;
    s.primitives.push_back(plane({0, 1, 0}, 0.0, floor));
    for (int i = 0; i < 9; ++i) {
        Material m = matte({0.1 * i, 0.9 - 0.08 * i, 0.5});
        m.finish.edit().specular = {0.5, 0.5, 0.5};
        m.finish.edit().specular_k = 10.0 + 5.0 * i;
        m.finish.edit().diffuse_k = i % 3 == 0 ? 2.0 : 1.0;
        if (i % 3 == 1) m.finish.edit().reflection = 0.6;
        if (i % 3 == 2) {
            m.finish.edit().transmission = 0.8;
            m.finish.edit().ior = 1.5;
        }
        s.primitives.push_back(sphere({i % 3 * 1.5 - 1.5, 0.5, i / 3 * 1.5 - 2.0}, 0.5, m));
    }
    s.lights.push_back({{4, 8, 6}, {0.8, 0.8, 0.7}});
    s.lights.push_back({{-5, 3, 2}, {0.2, 0.2, 0.4}});
    return s;
}

// Appends more distinct materials than prepare_scene copies for a scene
// shared, on spheres flattened by a zero scale, which the transform rule
// leaves out of the picture.
constexpr int many_materials = 20000;
Scene with_many_materials(Scene s) {
    for (int i = 0; i < many_materials; ++i) {
        Primitive p = sphere({0, 0, 0}, 1.0, matte({double(i) / many_materials, 0.5, 0.5}));
        p.transforms = {scale({0, 1, 1})};
        s.primitives.push_back(p);
    }
    return s;
}

TEST(OwnedScene, AFewMaterialsAreTaken) {
    const auto owned = prepare_scene(mixed_scene()).value();
    EXPECT_FALSE(owned->scene);
    EXPECT_EQ(owned->materials.size(), mixed_scene().primitives.size());
}

// Many distinct materials are moved out of the scene, not copied and not read
// where it holds them: nothing but the prepared scene holds a finish of its
// own afterwards, so no primitive of the scene is left.
TEST(OwnedScene, ManyMaterialsAreTakenAndThePrimitivesFreed) {
    const Scene scene = with_many_materials(mixed_scene());
    const auto copied = prepare_scene(scene).value();
    ASSERT_FALSE(copied->scene);
    ASSERT_FALSE(copied->materials.empty());

    Scene given = scene;
    for (Primitive& p : given.primitives) p.material.finish.edit();  // a finish of its own
    const auto owned = prepare_scene(std::move(given)).value();
    EXPECT_FALSE(owned->scene);
    ASSERT_EQ(owned->materials.size(), scene.primitives.size());
    EXPECT_TRUE(owned->material_of.empty()) << "each primitive's entry at its index";
    for (std::uint32_t i = 0; i < scene.primitives.size(); ++i) {
        const Material& m = primitive_material(*owned, i);
        ASSERT_EQ(m, scene.primitives[i].material) << "primitive " << i;
        ASSERT_TRUE(m.finish.unique()) << "primitive " << i;
    }
    EXPECT_TRUE(owned->has_transmission);
    EXPECT_EQ(owned->materials_gathered, scene.primitives.size());
    EXPECT_EQ(render_prepared(owned, scene), render_prepared(copied, scene));
}

TEST(OwnedScene, RandomScenesRenderTheSameBytes) {
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
        for (const Scene& scene :
             {random_scene(seed).scene, with_many_materials(random_scene(seed).scene)}) {
            const auto owned = prepare_scene(Scene(scene)).value();
            ASSERT_FALSE(owned->scene) << "seed " << seed;
            EXPECT_EQ(render_prepared(owned, scene),
                      render_prepared(prepare_scene(scene).value(), scene))
                << "seed " << seed;
        }
    }
}

// Runs of equal materials share an entry, also when the first run comes
// after many primitives of their own; and an edit patches either form.
TEST(OwnedScene, RunsAfterDistinctMaterialsShareEntries) {
    Scene scene = with_many_materials(mixed_scene());
    for (int i = 0; i < 3; ++i) scene.primitives.push_back(scene.primitives[2]);
    const auto owned = prepare_scene(Scene(scene)).value();
    EXPECT_EQ(owned->materials.size(), scene.primitives.size() - 2) << "the last three alike";
    ASSERT_EQ(owned->material_of.size(), scene.primitives.size());
    for (std::uint32_t i = 0; i < scene.primitives.size(); ++i)
        ASSERT_EQ(primitive_material(*owned, i), scene.primitives[i].material) << i;
    EXPECT_EQ(render_prepared(owned, scene), render_prepared(prepare_scene(scene).value(), scene));

    for (const Scene& before : {scene, with_many_materials(mixed_scene())}) {
        const auto previous = prepare_scene(Scene(before)).value();
        Scene after = before;
        after.primitives.back().material.pigment = {0.95, 0.1, 0.1};
        after.primitives[4].material.pigment = {0.1, 0.95, 0.1};
        const auto edited = prepare_scene_edit(before, after, previous).value();
        EXPECT_EQ(edited->materials_gathered, 2u);
        EXPECT_EQ(render_prepared(edited, after),
                  render_prepared(prepare_scene(after).value(), after));
    }
}

// A pattern reads pictures and pattern spaces that are parallel to a gathered
// list, so such a scene is gathered even when handed over.
TEST(OwnedScene, APatternGathersTheMaterials) {
    Scene scene = with_many_materials(mixed_scene());
    scene.primitives[3].material.finish.edit().checker = Colour(0.1, 0.1, 0.1);
    scene.primitives[3].material.finish.edit().checker_size = 0.2;
    const auto owned = prepare_scene(Scene(scene)).value();
    EXPECT_FALSE(owned->scene);
    EXPECT_FALSE(owned->materials.empty());
    EXPECT_FALSE(owned->pattern_space.empty());
    EXPECT_EQ(render_prepared(owned, scene), render_prepared(prepare_scene(scene).value(), scene));
}

// A handed-over scene leaves a list of materials, so an edit after it patches
// that list (its geometry reused): the same bytes as a fresh preparation.
TEST(OwnedScene, AnEditAfterItIsPatched) {
    const Scene before = with_many_materials(mixed_scene());
    const auto previous = prepare_scene(Scene(before)).value();
    ASSERT_FALSE(previous->scene);
    Scene after = before;
    after.primitives[4].material.pigment = {0.95, 0.1, 0.1};
    const auto edited = prepare_scene_edit(before, after, previous).value();
    EXPECT_EQ(edited->materials_gathered, 1u);
    EXPECT_EQ(edited->geometry, previous->geometry);
    const Image8 image = render_prepared(edited, after);
    EXPECT_EQ(image, render_prepared(prepare_scene(after).value(), after));
    EXPECT_NE(image, render_prepared(previous, before));
}

// A scene shared with its caller is kept and read in place, and a material
// edit of it is patched by holding the edited scene: nothing
// gathered, the geometry kept, the bytes of a fresh preparation.
TEST(OwnedScene, ASharedSceneIsReadInPlaceAndItsEditPatched) {
    const auto before = std::make_shared<const Scene>(with_many_materials(mixed_scene()));
    const auto previous = prepare_scene(before).value();
    ASSERT_TRUE(previous->scene);
    EXPECT_EQ(previous->scene, before) << "held, not copied";
    EXPECT_TRUE(previous->materials.empty());
    EXPECT_EQ(render_prepared(previous, *before),
              render_prepared(prepare_scene(*before).value(), *before));

    Scene after = *before;
    after.primitives[4].material.pigment = {0.95, 0.1, 0.1};
    after.primitives[3].material.finish.edit().transmission = 0.0;
    after.primitives[6].material.finish.edit().transmission = 0.0;
    after.primitives[9].material.finish.edit().transmission = 0.0;
    const auto shared_after = std::make_shared<const Scene>(after);
    const auto edited = prepare_scene_edit(*before, shared_after, previous).value();
    EXPECT_EQ(edited->materials_gathered, 4u);
    EXPECT_EQ(edited->geometry, previous->geometry);
    EXPECT_EQ(edited->scene, shared_after);
    EXPECT_FALSE(edited->has_transmission) << "worked out from the edited scene";
    const Image8 image = render_prepared(edited, after);
    EXPECT_EQ(image, render_prepared(prepare_scene(after).value(), after));
    EXPECT_NE(image, render_prepared(previous, *before));

    // With no transmission left, the edit that brings one back is found by
    // looking at the changed objects alone.
    Scene glass = after;
    glass.primitives[6].material.finish.edit().transmission = 0.8;
    const auto shared_glass = std::make_shared<const Scene>(glass);
    const auto glazed = prepare_scene_edit(after, shared_glass, edited).value();
    EXPECT_EQ(glazed->materials_gathered, 1u);
    EXPECT_TRUE(glazed->has_transmission);
    EXPECT_EQ(render_prepared(glazed, glass), render_prepared(prepare_scene(glass).value(), glass));

    // A pattern needs pattern spaces, which a scene read in place has none of.
    Scene checkered = after;
    checkered.primitives[4].material.finish.edit().checker = Colour(0.1, 0.1, 0.1);
    const auto shared_checkered = std::make_shared<const Scene>(checkered);
    const auto gathered = prepare_scene_edit(after, shared_checkered, edited).value();
    EXPECT_EQ(gathered->materials_gathered, checkered.primitives.size());
    EXPECT_EQ(render_prepared(gathered, checkered),
              render_prepared(prepare_scene(checkered).value(), checkered));
}

}  // namespace
}  // namespace jt::test
