// Generated smooth normals (docs/language.md §14.4), worked out by hand on
// small models held in memory: which triangles each corner takes in, -0 and 0
// as one position, the angle's edge, a zero sum, the file's normals kept, the
// bound on the work; and the validator's two warnings.

#include "common/files.hpp"
#include "common/scratch_dir.hpp"
#include "jtracer/limits.hpp"
#include "jtracer/scene_file.hpp"
#include "jtracer/smooth_normals.hpp"
#include "test_util.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>
#include <string>

namespace jt {
namespace {

using test::brief;

// A model of the given corners, one triangle for each three, none shared by
// index (as an STL file holds them).
Model split_model(const std::vector<glm::vec3>& corners) {
    Model m;
    m.positions = corners;
    for (std::uint32_t i = 0; i + 2 < corners.size(); i += 3)
        m.triangles.push_back({i, i + 1, i + 2});
    return m;
}

// The cube [-1, 1]^3 as 8 shared vertices and 12 triangles, counter-clockwise
// seen from outside.
Model cube() {
    Model m;
    for (int i = 0; i < 8; ++i)
        m.positions.emplace_back(i & 1 ? 1.0f : -1.0f, i & 2 ? 1.0f : -1.0f, i & 4 ? 1.0f : -1.0f);
    // Each face as a quad counter-clockwise from outside, fanned from its first corner.
    const std::uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) {
        m.triangles.push_back({q[0], q[1], q[2]});
        m.triangles.push_back({q[0], q[2], q[3]});
    }
    return m;
}

Vec3 unit_normal(const Model& m, std::size_t t) {
    const auto& c = m.triangles[t];
    const Vec3 a(m.positions[c[0]]), b(m.positions[c[1]]), d(m.positions[c[2]]);
    return glm::normalize(glm::cross(b - a, d - a));
}

double degrees_between(const Vec3& a, const Vec3& b) {
    return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0)) *
           180.0 / std::numbers::pi;
}

TEST(SmoothNormalGeneration, ACubeStaysFacetedAt60AndGoesRoundAt180) {
    const Model m = cube();
    EXPECT_EQ(corners_without_normals(m), 36u);
    const CornerNormals at60 = smooth_corner_normals(m, 60.0).value();
    ASSERT_EQ(at60.size(), 12u);
    // Faces meet at 90 degrees: each corner takes in only its own face's two
    // triangles, whose sum points along the face normal.
    for (std::size_t t = 0; t < 12; ++t)
        for (int k = 0; k < 3; ++k) EXPECT_EQ(at60[t][k], unit_normal(m, t)) << t << " " << k;
    // At 180 every triangle at a corner counts, by its area. Corner 6 =
    // (-1, 1, 1) is in one triangle of face +z (2 of area), one of face +y,
    // and both of face -x (the diagonal of its fan starts there): the sum of
    // the crosses is 4 (0, 0, 1) + 4 (0, 1, 0) + 8 (-1, 0, 0).
    const CornerNormals at180 = smooth_corner_normals(m, 180.0).value();
    int seen = 0;
    for (std::size_t t = 0; t < 12; ++t)
        for (int k = 0; k < 3; ++k)
            if (m.triangles[t][k] == 6) {
                ++seen;
                EXPECT_NEAR(glm::length(at180[t][k] - Vec3(-2, 1, 1) / std::sqrt(6.0)), 0.0, 1e-15);
                EXPECT_GT(degrees_between(at180[t][k], unit_normal(m, t)), 35.0);
            }
    EXPECT_EQ(seen, 4);
}

// Two triangles with a corner at the origin, one written as -0, their faces
// 30 degrees apart: one position, so within 60 degrees each takes in the
// other; within 20 degrees neither does.
TEST(SmoothNormalGeneration, CornersMatchAsNumbersSoMinusZeroIsZero) {
    const float s = static_cast<float>(std::sin(std::numbers::pi / 6));
    const float c = static_cast<float>(std::cos(std::numbers::pi / 6));
    // Face normals (0, 0, 1) and (0, -s, c) after the tilt about x.
    const Model m = split_model(
        {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-0.0f, -0.0f, -0.0f}, {0, c, s}, {-1, 0, 0}});
    ASSERT_EQ(m.triangles.size(), 2u);
    const CornerNormals wide = smooth_corner_normals(m, 60.0).value();
    EXPECT_EQ(wide[0][0], wide[1][0]);
    EXPECT_GT(degrees_between(wide[0][0], unit_normal(m, 0)), 5.0);
    // The other corners are not shared.
    EXPECT_EQ(wide[0][1], unit_normal(m, 0));
    EXPECT_EQ(wide[1][1], unit_normal(m, 1));
    const CornerNormals narrow = smooth_corner_normals(m, 20.0).value();
    EXPECT_EQ(narrow[0][0], unit_normal(m, 0));
    EXPECT_EQ(narrow[1][0], unit_normal(m, 1));
}

