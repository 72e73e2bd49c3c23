// The blocks an editor adds sit in front of the active camera, at a size that
// follows the view, with a material that is not black.

#include "jtracer/new_block.hpp"
#include "jtracer/value_text.hpp"

#include "edit_fixture.hpp"
#include "edit_test_support.hpp"

#include <glm/geometric.hpp>

#include <gtest/gtest.h>

namespace jt::test {
namespace {

Scene looking(Vec3 from, Vec3 to, double fov = 45) {
    Scene scene;
    Camera first, second;
    first.name = std::string("a");
    second.name = std::string("b");
    second.position = from;
    second.look_at = to;
    second.fov = fov;
    scene.cameras = {first, second};
    scene.settings.active_camera = second.name;
    return scene;
}

TEST(NewBlock, ASphereHalfwayAlongTheActiveCamerasView) {
    const Scene scene = looking({0, 2, 10}, {0, 2, 0});
    const Sphere sphere = std::get<Sphere>(new_primitive(ShapeKind::sphere, scene).shape);
    EXPECT_EQ(sphere.center, Vec3(0, 2, 5));
    // A fifth of the half-height of the view 5 units away, rounded.
    EXPECT_NEAR(sphere.radius, 5 * std::tan(22.5 * 3.14159265358979 / 180) / 5, 0.01);
    EXPECT_EQ(number_text(sphere.radius), "0.41");  // to 0.01: three digits of the view's scale

    // A view a hundred times bigger gives a sphere a hundred times bigger.
    const Sphere big = std::get<Sphere>(
        new_primitive(ShapeKind::sphere, looking({0, 200, 1000}, {0, 200, 0})).shape);
    EXPECT_EQ(big.center, Vec3(0, 200, 500));
    EXPECT_EQ(big.radius, 41.0);
}

TEST(NewBlock, APlaneBelowTheViewAndACylinderStandingInIt) {
    const Scene scene = looking({0, 2, 10}, {0, 2, 0});
    const Plane plane = std::get<Plane>(new_primitive(ShapeKind::plane, scene).shape);
    EXPECT_EQ(plane.normal, Vec3(0, 1, 0));
    EXPECT_LT(plane.distance, 2.0);  // below the camera and its view's centre
    EXPECT_GT(plane.distance, 0.0);  // but within the view's half-height there

    const Primitive cylinder = new_primitive(ShapeKind::cylinder, scene);
    const Cylinder& c = std::get<Cylinder>(cylinder.shape);
    ASSERT_EQ(cylinder.transforms.size(), 1u);
    // Centred on the point halfway along the view.
    EXPECT_NEAR(cylinder.transforms[0].vector.y + c.height / 2, 2.0, 1e-9);
    EXPECT_EQ(cylinder.transforms[0].vector.z, 5.0);
}

TEST(NewBlock, MaterialLightAndCamera) {
    const Material m = new_material();
    EXPECT_GT(m.pigment.x * m.diffuse.x, 0.5);  // lit, it shows
    const Scene scene = looking({0, 2, 10}, {0, 2, 0});
    const PointLight light = new_light(scene);
    EXPECT_GT(light.position.y, 2.0);  // above the camera
    EXPECT_EQ(light.position.z, 10.0);
    EXPECT_EQ(light.intensity, Colour(0.7));
    const Camera camera = new_camera(scene);
    EXPECT_EQ(camera.name, "b 2");
    EXPECT_EQ(camera.position, scene.cameras[1].position);
    EXPECT_EQ(new_camera(Scene{}).name, "camera");
}

TEST(NewBlock, WithoutAUsableCameraStillSensible) {
    // look_at on the position: the default view direction.
    const Sphere s =
        std::get<Sphere>(new_primitive(ShapeKind::sphere, looking({1, 1, 1}, {1, 1, 1})).shape);
    EXPECT_EQ(s.center, Vec3(1, 1, -1.5));
    EXPECT_GT(s.radius, 0.0);
}

}  // namespace
}  // namespace jt::test
