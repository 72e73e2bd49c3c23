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
    const Sphere sphere = shape_as<Sphere>(new_primitive(ShapeKind::sphere, scene).shape);
    EXPECT_EQ(sphere.center, Vec3(0, 2, 5));
    // A fifth of the half-height of the view 5 units away, rounded.
    EXPECT_NEAR(sphere.radius, 5 * std::tan(22.5 * 3.14159265358979 / 180) / 5, 0.01);
    EXPECT_EQ(number_text(sphere.radius), "0.41");  // to 0.01: three digits of the view's scale

    // A view a hundred times bigger gives a sphere a hundred times bigger.
    const Sphere big = shape_as<Sphere>(
        new_primitive(ShapeKind::sphere, looking({0, 200, 1000}, {0, 200, 0})).shape);
    EXPECT_EQ(big.center, Vec3(0, 200, 500));
    EXPECT_EQ(big.radius, 41.0);
}

TEST(NewBlock, APlaneBelowTheViewAndACylinderStandingInIt) {
    const Scene scene = looking({0, 2, 10}, {0, 2, 0});
    const Plane plane = shape_as<Plane>(new_primitive(ShapeKind::plane, scene).shape);
    EXPECT_EQ(plane.normal, Vec3(0, 1, 0));
    EXPECT_LT(plane.distance, 2.0);  // below the camera and its view's centre
    EXPECT_GT(plane.distance, 0.0);  // but within the view's half-height there

    // A camera that looks down still gets a level floor, below the point.
    const Plane floor =
        shape_as<Plane>(new_primitive(ShapeKind::plane, looking({0, 2, 8}, {0, 1, 0})).shape);
    EXPECT_EQ(floor.normal, Vec3(0, 1, 0));
    EXPECT_LT(floor.distance, 1.5);

    const Primitive cylinder = new_primitive(ShapeKind::cylinder, scene);
    const Cylinder& c = shape_as<Cylinder>(cylinder.shape);
    ASSERT_EQ(cylinder.transforms.size(), 1u);
    // Centred on the point halfway along the view.
    EXPECT_NEAR(cylinder.transforms[0].vector.y + c.height / 2, 2.0, 1e-9);
    EXPECT_EQ(cylinder.transforms[0].vector.z, 5.0);
}

// A plane added to new_scene() goes at the view's floor, under the objects,
// not through the middle of the view.
TEST(NewBlock, APlaneGoesAtTheViewsFloorUnderTheObjects) {
    Scene scene = new_scene();
    EXPECT_EQ(scene.cameras[0].name, "main");
    const Plane floor = shape_as<Plane>(new_primitive(ShapeKind::plane, scene).shape);
    EXPECT_EQ(floor.normal, Vec3(0, 1, 0));
    EXPECT_EQ(floor.distance, 0.0) << "the camera looks at a point a unit above the origin";
    Primitive low = new_primitive(ShapeKind::sphere, scene);
    shape_as<Sphere>(low.shape) = Sphere{Vec3(1, -2, 0), 0.5};
    scene.primitives.push_back(low);
    Primitive lifted = new_primitive(ShapeKind::cylinder, scene);
    lifted.transforms = {{TransformKind::translate, Vec3(0, -3, 0), 0.0}};
    const Plane under = shape_as<Plane>(new_primitive(ShapeKind::plane, scene).shape);
    EXPECT_EQ(under.distance, -2.5) << "under the sphere";
    scene.primitives.push_back(lifted);
    EXPECT_EQ(shape_as<Plane>(new_primitive(ShapeKind::plane, scene).shape).distance, -3.0)
        << "under the translated cylinder";
}

TEST(NewBlock, ATriangleStandingInTheViewFacingTheCamera) {
    const Scene scene = looking({0, 2, 10}, {0, 2, 0});
    const Primitive added = new_primitive(ShapeKind::triangle, scene);
    const Triangle& t = shape_as<Triangle>(added.shape);
    // Counter-clockwise seen from the camera: the front faces it.
    EXPECT_GT(glm::dot(glm::cross(t.b - t.a, t.c - t.a), Vec3(0, 0, 1)), 0.0);
    for (const Vec3& corner : {t.a, t.b, t.c}) EXPECT_EQ(corner.z, 5.0);
    EXPECT_EQ(t.a.y, t.b.y);
    EXPECT_LT(t.a.y, 2.0);
    EXPECT_GT(t.c.y, 2.0);
    EXPECT_EQ(t.c.x, 0.0);
    // As wide as a new sphere.
    const Sphere sphere = shape_as<Sphere>(new_primitive(ShapeKind::sphere, scene).shape);
    EXPECT_NEAR(t.b.x - t.a.x, 2 * sphere.radius, 0.01);
    EXPECT_EQ(t.uv_b, Triangle{}.uv_b);
    EXPECT_TRUE(added.transforms.empty());
}

TEST(NewBlock, AMeshScaledToASpheresSizeAndCentredWhereItGoes) {
    const Scene scene = looking({0, 2, 10}, {0, 2, 0});
    Model model;  // spans x in [-1, 39], y in [0, 20]: 40 across
    model.positions = {{-1, 0, 0}, {39, 0, 0}, {19, 20, 0}, {1000, 1000, 1000}};
    model.triangles = {{0, 1, 2}};  // the fourth position is no triangle's corner
    const Primitive mesh = new_mesh(scene, "models/m.obj", model);
    EXPECT_EQ(shape_as<Mesh>(mesh.shape).file, "models/m.obj");
    EXPECT_EQ(shape_as<Mesh>(mesh.shape).shading, "smooth");
    EXPECT_EQ(mesh.material, new_material());
    ASSERT_EQ(mesh.transforms.size(), 2u);
    ASSERT_EQ(mesh.transforms[0].kind, TransformKind::scale);
    ASSERT_EQ(mesh.transforms[1].kind, TransformKind::translate);
    const double s = mesh.transforms[0].vector.x;
    EXPECT_EQ(mesh.transforms[0].vector, Vec3(s));
    const Sphere sphere = shape_as<Sphere>(new_primitive(ShapeKind::sphere, scene).shape);
    EXPECT_NEAR(40 * s, 2 * sphere.radius, 0.01);
    // The box's centre (19, 10, 0), scaled then moved, lands halfway along the view.
    const Vec3 centre = Vec3(19, 10, 0) * s + mesh.transforms[1].vector;
    EXPECT_NEAR(centre.x, 0.0, 0.01);
    EXPECT_NEAR(centre.y, 2.0, 0.01);
    EXPECT_NEAR(centre.z, 5.0, 0.01);
    EXPECT_EQ(number_text(s), "0.0207");  // three significant digits
}

TEST(NewBlock, MaterialLightAndCamera) {
    const Material m = new_material();
    EXPECT_GT(m.pigment.x * m.finish->diffuse.x, 0.5);  // lit, it shows
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
        shape_as<Sphere>(new_primitive(ShapeKind::sphere, looking({1, 1, 1}, {1, 1, 1})).shape);
    EXPECT_EQ(s.center, Vec3(1, 1, -1.5));
    EXPECT_GT(s.radius, 0.0);
}

}  // namespace
}  // namespace jt::test