// Faces exactly 90 degrees apart: cos(90 degrees) is 6e-17 in double, not 0;
// the language's 1e-12 lets a face exactly at the angle in.
TEST(SmoothNormalGeneration, AFaceExactlyAtTheAngleCountsAndOneBeyondDoesNot) {
    const Model m = split_model({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}, {0, 0, 1}, {1, 0, 0}});
    EXPECT_EQ(unit_normal(m, 0), Vec3(0, 0, 1));
    EXPECT_EQ(unit_normal(m, 1), Vec3(0, 1, 0));
    const CornerNormals at90 = smooth_corner_normals(m, 90.0).value();
    EXPECT_EQ(at90[0][0], glm::normalize(Vec3(0, 1, 1)));
    EXPECT_EQ(at90[0][1], glm::normalize(Vec3(0, 1, 1)));  // (1, 0, 0) is shared too
    const CornerNormals below = smooth_corner_normals(m, 89.999).value();
    EXPECT_EQ(below[0][0], Vec3(0, 0, 1));
    EXPECT_EQ(below[1][0], Vec3(0, 1, 0));
}

// Two faces back to back on the same corners: within 180 degrees each takes
// in the other, and the sum is zero: each corner falls back to its own
// triangle's geometric normal.
TEST(SmoothNormalGeneration, AZeroSumFallsBackToTheGeometricNormal) {
    const Model m = split_model({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}, {0, 1, 0}, {1, 0, 0}});
    const CornerNormals n = smooth_corner_normals(m, 180.0).value();
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(n[0][k], Vec3(0, 0, 1));
        EXPECT_EQ(n[1][k], Vec3(0, 0, -1));
    }
}

// The file's normals stay as stored (not made unit length), and the corners
// that have one still count in their neighbours' sums.
TEST(SmoothNormalGeneration, TheFilesNormalsAreKeptWhereItHasThem) {
    Model m = split_model({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}, {0, 0, 1}, {1, 0, 0}});
    m.normals.assign(6, glm::vec3(0.0f));
    m.normals[0] = {0.0f, 0.0f, 2.0f};
    m.normals[4] = {0.0f, 3.0f, 0.0f};
    EXPECT_EQ(corners_without_normals(m), 4u);
    const CornerNormals n = smooth_corner_normals(m, 90.0).value();
    EXPECT_EQ(n[0][0], Vec3(0, 0, 2));
    EXPECT_EQ(n[1][1], Vec3(0, 3, 0));
    EXPECT_EQ(n[1][0], glm::normalize(Vec3(0, 1, 1)));  // the first triangle is in the sum
    EXPECT_EQ(n[0][2], Vec3(0, 0, 1));                  // (0, 1, 0) is its alone
}

// A cone of many thin faces around one apex, each facing its own way, would
// take quadratic time: past the bound it is an error naming the place.
TEST(SmoothNormalGeneration, TooManyDirectionsAtOnePointIsAnErrorNotAHang) {
    constexpr int sides = 6000;
    std::vector<glm::vec3> corners;
    for (int i = 0; i < sides; ++i) {
        const double a = 2 * std::numbers::pi * i / sides,
                     b = 2 * std::numbers::pi * (i + 1) / sides;
        corners.push_back({0.0f, 0.0f, 1.0f});
        corners.push_back({static_cast<float>(std::cos(a)), static_cast<float>(std::sin(a)), 0.0f});
        corners.push_back({static_cast<float>(std::cos(b)), static_cast<float>(std::sin(b)), 0.0f});
    }
    const Model m = split_model(corners);
    ASSERT_GT(static_cast<double>(sides) * sides,
              static_cast<double>(smooth_normal_comparisons(m)));
    const auto n = smooth_corner_normals(m, 30.0);
    ASSERT_FALSE(n.has_value());
    EXPECT_NE(n.error().message.find("meet at <0, 0, 1>"), std::string::npos) << n.error().message;
    // Within the bound the same apex is fine: a few hundred sides.
    EXPECT_TRUE(
        smooth_corner_normals(split_model({corners.begin(), corners.begin() + 3 * 500}), 30.0)
            .has_value());
}

constexpr std::string_view kHead =
    "render_settings { width: 4; height: 4; }\n"
    "cameras { perspective_camera { } }\n";

