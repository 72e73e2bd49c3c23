// Scenes large enough that the parser reserves its arrays for 2 MiB pages
// (io/reserve_records.hpp): the records must come out the same as for a small
// scene, with and without the source map.

#include "test_util.hpp"

#include "io/huge_pages.hpp"
#include "io/page_warmer.hpp"

// (Strings are built with append: GCC 12 warns falsely on "literal" + std::string&&.)

#include <string>

namespace jt {
namespace {

// ~22 MB of property records, past the size from which arrays take 2 MiB
// pages (the primitives pass it in the last test).
constexpr int sphere_count = 70000;

// Sphere i: centre <i, 0, 0>, radius 1 + i/10000, then a material and a
// transform block, then one more property after them.
std::string many_spheres() {
    std::string text = "scene {\n";
    for (int i = 0; i < sphere_count; ++i) {
        text += "sphere { center: <" + std::to_string(i) + ", 0, 0>; material { pigment: <0.5, " +
                std::to_string(i % 2) + ", 0>; diffuse: <0.8, 0.8, 0.8>; } transform { scale: <" +
                std::to_string(i + 1) + ", 1, 1>; } radius: 1." + std::to_string(i) + "; }\n";
    }
    text += "point_light { position: <0, 5, 0>; intensity: <1, 1, 1>; }\n}\n";
    return text;
}

TEST(LargeScene, EveryRecordInPlace) {
    ASSERT_GE(5 * sphere_count * sizeof(PropertySource), min_huge_page_array_bytes);
    const std::string text = many_spheres();
    ParseResult r = test::parse_clean(text);
    ASSERT_EQ(r.scene.primitives.size(), static_cast<std::size_t>(sphere_count));
    ASSERT_EQ(r.source.primitives.size(), static_cast<std::size_t>(sphere_count));
    ASSERT_EQ(r.source.children.size(), 2u * sphere_count);
    ASSERT_EQ(r.scene.lights.size(), 1u);
    // 5 a sphere (2 its own, 2 its material's, 1 its transform's), 2 the light's.
    ASSERT_EQ(r.source.properties.size(), 5u * sphere_count + 2u);
    for (int i = 0; i < sphere_count; i += 997) {
        const Primitive& p = r.scene.primitives[static_cast<std::size_t>(i)];
        EXPECT_EQ(shape_as<Sphere>(p.shape).center, Vec3(i, 0, 0));
        EXPECT_EQ(p.material.pigment, Colour(0.5, i % 2, 0));
        ASSERT_EQ(p.transforms.size(), 1u);
        EXPECT_EQ(p.transforms[0].vector, Vec3(i + 1, 1, 1));

        const BlockSource& block = r.source.primitives[static_cast<std::size_t>(i)];
        auto own = properties_of(r.source, block);
        ASSERT_EQ(own.size(), 2u);
        EXPECT_EQ(own[0].name, "center");
        EXPECT_EQ(own[1].name, "radius");
        EXPECT_EQ(text.substr(own[1].value_span.offset, own[1].value_span.length),
                  std::string("1.").append(std::to_string(i)));
        EXPECT_EQ(own[1].value_span.pos.line, i + 2);

        auto children = children_of(r.source, block);
        ASSERT_EQ(children.size(), 2u);
        EXPECT_EQ(children[0].keyword, "material");
        EXPECT_EQ(children[1].keyword, "transform");
        auto material = properties_of(r.source, children[0]);
        ASSERT_EQ(material.size(), 2u);
        EXPECT_EQ(material[0].name, "pigment");
        EXPECT_EQ(material[1].name, "diffuse");
        auto transform = properties_of(r.source, children[1]);
        ASSERT_EQ(transform.size(), 1u);
        EXPECT_EQ(text.substr(transform[0].value_span.offset, transform[0].value_span.length),
                  std::string("<").append(std::to_string(i + 1)).append(", 1, 1>"));
    }
    auto light = properties_of(r.source, r.source.lights.at(0));
    ASSERT_EQ(light.size(), 2u);
    EXPECT_EQ(light[1].name, "intensity");
}

TEST(LargeScene, SameSceneWithoutTheSourceMap) {
    const std::string text = many_spheres();
    ParseResult mapped = parse_scene(text);
    ParseResult unmapped = parse_scene(text, {.source_map = false});
    EXPECT_TRUE(unmapped.ok());
    EXPECT_TRUE(unmapped.source == SceneSource{});
    EXPECT_TRUE(unmapped.scene == mapped.scene);
}

// The same errors, in the same places, whatever the size: the last sphere's
// are reported at its own line.
TEST(LargeScene, DiagnosticsInABigScene) {
    std::string text = many_spheres();
    text.insert(text.rfind("point_light"), "sphere { radius: -1; material { x { } } }\n");
    const std::string line = std::to_string(sphere_count + 2);
    EXPECT_EQ(test::brief(parse_scene(text).diagnostics),
              line + ":18: error: 'radius' must be greater than 0 and at most 1e+09, got -1\n" +
                  line +
                  ":33: error: unexpected block 'x' in 'material', which holds only properties");
}

// So many spheres that their primitives' pages are faulted in on another
// thread while the parser fills them (io/page_warmer.hpp): every primitive
// comes out as written, with or without the source map.
TEST(LargeScene, PrimitivesFilledBesideTheirPageWarmerAreAsWritten) {
    constexpr int count = 800000;  // ~77 MB of primitives, past the warmer's threshold
    ASSERT_GT(count * sizeof(Primitive), PageWarmer::smallest_warmed_bytes);
    std::string text = "scene {\n";
    for (int i = 0; i < count; ++i)
        text.append("sphere{center:<")
            .append(std::to_string(i))
            .append(",0,0>;radius:1;material{pigment:<0.5,0,")
            .append(std::to_string(i % 2))
            .append(">;}}\n");
    text += "}\n";
    for (bool source_map : {false, true}) {
        ParseResult r = parse_scene(text, {.source_map = source_map});
        ASSERT_TRUE(r.ok());
        ASSERT_EQ(r.scene.primitives.size(), static_cast<std::size_t>(count));
        for (int i = 0; i < count; ++i) {
            const Primitive& p = r.scene.primitives[static_cast<std::size_t>(i)];
            ASSERT_EQ(shape_as<Sphere>(p.shape).center, Vec3(i, 0, 0)) << i;
            ASSERT_EQ(p.material.pigment, Colour(0.5, 0, i % 2)) << i;
        }
    }
}

}  // namespace
}  // namespace jt
