// Triangles and meshes, worked out by hand from docs/language.md §13.5: the hit
// point and barycentric UV of a triangle, smooth normals from known vertex
// normals, the two-sided rule, the shadow rule, instancing, and watertight
// edges and vertices of a closed mesh.

#include "common/files.hpp"
#include "common/scratch_dir.hpp"
#include "render/prepared_scene.hpp"
#include "render/ray_queries.hpp"
#include "scene_builder.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <random>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

namespace jt::test {
namespace {

Primitive triangle(const Vec3& a, const Vec3& b, const Vec3& c, const Material& m = {}) {
    Triangle t;
    t.a = a;
    t.b = b;
    t.c = c;
    return Primitive{t, m, {}};
}

Primitive mesh(const std::filesystem::path& file, const Material& m = {},
               std::string_view shading = kSmoothShading) {
    Mesh shape;
    shape.file = file.string();
    shape.shading = std::string(shading);
    return Primitive{shape, m, {}};
}

// The triangle z = -2 with corners (-1,-1), (1,-1), (-1,1): the ray from the
// origin along (0.2, -0.4, -1) meets it at t = 2, at (0.4, -0.8, -2), where
// p = a + u (b - a) + v (c - a) gives u = 0.7, v = 0.1.
TEST(Triangles, HitAtAKnownPointWithBarycentricUv) {
    Scene s = scene_with_camera(camera_at({0, 0, 0}, {0, 0, -1}));
    Primitive p = triangle({-1, -1, -2}, {1, -1, -2}, {-1, 1, -2});
    auto& t = shape_as<Triangle>(p.shape);
    t.uv_a = {0.5, 0.5, 0};
    t.uv_b = {1.5, 0.5, 0};
    t.uv_c = {0.5, 2.5, 0};
    s.primitives.push_back(p);
    auto prepared = prepare_scene(s).value();
    Hit hit;
    ASSERT_TRUE(closest_hit(*prepared->geometry, {0, 0, 0}, {0.2, -0.4, -1}, 0.0, hit));
    EXPECT_NEAR(hit.t, 2.0, 1e-14);
    const Vec3 n = glm::normalize(hit.normal);
    EXPECT_NEAR(n.z, 1.0, 1e-15);  // cross(b - a, c - a): counter-clockwise from the front
    // uv = w uv_a + u uv_b + v uv_c with w = 0.2.
    EXPECT_NEAR(hit.uv.x, 0.2 * 0.5 + 0.7 * 1.5 + 0.1 * 0.5, 1e-14);
    EXPECT_NEAR(hit.uv.y, 0.2 * 0.5 + 0.7 * 0.5 + 0.1 * 2.5, 1e-14);
    // Outside the triangle (u + v > 1): no hit.
    EXPECT_FALSE(closest_hit(*prepared->geometry, {0, 0, 0}, {0.5, 0.6, -2}, 0.0, hit));
}

TEST(Triangles, ZeroAreaAndZeroScaleTrianglesAreLeftOut) {
    Scene s = scene_with_camera(camera_at({0, 0, 0}, {0, 0, -1}));
    s.primitives.push_back(triangle({-1, -1, -2}, {1, 1, -2}, {2, 2, -2}));
    Primitive flattened = triangle({-1, -1, -2}, {1, -1, -2}, {-1, 1, -2});
    flattened.transforms = {scale({1, 1, 0})};
    s.primitives.push_back(flattened);
    auto prepared = prepare_scene(s).value();
    Hit hit;
    EXPECT_FALSE(closest_hit(*prepared->geometry, {0, 0, 0}, {-0.1, -0.1, -1}, 0.0, hit));
}

// One triangle in an OBJ file with a normal at each corner, seen head-on from
// a 1x1 camera whose ray hits (0, 0, -2); the light sits at the camera.
std::filesystem::path facing_triangle(const std::filesystem::path& dir,
                                      const std::string& normals) {
    const auto file = dir / "t.obj";
    write_file(file, "v -1 -1 -2\nv 3 -1 -2\nv -1 3 -2\n" + normals + "f 1//1 2//2 3//3\n");
    return file;
}

Scene lit_head_on(const std::filesystem::path& model, std::string_view shading) {
    Scene s = scene_with_camera(camera_at({0, 0, 0}, {0, 0, -1}));
    s.primitives.push_back(mesh(model, matte(Colour(1.0)), shading));
    s.lights.push_back({{0, 0, 0}, Colour(1.0)});
    return s;
}

TEST(Triangles, SmoothNormalIsTheBarycentricBlendOfTheVertexNormals) {
    ScratchDir dir;
    // At (0, 0, -2): u = v = 0.25, w = 0.5. Blend of (0,0,1), (1,0,0), (0,1,0):
    // (0.25, 0.25, 0.5) / |..| = (1, 1, 2) / sqrt(6); L = +z, so the diffuse term
    // is 2 / sqrt(6).
    const auto model = facing_triangle(dir.path(), "vn 0 0 1\nvn 1 0 0\nvn 0 1 0\n");
    auto prepared = prepare_scene(lit_head_on(model, kSmoothShading)).value();
    Hit hit;
    ASSERT_TRUE(closest_hit(*prepared->geometry, {0, 0, 0}, {0, 0, -1}, 0.0, hit));
    const Vec3 n = glm::normalize(hit.shading);
    EXPECT_NEAR(n.x, 1 / std::sqrt(6.0), 1e-7);
    EXPECT_NEAR(n.y, 1 / std::sqrt(6.0), 1e-7);
    EXPECT_NEAR(n.z, 2 / std::sqrt(6.0), 1e-7);
    EXPECT_EQ(at(render(lit_head_on(model, kSmoothShading)), 0, 0),
              expected(Colour(2 / std::sqrt(6.0))));
    // Flat shading uses the geometric normal: the full light.
    EXPECT_EQ(at(render(lit_head_on(model, kFlatShading)), 0, 0), expected(Colour(1.0)));
}

TEST(Triangles, TwoSidedRuleTurnsTheSmoothNormalToTheFacingSide) {
    ScratchDir dir;
    // Stored normals pointing away from the camera, tilted: (0.6, 0, -0.8).
    // Ng faces the camera (+z); N turns to its side: (-0.6, 0, 0.8), so the
    // diffuse term for L = +z is 0.8.
    const auto model = facing_triangle(dir.path(), "vn 0.6 0 -0.8\nvn 0.6 0 -0.8\nvn 0.6 0 -0.8\n");
    EXPECT_EQ(at(render(lit_head_on(model, kSmoothShading)), 0, 0), expected(Colour(0.8)));
    // From behind, Ng turns to -z and N = (0.6, 0, -0.8): the same 0.8.
    Scene behind = lit_head_on(model, kSmoothShading);
    behind.cameras[0] = camera_at({0, 0, -4}, {0, 0, -1});
    behind.lights[0].position = {0, 0, -4};
    EXPECT_EQ(at(render(behind), 0, 0), expected(Colour(0.8)));
}

// A smooth normal facing a light the flat face turns away from: the light is
// blocked only by surfaces other than the triangle that holds the point.
TEST(Triangles, ALightBehindTheFaceButBeforeTheSmoothNormalIsNotBlockedByItsOwnTriangle) {
    ScratchDir dir;
    const auto model = facing_triangle(dir.path(), "vn 0.8 0 0.6\nvn 0.8 0 0.6\nvn 0.8 0 0.6\n");
    Scene s = lit_head_on(model, kSmoothShading);
    // From (0,0,-2) toward (10, 0, -3): L = (10, 0, -1)/|..|, behind the face
    // (dot(Ng, L) < 0), in front of N: dot(N, L) = (8 - 0.6) / sqrt(101).
    s.lights[0].position = {10, 0, -3};
    EXPECT_EQ(at(render(s), 0, 0), expected(Colour(7.4 / std::sqrt(101.0))));
    // Another surface in the way still blocks it.
    s.primitives.push_back(sphere({5, 0, -2.5}, 0.5, matte(Colour(1.0))));
    EXPECT_EQ(at(render(s), 0, 0), (Rgb{0, 0, 0}));
}

// A glass triangle in z = 0 seen at 60 degrees from +z: entering glass of
// index 1.5, the ray refracts down to a glowing floor (green); taken for a ray
// leaving the glass it would be totally reflected (1.5 sin 60 > 1) up into the
// background (red).
Scene glass_triangle_over_a_floor(const Primitive& glass) {
    const Vec3 aim{2, -2, 0};
    Scene s = scene_with_camera(camera_at(aim + Vec3(0, -std::sqrt(3.0), 1), aim), 9, 9);
    s.settings.recurse_depth = 1;
    s.settings.ambient_light = Colour(1.0);
    s.settings.background = {1, 0, 0};
    s.primitives.push_back(glass);
    s.primitives.push_back(plane({0, 0, 1}, -1.0, glowing({0, 1, 0})));
    return s;
}

// The outward normal of a triangle under a transform M is M^-T cross(b - a,
// c - a): under a mirror (det M < 0) the corners wind the other way in world
// space, and the outside stays where M puts it.
TEST(Triangles, AMirroredGlassTriangleRefractsAsItsOutwardNormalSays) {
    Material glass;  // black: only the transmitted ray shows
    glass.finish.edit().transmission = 1.0;
    glass.finish.edit().ior = 1.5;
    // Counter-clockwise seen from +z; mirrored in x, its outward normal
    // M^-T (0, 0, 1) is still +z, though its world corners (5, -5), (-5, -5),
    // (5, 5) wind clockwise seen from there.
    Primitive mirrored = triangle({-5, -5, 0}, {5, -5, 0}, {-5, 5, 0}, glass);
    mirrored.transforms = {scale({-1, 1, 1})};
    // Those corners counter-clockwise, with no transform.
    const Primitive plain = triangle({5, -5, 0}, {5, 5, 0}, {-5, -5, 0}, glass);
    const Image8 expected_image = render(glass_triangle_over_a_floor(plain));
    EXPECT_EQ(at(expected_image, 4, 4), (Rgb{0, 255, 0}));
    const Image8 image = render(glass_triangle_over_a_floor(mirrored));
    EXPECT_EQ(at(image, 4, 4), (Rgb{0, 255, 0}));
    EXPECT_TRUE(image == expected_image);
    // Mirrored in two axes (det > 0) is no mirror: turned back by a rotation
    // onto the same region, it is entered from above as well.
    mirrored.transforms = {scale({-1, -1, 1}), rotate(TransformKind::zrotate, -90)};
    EXPECT_EQ(at(render(glass_triangle_over_a_floor(mirrored)), 4, 4), (Rgb{0, 255, 0}));
    // Seen from below, the same ray leaves the glass: totally reflected down, to black.
    Scene below = glass_triangle_over_a_floor(plain);
    below.cameras[0] = camera_at({2, -2 - std::sqrt(3.0), -1}, {2, -2, 0});
    below.primitives.pop_back();
    EXPECT_EQ(at(render(below), 4, 4), (Rgb{255, 0, 0}));
}

// One triangle in y = 0 whose vertex normals all lean far from its face,
// <1, 0.1, 0>, seen from above: the ray reflected about that normal heads
// below the face, where it must see what lies there (the background), not the
// triangle it leaves (docs/language.md §13.5: no surface reflects itself).
TEST(Triangles, ARayReflectedBehindItsFaceDoesNotMeetItsOwnTriangle) {
    ScratchDir dir;
    const auto model = dir.path() / "leaning.obj";
    write_file(model,
               "v -40 0 40\nv 40 0 40\nv 0 0 -40\nvn 1 0.1 0\nvn 1 0.1 0\nvn 1 0.1 0\n"
               "f 1//1 2//2 3//3\n");
    Scene s = scene_with_camera(camera_at({0.3, 5, 0.2}, {0.3, 0, 0.2}, {0, 0, -1}, 20.0), 7, 7);
    s.settings.recurse_depth = 1;
    s.settings.ambient_light = Colour(1.0);
    s.settings.background = {0, 0, 1};
    Material m = glowing({0.5, 0, 0});
    m.finish.edit().reflection = 1.0;
    s.primitives.push_back(mesh(model, m, kSmoothShading));
    const Image8 image = render(s);
    // Half red of its own, and the blue background its reflection sees.
    for (int y = 0; y < 7; ++y)
        for (int x = 0; x < 7; ++x)
            EXPECT_EQ(at(image, x, y), (Rgb{128, 0, 255})) << x << ", " << y;
}

TEST(Triangles, InstancesShareOneModelAndFollowTheirTransforms) {
    ScratchDir dir;
    const auto model = facing_triangle(dir.path(), "");
    Scene s = scene_with_camera(camera_at({0, 0, 0}, {0, 0, -1}));
    for (int i = 0; i < 100; ++i) {
        Primitive p = mesh(model, glowing(Colour(1.0)));
        p.transforms = {translate({10.0 * i, 0, 0})};
        s.primitives.push_back(p);
    }
    auto prepared = prepare_scene(s).value();
    const TriangleGeometry& t = *prepared->geometry->triangles;
    EXPECT_EQ(t.models.size(), 1u);
    EXPECT_EQ(t.instances.size(), 100u);
    Hit hit;
    ASSERT_TRUE(closest_hit(*prepared->geometry, {990, 0, 0}, {0, 0, -1}, 0.0, hit));
    EXPECT_EQ(hit.source, 99u);
    EXPECT_NEAR(hit.t, 2.0, 1e-12);
}

// The octahedron with corners at +-1 on each axis, as an OBJ.
std::filesystem::path octahedron(const std::filesystem::path& dir) {
    const auto file = dir / "octahedron.obj";
    write_file(file,
               "v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\n"
               "f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n");
    return file;
}

// Rays aimed exactly at every shared vertex and edge midpoint of a closed
// mesh, from many directions that enter the solid there, never slip through.
TEST(Triangles, RaysThroughSharedEdgesAndVerticesNeverMiss) {
    ScratchDir dir;
    Scene s = scene_with_camera(camera_at({0, 0, 0}, {0, 0, -1}));
    s.primitives.push_back(mesh(octahedron(dir.path())));
    Primitive turned = mesh(octahedron(dir.path()));
    turned.transforms = {rotate(TransformKind::yrotate, 30), translate({5, 0, 0})};
    s.primitives.push_back(turned);
    auto prepared = prepare_scene(s).value();
    const std::vector<Vec3> corners{{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                    {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
    std::vector<Vec3> targets = corners;
    for (std::size_t i = 0; i < corners.size(); ++i)
        for (std::size_t j = i + 1; j < corners.size(); ++j)
            if (corners[i] != -corners[j]) targets.push_back(0.5 * (corners[i] + corners[j]));
    ASSERT_EQ(targets.size(), 18u);
    std::mt19937 rng(3);
    // Within 23 degrees of the outward direction: inside the 35-degree cone of
    // solid at a vertex and the wider wedge at an edge, so every ray enters.
    std::uniform_real_distribution<double> tilt(-0.25, 0.25);
    const double c = std::cos(M_PI / 6), sn = std::sin(M_PI / 6);
    auto turn = [&](const Vec3& v) { return Vec3{c * v.x + sn * v.z, v.y, -sn * v.x + c * v.z}; };
    int misses = 0, rays = 0;
    for (int k = 0; k < 300; ++k) {
        for (const Vec3& target : targets) {
            const Vec3 out =
                glm::normalize(glm::normalize(target) + Vec3(tilt(rng), tilt(rng), tilt(rng)));
            Hit hit;
            const Vec3 from = target + 7.0 * out;
            ++rays;
            if (!closest_hit(*prepared->geometry, from, target - from, 0.0, hit)) ++misses;
            // The turned copy: the same points through its transform.
            const Vec3 placed = turn(target) + Vec3(5, 0, 0);
            const Vec3 origin = placed + 7.0 * turn(out);
            ++rays;
            if (!closest_hit(*prepared->geometry, origin, placed - origin, 0.0, hit)) ++misses;
        }
    }
    EXPECT_EQ(misses, 0) << "of " << rays;
}

// The offset of the octahedron the vertex tests aim at: no round numbers.
const Vec3 kVertexTestOffset(-36.563575588759875, 34.74337369372327, 26.377461897661405);

struct VertexRays {
    int rays = 0;
    int away = 0;       // met nothing, or not at the vertex
    int unblocked = 0;  // shadow rays to just past the vertex that nothing blocked
};

// Rays from 500 and 5000 model sizes away, aimed exactly at each vertex of
// the octahedron placed at kVertexTestOffset, from within its cone of solid.
VertexRays rays_at_vertices(const Geometry& geometry) {
    const Vec3 corners[] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> tilt(-0.3, 0.3);
    VertexRays counts;
    for (const double distance : {500.0, 5000.0}) {
        for (int k = 0; k < 200; ++k) {
            for (const Vec3& corner : corners) {
                const Vec3 out = glm::normalize(corner + Vec3(tilt(rng), tilt(rng), tilt(rng)));
                const Vec3 target = corner + kVertexTestOffset;
                const Vec3 from = target + distance * out;
                Hit hit;
                ++counts.rays;
                if (!closest_hit(geometry, from, target - from, 0.0, hit) ||
                    !(std::abs(hit.t - 1.0) < 1e-9))
                    ++counts.away;
                if (!occluded(geometry, from, target - from, 0.0, 1.0 + 1e-6)) ++counts.unblocked;
            }
        }
    }
    return counts;
}

// Each ray meets a face around the vertex, at the vertex, never the face it
// leaves by (t about 1 + 2 / D), and a shadow ray to just past it is blocked.
// A float ray started that far off rounds the edge values at the vertex at its
// own distance, and all four could come out on one side.
TEST(Triangles, ARayFromFarOffThroughAVertexMeetsAFaceAroundIt) {
    ScratchDir dir;
    Scene s = scene_with_camera(camera_at({0, 0, 0}, {0, 0, -1}));
    Primitive placed = mesh(octahedron(dir.path()));
    placed.transforms = {translate(kVertexTestOffset)};
    s.primitives.push_back(placed);
    const VertexRays counts = rays_at_vertices(*prepare_scene(s).value()->geometry);
    EXPECT_EQ(counts.away, 0) << "of " << counts.rays << " rays met no face at the vertex";
    EXPECT_EQ(counts.unblocked, 0) << "of " << counts.rays << " shadow rays passed the vertex";
}

// The same rays, from inside the box of all the triangles: a second, huge
// octahedron around the first puts every start inside its box (and inside
// it), so no move to where the ray enters the triangles' box comes near the
// small mesh.
TEST(Triangles, ARayFromInsideTheTrianglesBoxThroughAVertexMeetsAFaceAroundIt) {
    ScratchDir dir;
    Scene s = scene_with_camera(camera_at({0, 0, 0}, {0, 0, -1}));
    Primitive small = mesh(octahedron(dir.path()));
    small.transforms = {translate(kVertexTestOffset)};
    Primitive huge = mesh(octahedron(dir.path()));
    huge.transforms = {scale({30000, 30000, 30000}), translate(kVertexTestOffset)};
    s.primitives.push_back(small);
    s.primitives.push_back(huge);
    const VertexRays counts = rays_at_vertices(*prepare_scene(s).value()->geometry);
    EXPECT_EQ(counts.away, 0) << "of " << counts.rays << " rays met no face at the vertex";
    EXPECT_EQ(counts.unblocked, 0) << "of " << counts.rays << " shadow rays passed the vertex";
}

// Rays from inside a tetrahedron's face F, lifted off it as a hit's are,
// leaving 1e-7 to 3e-6 (barycentric) from its edge with face N and heading
// out through N near that edge, where they pass in double precision: the
// closest hit along each is N, and a shadow ray along it toward a light
// outside is blocked by N. Within single-precision rounding of the edge,
// Embree's float test may put such a ray just outside N, and the partner
// across the edge is F, which the ray leaves and never meets.
// A tetrahedron whose faces F = (a, b, c) and N = (a, d, b) share the edge ab,
// as an OBJ file's text.
constexpr const char* kTetrahedron =
    "v 0.75 1.25 0.75\nv 1.25 -1 -1\nv -1 1 -0.75\nv -1 -1 0.75\n"
    "f 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n";

// One mesh, the OBJ text `obj` written into `dir`, under `transforms`, prepared.
std::shared_ptr<const PreparedScene> prepared_mesh(const std::filesystem::path& dir,
                                                   std::string_view obj,
                                                   std::vector<TransformOp> transforms) {
    const auto file = dir / "model.obj";
    write_file(file, obj);
    Scene s = scene_with_camera(camera_at({0, 0, 0}, {0, 0, -1}));
    Primitive p = mesh(file);
    p.transforms = std::move(transforms);
    s.primitives.push_back(p);
    return prepare_scene(s).value();
}

TEST(Triangles, AShadowRayLeavingNearAnEdgeIntoAFoldIsBlocked) {
    ScratchDir dir;
    const Vec3 shift{37.3, -21.7, 55.1};
    auto prepared = prepared_mesh(dir.path(), kTetrahedron, {translate(shift)});
    const Geometry& geometry = *prepared->geometry;
    // F = (a, b, c) and N = (a, d, b) share the edge ab.
    const Vec3 a{0.75, 1.25, 0.75}, b{1.25, -1, -1}, c{-1, 1, -0.75}, d{-1, -1, 0.75};
    const TriangleId f{0, 0}, n{0, 1};
    Vec3 inward = glm::normalize(glm::cross(b - a, c - a));
    if (glm::dot(inward, d - a) < 0) inward = -inward;
    // Where the ray o + t dir crosses N's plane, and whether inside N
    // (Moller-Trumbore, in double, in the model's space).
    auto through_n = [&](const Vec3& o, const Vec3& dir, double& t) {
        const Vec3 e1 = d - a, e2 = b - a, pv = glm::cross(dir, e2), tv = o - a,
                   qv = glm::cross(tv, e1);
        const double det = glm::dot(e1, pv), u = glm::dot(tv, pv) / det,
                     v = glm::dot(dir, qv) / det;
        t = glm::dot(e2, qv) / det;
        return u >= 0 && v >= 0 && u + v <= 1;
    };
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> along(0.1, 0.9), exponent(-7, -5.5), jitter(-1, 1);
    int rays = 0, slipped = 0, slipped_together = 0, closest_elsewhere = 0;
    while (rays < 2000) {
        const double w = std::pow(10.0, exponent(rng)), w_n = std::pow(10.0, exponent(rng));
        const double x = along(rng);
        const Vec3 point = (1 - w) * (a + x * (b - a)) + w * c;
        const Vec3 aim = (1 - w_n) * (a + (x + w * jitter(rng)) * (b - a)) + w_n * d;
        const Vec3 dir = glm::normalize(aim - point);
        const Vec3 from = point + shift;
        const double lift = 1e-9 * std::max({std::abs(from.x), std::abs(from.y), std::abs(from.z)});
        const Vec3 origin = from + lift * inward;
        double t_point = 0, t_origin = 0;
        if (!through_n(point, dir, t_point) || !(t_point > lift) ||
            !through_n(origin - shift, dir, t_origin) || !(t_origin > 0))
            continue;
        ++rays;
        const Departure leaving{f, from};
        Hit hit;
        if (!closest_hit(geometry, origin, dir, 0.0, hit, nullptr, leaving) || hit.triangle != n)
            ++closest_elsewhere;
        if (!occluded(geometry, origin, dir, 0.0, 100.0, nullptr, nullptr, leaving)) ++slipped;
        const ShadowRay ray{origin, dir, 0.0, 100.0};
        bool blocked = false;
        occluded_together(geometry, std::span(&ray, 1), &blocked, nullptr, leaving);
        if (!blocked) ++slipped_together;
    }
    EXPECT_EQ(closest_elsewhere, 0);
    EXPECT_EQ(slipped, 0) << "of " << rays;
    EXPECT_EQ(slipped_together, 0) << "of " << rays;
}

// An octahedron scaled past Embree's float range (3e18) is walked on its own
// (TriangleGeometry::far_instances): rays aimed exactly at its shared vertices
// and edges still never slip through, and meet it where they aim.
TEST(Triangles, AMeshPastEmbreesReachIsWatertight) {
    ScratchDir dir;
    Scene s = scene_with_camera(camera_at({0, 0, 0}, {0, 0, -1}));
    Primitive huge = mesh(octahedron(dir.path()));
    huge.transforms = {rotate(TransformKind::yrotate, 30), scale({1e9, 1e9, 1e9}),
                       scale({1e9, 1e9, 1e9}), scale({3, 3, 3})};
    s.primitives.push_back(huge);
    auto prepared = prepare_scene(s).value();
    ASSERT_EQ(prepared->geometry->triangles->far_instances.size(), 1u);
    const double size = 3e18;
    const double c = std::cos(M_PI / 6), sn = std::sin(M_PI / 6);
    auto turn = [&](const Vec3& v) { return Vec3{c * v.x + sn * v.z, v.y, -sn * v.x + c * v.z}; };
    const std::vector<Vec3> corners{{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                    {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
    std::vector<Vec3> targets = corners;
    for (std::size_t i = 0; i < corners.size(); ++i)
        for (std::size_t j = i + 1; j < corners.size(); ++j)
            if (corners[i] != -corners[j]) targets.push_back(0.5 * (corners[i] + corners[j]));
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> tilt(-0.25, 0.25);
    int misses = 0, rays = 0;
    for (int k = 0; k < 100; ++k) {
        for (const Vec3& target : targets) {
            const Vec3 out =
                glm::normalize(glm::normalize(target) + Vec3(tilt(rng), tilt(rng), tilt(rng)));
            const Vec3 placed = size * turn(target);
            const Vec3 origin = placed + 7.0 * size * turn(out);
            Hit hit;
            ++rays;
            if (!closest_hit(*prepared->geometry, origin, placed - origin, 0.0, hit)) {
                ++misses;
                continue;
            }
            EXPECT_NEAR(hit.t, 1.0, 1e-9);
            EXPECT_TRUE(occluded(*prepared->geometry, origin, placed - origin, 0.0, 1.0 + 1e-9));
            EXPECT_FALSE(occluded(*prepared->geometry, origin, placed - origin, 0.0, 1.0 - 1e-9));
        }
    }
    EXPECT_EQ(misses, 0) << "of " << rays;
}

// A random scene's (differential seed 1.2-normals 460): a tetrahedron
// stretched about 600 times more along one axis than another, and a reflected
// ray that passes 3e-6 (in barycentric terms) inside the edge two of its
// faces share, through a corner of the solid. Embree's float move into the
// instance's space erred by 3e-5, and the ray missed both faces; the
// reference meets the nearer one. A map so ill-conditioned has its rays moved
// in double precision instead.
TEST(Triangles, AnIllConditionedMeshIsMetNearItsEdges) {
    ScratchDir dir;
    auto prepared = prepared_mesh(
        dir.path(), kTetrahedron,
        {scale(Vec3(9.64063685567787)), rotate(TransformKind::yrotate, 34.945434113689146),
         scale({118.98901232279036, 137.75951600311862, 171.44186551255808}),
         scale({0.0016165992815658072, 0.015777376647418778, 0.6650916654087091}),
         rotate(TransformKind::yrotate, 39.10633567795952),
         translate({-387.18579221517655, 41.817545423635636, -490.10194747416307})});
    const Vec3 origin{0.55721115204689875, 47.174279860472055, 16.551563000012983};
    const Vec3 direction{0.76349230764833165, -0.56015806689366721, 0.32140696360809529};
    Hit hit;
    ASSERT_TRUE(closest_hit(*prepared->geometry, origin, direction, 0.0, hit));
    EXPECT_NEAR(hit.t, 46.9694511, 1e-6);
    EXPECT_TRUE(occluded(*prepared->geometry, origin, direction, 0.0, 47.0));
}

// A random scene's (differential seed 1.1 826): two faces of a mesh meeting
// at a ridge, the mesh squashed about 1e-3 thin and so ill-conditioned that
// it is walked on its own, and a shadow ray that crosses the ridge, 1e-5 and
// 5e-4 (barycentric) inside the two faces. Moved into the model's space, the
// ray's start lay 400 model sizes away, where a float rounds by 3e-5; the
// ray, started there, passed outside both faces.
TEST(Triangles, ARayFromFarOffCrossesARidgeOfAnIllConditionedMesh) {
    ScratchDir dir;
    auto prepared = prepared_mesh(
        dir.path(),
        "v 1.25 0 0.25\nv 0 1 -0.25\nv 0 0 1\nv -0.25 0.25 -1\n"
        "f 1 2 3\nf 2 1 4\n",
        {scale(Vec3(1131.8823735734179)), rotate(TransformKind::zrotate, 50.360224365951865),
         rotate(TransformKind::xrotate, 219.77232076200232),
         scale({0.52879878672746583, 55.724243021772345, 0.0012129687815898491}),
         translate({176.52827709637091, 38369.012926038988, 61.318712039527476})});
    ASSERT_EQ(prepared->geometry->triangles->far_instances.size(), 1u);
    const Vec3 origin{186.84590082234729, 1336.1477506009321, 717.69544907414445};
    const Vec3 light{832.61665833632992, 1068.2992760750931, -529.00094949631796};
    const Vec3 direction = glm::normalize(light - origin);
    Hit hit;
    const bool met = closest_hit(*prepared->geometry, origin, direction, 0.0, hit);
    EXPECT_TRUE(met);
    if (met) {
        EXPECT_NEAR(hit.t, 753.682811, 1e-6);
    }
    EXPECT_TRUE(occluded(*prepared->geometry, origin, direction, 0.0, glm::length(light - origin)));
}

// The octahedron in material m, flat, under `transforms`, seen by a 9 x 9
// camera with a field of 10 degrees, lit by white ambient light and one white
// point light.
Scene flat_octahedron(const std::filesystem::path& dir, const Material& m,
                      std::vector<TransformOp> transforms, const Camera& camera,
                      const Vec3& light) {
    Scene s = scene_with_camera(camera, 9, 9);
    s.settings.ambient_light = Colour(1.0);
    Primitive p = mesh(octahedron(dir), m, kFlatShading);
    p.transforms = std::move(transforms);
    s.primitives.push_back(p);
    s.lights.push_back({light, Colour(1.0)});
    return s;
}

// The octahedron scaled 0.75, flat, seen along an axis from 5 away with a
// light at 9 behind the camera. The centre pixel's ray meets the vertex on
// that axis exactly, where four faces meet; each faces the light at
// dot(N, L) = 1/sqrt(3), so the vertex is lit as every face near it.
TEST(Triangles, AVertexSharedByFlatFacesIsLitAsTheFacesAroundIt) {
    ScratchDir dir;
    Material m;
    m.pigment = {1.0, 0.16, 0.25};
    m.finish.edit().ambient = Colour(0.12);
    m.finish.edit().diffuse = Colour(0.4);
    const Rgb lit = expected(0.12 * m.pigment + 0.4 * m.pigment / std::sqrt(3.0));
    const Vec3 axes[] = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
    for (const Vec3& axis : axes) {
        const Vec3 up = axis.y == 0 ? Vec3(0, 1, 0) : Vec3(0, 0, 1);
        const Image8 image =
            render(flat_octahedron(dir.path(), m, {scale(Vec3(0.75))},
                                   camera_at(5.0 * axis, {0, 0, 0}, up, 10.0), 9.0 * axis));
        EXPECT_EQ(at(image, 4, 4), lit)
            << "the vertex at " << 0.75 * axis.x << ", " << 0.75 * axis.y << ", " << 0.75 * axis.z;
        // Its neighbours, 0.1 off the vertex on one face each, see the light
        // a little more than a degree off the axis.
        for (const auto& [x, y] : {std::pair{3, 4}, {5, 4}, {4, 3}, {4, 5}}) {
            const Rgb c = at(image, x, y);
            EXPECT_NEAR(c.r, lit.r, 2) << x << ", " << y;
            EXPECT_NEAR(c.g, lit.g, 2) << x << ", " << y;
        }
    }
}

// The octahedron squashed to a quarter of its height, flat: at its top vertex
// V = (0, 0, 0.25) the four faces have outward normals (+-1, +-1, 4) / sqrt(18),
// each less than 90 degrees from every other, so V lifted along any face's
// inward normal lies inside the solid. A horizontal ray through V only touches
// the solid there: the faces it leaves behind turn their backs to it. The
// light, up and back toward the camera, lights every face at V (the back
// faces from their inner side) and the segment to it touches the solid only at
// V, so whichever face the ray meets there is lit: a back face's shadow ray,
// lifted into the solid, must not be stopped by the faces around V on its way
// out (docs/language.md §13.5: P lies on all of them).
TEST(Triangles, ASilhouetteVertexIsLitOnWhicheverFaceTheRayMeetsThere) {
    ScratchDir dir;
    Material m;
    m.pigment = {1.0, 0.5, 0.25};
    m.finish.edit().ambient = Colour(0.1);
    m.finish.edit().diffuse = Colour(0.8);
    const Vec3 top{0, 0, 0.25};
    int back_faces = 0;
    for (const double degrees : {0, 20, 70, 90, 110, 160, 180, 200, 250, 270, 290, 340}) {
        const double a = degrees * M_PI / 180;
        const Vec3 d{std::cos(a), std::sin(a), 0};
        const Vec3 l = glm::normalize(-d + Vec3(0, 0, 0.05));
        Scene s = flat_octahedron(dir.path(), m, {scale({1, 1, 0.25})},
                                  camera_at(top - 5.0 * d, top, {0, 0, 1}, 10.0), top + 9.0 * l);
        s.settings.background = {0, 0, 1};
        // The value of each face at V; none is the ambient term alone.
        std::vector<Rgb> lit;
        for (const double x : {-1.0, 1.0})
            for (const double y : {-1.0, 1.0}) {
                const Vec3 n = glm::normalize(Vec3(x, y, 4));
                const double facing = glm::dot(n, d) > 0 ? -glm::dot(n, l) : glm::dot(n, l);
                ASSERT_GT(facing, 0.05) << degrees;
                lit.push_back(expected(0.1 * m.pigment + 0.8 * facing * m.pigment));
                if (glm::dot(n, d) > 0) ++back_faces;
            }
        const Rgb c = at(render(s), 4, 4);
        const bool as_a_face = std::any_of(lit.begin(), lit.end(), [&](const Rgb& v) {
            return std::abs(c.r - v.r) <= 1 && std::abs(c.g - v.g) <= 1 && std::abs(c.b - v.b) <= 1;
        });
        EXPECT_TRUE(as_a_face) << "seen along " << degrees << " degrees: " << c
                               << "; ambient alone is " << expected(0.1 * m.pigment);
    }
    EXPECT_EQ(back_faces, 24);
}

// A ray leaving a mesh's surface never meets it again at its start (no acne):
// a lit sphere-like mesh renders no dark specks where the light faces it.
TEST(Triangles, SecondaryRaysDoNotMeetTheirOwnSurface) {
    ScratchDir dir;
    Scene s = scene_with_camera(camera_at({0, 0, 6}, {0, 0, 0}), 64, 64);
    s.primitives.push_back(mesh(octahedron(dir.path()), matte(Colour(1.0)), kFlatShading));
    s.lights.push_back({{0, 0, 100}, Colour(1.0)});
    const Image8 image = render(s);
    // The octahedron's outline is a diamond about 13 pixels from the centre to
    // a corner; every pixel well inside it sees a face turned toward the light.
    int dark = 0, lit = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const Rgb c = at(image, x, y);
            if (c.r > 0) ++lit;
            if (c.r == 0 && std::abs(x - 31.5) + std::abs(y - 31.5) < 11) ++dark;
        }
    EXPECT_GT(lit, 250);
    EXPECT_EQ(dark, 0);
}

// Preparing again after the model file changed reads it again; an unchanged
// one keeps the previous geometry.
TEST(Triangles, AChangedModelFileIsReadAgainWhenPreparedAgain) {
    ScratchDir dir;
    const auto model = facing_triangle(dir.path(), "");
    const Scene s = lit_head_on(model, kFlatShading);
    auto first = prepare_scene(s).value();
    auto same = prepare_scene(s, first).value();
    EXPECT_EQ(same->geometry, first->geometry);
    write_file(model, "v -1 -1 -3\nv 3 -1 -3\nv -1 3 -3\nv 0 0 -9\nf 1 2 3\n");
    auto changed = prepare_scene(s, first).value();
    EXPECT_NE(changed->geometry, first->geometry);
    Hit hit;
    ASSERT_TRUE(closest_hit(*changed->geometry, {0, 0, 0}, {0, 0, -1}, 0.0, hit));
    EXPECT_NEAR(hit.t, 3.0, 1e-12);
}

TEST(Triangles, AMissingModelFailsPreparation) {
    Scene s = scene_with_camera(camera_at({0, 0, 0}, {0, 0, -1}));
    s.primitives.push_back(mesh("/nonexistent/model.obj"));
    auto prepared = prepare_scene(s);
    ASSERT_FALSE(prepared.has_value());
    EXPECT_NE(prepared.error().message.find("model.obj"), std::string::npos);
}

}  // namespace
}  // namespace jt::test
