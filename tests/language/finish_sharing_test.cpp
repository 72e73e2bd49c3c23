// The parser gives primitives of equal finishes one finish between them
// (finish_table.hpp): a file of a million spheres of one finish holds it once.
#include "jtracer/finish_table.hpp"
#include "jtracer/parser.hpp"
#include "test_util.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace jt {
namespace {

const char* const kHead =
    "render_settings { width: 4; height: 4; }\n"
    "cameras { perspective_camera { position: <0, 0, 10>; } }\n";

std::size_t distinct_finishes(const Scene& scene) {
    std::set<const void*> addresses;
    for (const Primitive& p : scene.primitives) addresses.insert(p.material.finish.address());
    return addresses.size();
}

std::string sphere(int i, const std::string& finish) {
    return "sphere { center: <" + std::to_string(i) +
           ", 0, 0>; radius: 0.5; material { pigment: <" + std::to_string(i % 7 / 7.0) +
           ", 0.5, 0.5>; " + finish + " } }\n";
}

TEST(FinishSharing, TenThousandSpheresOfOneFinishHoldItOnce) {
    std::string text = std::string(kHead) + "scene {\n";
    for (int i = 0; i < 10000; ++i)
        text += sphere(i, "ambient: <0.2, 0.2, 0.2>; diffuse: <0.8, 0.8, 0.8>;");
    text += "}\n";
    const ParseResult r = test::parse_clean(text);
    ASSERT_EQ(r.scene.primitives.size(), 10000u);
    EXPECT_EQ(distinct_finishes(r.scene), 1u);
    EXPECT_EQ(r.scene.primitives[9999].material.finish->diffuse, Colour(0.8));
    EXPECT_NE(r.scene.primitives[1].material.pigment, r.scene.primitives[2].material.pigment);
}

TEST(FinishSharing, AlternatingFinishesAreEachHeldOnce) {
    std::string text = std::string(kHead) + "scene {\n";
    for (int i = 0; i < 1000; ++i)
        text += sphere(i, i % 3 == 0   ? "reflection: 0.5;"
                          : i % 3 == 1 ? "specular: <1, 1, 1>; specular_k: 20;"
                                       : "");
    text += "}\n";
    const ParseResult r = test::parse_clean(text);
    ASSERT_EQ(r.scene.primitives.size(), 1000u);
    EXPECT_EQ(distinct_finishes(r.scene), 3u);
    // A material that sets no finish property has the default one, shared.
    EXPECT_TRUE(r.scene.primitives[2].material.finish.shares_with(Material{}.finish));
    EXPECT_EQ(r.scene.primitives[3].material.finish->reflection, 0.5);
    EXPECT_EQ(r.scene.primitives[4].material.finish->specular_k, 20.0);
}

TEST(FinishSharing, ANamedMaterialsFinishIsSharedByItsUsers) {
    std::string text = std::string(kHead) +
                       "material shiny { pigment: <1, 0, 0>; reflection: 0.3; }\n"
                       "scene {\n";
    for (int i = 0; i < 100; ++i)
        text += "sphere { center: <" + std::to_string(i) +
                ", 0, 0>; radius: 0.5; material: shiny; material { pigment: <0, " +
                std::to_string(i / 100.0) + ", 0>; } }\n";
    // One that overrides a finish property has a finish of its own.
    text += "sphere { material: shiny; material { reflection: 0.6; } }\n}\n";
    const ParseResult r = test::parse_clean(text);
    ASSERT_EQ(r.scene.primitives.size(), 101u);
    EXPECT_EQ(distinct_finishes(r.scene), 2u);
    EXPECT_EQ(r.scene.primitives[50].material.finish->reflection, 0.3);
    EXPECT_EQ(r.scene.primitives[100].material.finish->reflection, 0.6);
    EXPECT_EQ(r.scene.primitives[100].material.pigment, Colour(1, 0, 0));
}

TEST(FinishSharing, ASharedSceneEqualsOneBuiltInCode) {
    const ParseResult r =
        test::parse_clean(std::string(kHead) + "scene {\n" + sphere(0, "reflection: 0.5;") +
                          sphere(1, "reflection: 0.5;") + "}\n");
    Scene built = r.scene;
    for (Primitive& p : built.primitives) {
        Finish own;
        own.reflection = 0.5;
        p.material.finish = own;  // equal values, held apart
    }
    EXPECT_FALSE(
        built.primitives[0].material.finish.shares_with(built.primitives[1].material.finish));
    EXPECT_EQ(built, r.scene);
}

TEST(FinishTable, SharesEqualValuesAndRemembersAtMostItsLimit) {
    FinishTable table;
    std::vector<Shared<Finish>> finishes;
    for (std::size_t i = 0; i < kMaxTabledFinishes + 10; ++i) {
        Finish f;
        f.map_size = 1.0 + static_cast<double>(i);
        finishes.emplace_back(f);
        table.share(finishes.back());
    }
    EXPECT_EQ(table.size(), kMaxTabledFinishes);
    Shared<Finish> again = *finishes[5];
    table.share(again);
    EXPECT_TRUE(again.shares_with(finishes[5]));
    Shared<Finish> past = *finishes.back();
    table.share(past);
    EXPECT_FALSE(past.shares_with(finishes.back())) << "past the limit: not remembered";
    // As many misses in a row once full stop the search, even for a finish it holds.
    for (std::size_t i = 0; i < kMaxTabledFinishes; ++i) {
        Finish f;
        f.map_size = -1.0 - static_cast<double>(i);
        Shared<Finish> own = f;
        table.share(own);
    }
    Shared<Finish> late = *finishes[5];
    table.share(late);
    EXPECT_FALSE(late.shares_with(finishes[5]));
    // -0 and 0 are equal: they hash alike.
    Finish zero, negative_zero;
    negative_zero.reflection = -0.0;
    EXPECT_EQ(hash_value(zero), hash_value(negative_zero));
}

}  // namespace
}  // namespace jt
