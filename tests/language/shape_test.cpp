// The scene model's Shape: triangles and meshes are boxed (scene.hpp), and
// a Shape is still a value that copies, compares and edits like one.
#include "jtracer/scene.hpp"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

namespace jt {
namespace {

TEST(Shape, IsNoLargerThanASphereAndItsTag) {
    // What a million-sphere scene pays a sphere; a triangle inline would make it 152.
    EXPECT_LE(sizeof(Shape), sizeof(Sphere) + sizeof(void*));
}

TEST(Shape, ACopyOfABoxedShapeIsItsOwnValue) {
    Primitive a;
    a.shape = Triangle{{1, 2, 3}, {4, 5, 6}, {7, 8, 9}};
    Primitive b = a;
    EXPECT_EQ(a, b);
    EXPECT_NE(shape_if<Triangle>(&a.shape), shape_if<Triangle>(&b.shape));

    shape_as<Triangle>(b.shape).c = {0, 0, 1};
    EXPECT_NE(a, b);
    EXPECT_EQ(shape_as<Triangle>(a.shape).c, Vec3(7, 8, 9));

    b = a;
    EXPECT_EQ(a, b);
    Mesh mesh;
    mesh.file = "m.obj";
    b.shape = mesh;
    EXPECT_TRUE(shape_is<Mesh>(b.shape));
    EXPECT_EQ(shape_as<Mesh>(b.shape).file, "m.obj");
    EXPECT_FALSE(shape_is<Triangle>(b.shape));
    EXPECT_EQ(shape_if<Triangle>(&b.shape), nullptr);
    EXPECT_EQ(shape_if<Sphere>(&b.shape), nullptr);
}

TEST(Shape, MovingPrimitivesKeepsTheirShapesInPlace) {
    std::vector<Primitive> primitives(1);
    primitives[0].shape = Triangle{};
    const Triangle* held = shape_if<Triangle>(&primitives[0].shape);
    // Growing moves the boxes rather than copying them: the triangle stays where it was.
    for (int i = 0; i < 100; ++i) primitives.emplace_back();
    EXPECT_EQ(shape_if<Triangle>(&primitives[0].shape), held);
    std::vector<Primitive> moved = std::move(primitives);
    EXPECT_EQ(shape_if<Triangle>(&moved[0].shape), held);
}

TEST(Shape, AVisitSeesTheShapeNotItsBox) {
    std::vector<std::string> seen;
    const auto name = [&](const auto& shape) {
        using T = std::decay_t<decltype(shape)>;
        if constexpr (std::is_same_v<T, Triangle>) seen.push_back("triangle");
        if constexpr (std::is_same_v<T, Mesh>) seen.push_back("mesh " + shape.file);
        if constexpr (std::is_same_v<T, Sphere>) seen.push_back("sphere");
    };
    Mesh mesh;
    mesh.file = "a.ply";
    for (const Shape& shape : {Shape(Sphere{}), Shape(Triangle{}), Shape(mesh)})
        visit_shape(name, shape);
    EXPECT_EQ(seen, (std::vector<std::string>{"sphere", "triangle", "mesh a.ply"}));

    Shape editable = Triangle{};
    visit_shape(
        [](auto& shape) {
            if constexpr (std::is_same_v<std::decay_t<decltype(shape)>, Triangle>)
                shape.a = {5, 5, 5};
        },
        editable);
    EXPECT_EQ(shape_as<Triangle>(editable).a, Vec3(5, 5, 5));
}

}  // namespace
}  // namespace jt
