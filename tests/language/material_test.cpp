// The scene model's Material: a pigment of its own and a finish shared
// (scene.hpp, shared.hpp). A material is still a value that copies, compares
// and edits like one; the sharing shows only in its size and its allocations.
#include "jtracer/scene.hpp"
#include "jtracer/schema.hpp"

#include <gtest/gtest.h>

#include <utility>
#include <vector>

namespace jt {
namespace {

TEST(Material, APrimitiveIsAShapeAPigmentAPointerAndItsTransforms) {
    // What a million-sphere scene pays a sphere: 96 bytes, not the 280 of a
    // material held whole.
    EXPECT_EQ(sizeof(Material), sizeof(Colour) + sizeof(void*));
    EXPECT_LE(sizeof(Primitive), 104u);
}

TEST(Material, DefaultMaterialsShareOneFinish) {
    // The parser and the viewer make many: none allocates a finish.
    std::vector<Material> many(3);
    EXPECT_TRUE(many[0].finish.shares_with(many[1].finish));
    Material moved = std::move(many[0]);
    EXPECT_TRUE(moved.finish.shares_with(many[2].finish));
    EXPECT_TRUE(many[0].finish.shares_with(many[2].finish)) << "moved from: the default again";
    many[1] = std::move(moved);
    EXPECT_TRUE(moved.finish.shares_with(many[2].finish));  // NOLINT(bugprone-use-after-move)
}

TEST(Material, ACopySharesTheFinishAndEditingItLeavesTheOriginal) {
    Material a;
    a.finish.edit().reflection = 0.5;
    a.finish.edit().image_map = "wood.png";
    Material b = a;
    EXPECT_TRUE(b.finish.shares_with(a.finish));
    EXPECT_EQ(a, b);

    b.finish.edit().reflection = 0.25;
    EXPECT_FALSE(b.finish.shares_with(a.finish));
    EXPECT_EQ(a.finish->reflection, 0.5);
    EXPECT_EQ(b.finish->reflection, 0.25);
    EXPECT_EQ(b.finish->image_map, "wood.png");
    EXPECT_NE(a, b);

    // A finish no one else sees is edited where it is.
    const void* own = b.finish.address();
    b.finish.edit().ior = 1.5;
    EXPECT_EQ(b.finish.address(), own);
}

TEST(Material, EqualityIsByValueNotBySharing) {
    Material a, b;
    a.finish.edit().diffuse = Colour(0.5);
    b.finish.edit().diffuse = Colour(0.5);
    EXPECT_FALSE(a.finish.shares_with(b.finish));
    EXPECT_EQ(a, b);
    b.finish.edit().checker = Colour(1.0);
    EXPECT_NE(a, b);
    b.finish.edit().checker.reset();
    EXPECT_EQ(a, b);
    b.pigment = Colour(0.1);
    EXPECT_NE(a, b);
    // Default finishes, shared or not, are equal.
    Material c;
    c.finish = Finish{};
    EXPECT_FALSE(c.finish.shares_with(Material{}.finish));
    EXPECT_EQ(c, Material{});
}

TEST(Material, AMovedFromMaterialHoldsTheDefaultFinish) {
    Material a;
    a.finish.edit().specular_k = 8.0;
    Material b = std::move(a);
    EXPECT_EQ(b.finish->specular_k, 8.0);
    EXPECT_EQ(a.finish->specular_k, Finish{}.specular_k);  // NOLINT(bugprone-use-after-move)
}

TEST(Material, TheSchemaReadsThroughTheFinishAndWritesACopy) {
    Material a;
    a.finish.edit().transmission = 0.75;
    const Material original = a;
    const auto* property = find_property<Material>("transmission");
    ASSERT_NE(property, nullptr);
    EXPECT_EQ(value_text(*property, original), "0.75");
    EXPECT_TRUE(original.finish.shares_with(a.finish));
    with_member(*property, a, [](auto& value) {
        if constexpr (std::is_same_v<std::decay_t<decltype(value)>, double>) value = 0.25;
    });
    EXPECT_EQ(original.finish->transmission, 0.75);
    EXPECT_EQ(a.finish->transmission, 0.25);
    EXPECT_FALSE(same_value(*property, a, original));
    copy_value(*property, original, a);
    EXPECT_TRUE(same_value(*property, a, original));
    EXPECT_EQ(a, original);
}

}  // namespace
}  // namespace jt