std::string check(const std::filesystem::path& dir, const std::string& scene) {
    test::write_file(dir / "s.jts", std::string(kHead) + scene);
    Expected<LoadedScene> loaded = load_scene_file(dir / "s.jts");
    EXPECT_TRUE(loaded.has_value());
    return loaded ? brief(check_scene(*loaded)) : "";
}

// Language 1.1 shades flat a triangle the file gives no normal at some
// corner; the validator says so once a mesh, at its file string, with how
// many corners, and names smooth_angle. Flat meshes and meshes with
// smooth_angle do not get it; smooth_angle on a flat mesh is ignored, said at
// the property.
TEST(SmoothNormalGeneration, WarningsAtTheFileStringAndAtTheProperty) {
    test::ScratchDir dir;
    // Two triangles; the first has normals at all its corners, the second at one.
    test::write_file(dir.path() / "m.obj",
                     "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 0 0 1\n"
                     "f 1//1 2//1 3//1\nf 2//1 4 3\n");
    test::write_file(dir.path() / "n.stl",
                     "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                     "vertex 0 1 0\nendloop\nendfacet\nendsolid s\n");
    EXPECT_EQ(check(dir.path(),
                    "scene {\n  mesh { file: \"m.obj\"; }\n"
                    "  mesh { file: \"m.obj\"; }\n}\n"),
              "4:16: warning: mesh 1: 'm.obj' has no normal at 2 of its 6 triangle corners: their "
              "triangles are shaded flat; smooth_angle (such as 60) generates normals there\n"
              "5:16: warning: mesh 2: 'm.obj' has no normal at 2 of its 6 triangle corners: their "
              "triangles are shaded flat; smooth_angle (such as 60) generates normals there");
    // STL's facet normals are not vertex normals.
    EXPECT_EQ(check(dir.path(), "scene { mesh { file: \"n.stl\"; } }\n"),
              "3:22: warning: mesh 1: 'n.stl' has no normal at 3 of its 3 triangle corners: their "
              "triangles are shaded flat; smooth_angle (such as 60) generates normals there");
    EXPECT_EQ(check(dir.path(), "scene { mesh { file: \"n.stl\"; smooth_angle: 60; } }\n"), "");
    EXPECT_EQ(check(dir.path(), "scene { mesh { file: \"n.stl\"; shading: \"flat\"; } }\n"), "");
    EXPECT_EQ(check(dir.path(),
                    "scene { mesh { file: \"n.stl\"; shading: \"flat\"; smooth_angle: 30; } }\n"),
              "3:62: warning: mesh 1: 'smooth_angle' does nothing with shading \"flat\": it is "
              "ignored");
}

// A model past the work bound is an error where the angle is written, for
// --check as for a render.
TEST(SmoothNormalGeneration, AModelPastTheWorkBoundIsAnErrorAtTheAngle) {
    test::ScratchDir dir;
    constexpr int sides = 6000;
    std::string obj = "v 0 0 1\n";
    for (int i = 0; i < sides; ++i) {
        const double a = 2 * std::numbers::pi * i / sides;
        obj += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
    }
    for (int i = 0; i < sides; ++i)
        obj += "f 1 " + std::to_string(2 + i) + " " + std::to_string(2 + (i + 1) % sides) + "\n";
    test::write_file(dir.path() / "cone.obj", obj);
    const std::string found =
        check(dir.path(), "scene { mesh { file: \"cone.obj\"; smooth_angle: 30; } }\n");
    EXPECT_EQ(
        found.rfind("3:48: error: mesh 1: 'cone.obj': smooth_angle would compare more than ", 0),
        0u)
        << found;
    EXPECT_NE(found.find("6000 triangles meet at <0, 0, 1>"), std::string::npos) << found;
}

TEST(SmoothNormalGeneration, TheAngleIsCheckedWhereItIsWritten) {
    const std::string mesh = std::string(kHead) + "scene { mesh { file: \"m.obj\"; smooth_angle: ";
    EXPECT_EQ(brief(mesh + "-1; } }"),
              "3:45: error: 'smooth_angle' must be from 0 to 180 degrees, got -1");
    EXPECT_EQ(brief(mesh + "181; } }"),
              "3:45: error: 'smooth_angle' must be from 0 to 180 degrees, got 181");
    EXPECT_EQ(brief(mesh + "\"x\"; } }"),
              "3:45: error: 'smooth_angle' takes a number like 1.5, got the string \"x\"");
    const ParseResult r = test::parse_clean(mesh + "0; } }");
    EXPECT_EQ(shape_as<Mesh>(r.scene.primitives[0].shape).smooth_angle, 0.0);
}

}  // namespace
}  // namespace jt
