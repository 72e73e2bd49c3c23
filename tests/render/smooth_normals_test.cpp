// Generated smooth normals in the renderer (docs/language.md §14.4): a sphere
// tessellated without normals shades as the true sphere, a cube stays
// faceted at 60 degrees and goes round at 180, an STL of split vertices
// smooths exactly as the indexed OBJ of the same surface, the file's normals
// are kept, and the mesh's transform turns generated normals as it turns the
// file's. The models are written here, as text.

#include "common/files.hpp"
#include "common/scratch_dir.hpp"
#include "jtracer/png.hpp"
#include "render/prepared_scene.hpp"
#include "render/ray_queries.hpp"
#include "scene_builder.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace jt::test {
namespace {

namespace fs = std::filesystem;

struct Surface {
    std::vector<Vec3> positions;
    std::vector<std::array<int, 3>> triangles;  // counter-clockwise seen from outside
};

// An icosahedron split `levels` times, its vertices on the unit sphere.
Surface icosphere(int levels) {
    const double g = (1.0 + std::sqrt(5.0)) / 2.0;
    Surface s;
    for (const Vec3& p : {Vec3(-1, g, 0), Vec3(1, g, 0), Vec3(-1, -g, 0), Vec3(1, -g, 0),
                          Vec3(0, -1, g), Vec3(0, 1, g), Vec3(0, -1, -g), Vec3(0, 1, -g),
                          Vec3(g, 0, -1), Vec3(g, 0, 1), Vec3(-g, 0, -1), Vec3(-g, 0, 1)})
        s.positions.push_back(glm::normalize(p));
    s.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                   {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                   {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                   {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (int level = 0; level < levels; ++level) {
        std::map<std::pair<int, int>, int> middles;
        auto middle = [&](int a, int b) {
            const auto key = std::minmax(a, b);
            auto known = middles.find(key);
            if (known != middles.end()) return known->second;
            s.positions.push_back(glm::normalize(s.positions[a] + s.positions[b]));
            const int made = static_cast<int>(s.positions.size()) - 1;
            middles.emplace(key, made);
            return made;
        };
        std::vector<std::array<int, 3>> finer;
        for (const auto& t : s.triangles) {
            const int ab = middle(t[0], t[1]), bc = middle(t[1], t[2]), ca = middle(t[2], t[0]);
            finer.push_back({t[0], ab, ca});
            finer.push_back({t[1], bc, ab});
            finer.push_back({t[2], ca, bc});
            finer.push_back({ab, bc, ca});
        }
        s.triangles = std::move(finer);
    }
    return s;
}

// The cube [-1, 1]^3: 8 vertices, each face two triangles.
Surface cube() {
    Surface s;
    for (int i = 0; i < 8; ++i)
        s.positions.emplace_back(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                             {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) {
        s.triangles.push_back({q[0], q[1], q[2]});
        s.triangles.push_back({q[0], q[2], q[3]});
    }
    return s;
}

// Each coordinate as the same text in every file, so that the OBJ and the STL
// hold the same floats.
std::string point_text(const Vec3& p) {
    char text[96];
    std::snprintf(text, sizeof text, "%.9g %.9g %.9g", static_cast<double>(static_cast<float>(p.x)),
                  static_cast<double>(static_cast<float>(p.y)),
                  static_cast<double>(static_cast<float>(p.z)));
    return text;
}

// Shared vertices, indexed, no normals.
fs::path write_obj(const fs::path& file, const Surface& s) {
    std::string text;
    for (const Vec3& p : s.positions) text += "v " + point_text(p) + "\n";
    for (const auto& t : s.triangles)
        text += "f " + std::to_string(t[0] + 1) + " " + std::to_string(t[1] + 1) + " " +
                std::to_string(t[2] + 1) + "\n";
    write_file(file, text);
    return file;
}

// Every triangle's corners written out again, with a facet normal that is
// deliberately wrong: STL's facet normals are not used.
fs::path write_stl(const fs::path& file, const Surface& s) {
    std::string text = "solid surface\n";
    for (const auto& t : s.triangles) {
        text += "facet normal 1 0 0\nouter loop\n";
        for (int k : t) text += "vertex " + point_text(s.positions[k]) + "\n";
        text += "endloop\nendfacet\n";
    }
    write_file(file, text + "endsolid surface\n");
    return file;
}

Primitive mesh(const fs::path& file, std::optional<double> smooth_angle,
               std::string_view shading = kSmoothShading) {
    Mesh m;
    m.file = file.string();
    m.shading = std::string(shading);
    m.smooth_angle = smooth_angle;
    return Primitive{m, matte(Colour(1.0)), {}};
}

Scene scene_of(const Primitive& p) {
    Scene s = scene_with_camera(camera_at({0, 0, 5}, {0, 0, 0}));
    s.primitives.push_back(p);
    s.lights.push_back({{3, 4, 5}, Colour(1.0)});
    return s;
}

double degrees_between(const Vec3& a, const Vec3& b) {
    const double c = glm::dot(glm::normalize(a), glm::normalize(b));
    return std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / std::numbers::pi;
}

// Rays from far outside toward the origin, in directions spread over the sphere.
std::vector<Vec3> directions(int count) {
    std::mt19937 rng(29);
    std::normal_distribution<double> normal;
    std::vector<Vec3> out;
    while (static_cast<int>(out.size()) < count) {
        const Vec3 d(normal(rng), normal(rng), normal(rng));
        if (glm::length(d) > 1e-3) out.push_back(glm::normalize(d));
    }
    return out;
}

// The normal that shades each hit along rays toward the origin (the smooth
// one, or the geometric one when there is none), and where the hit lies.
struct Shaded {
    Vec3 point, normal;
    std::uint32_t triangle;  // its index in the model
};
std::vector<Shaded> shade_along(const Scene& scene, const std::vector<Vec3>& toward_origin) {
    auto prepared = prepare_scene(scene);
    EXPECT_TRUE(prepared.has_value());
    std::vector<Shaded> out;
    if (!prepared) return out;
    for (const Vec3& d : toward_origin) {
        Hit hit;
        const Vec3 origin = 4.0 * d;
        if (!closest_hit(*(*prepared)->geometry, origin, -d, 0.0, hit)) {
            ADD_FAILURE() << "no hit";
            continue;
        }
        out.push_back({origin - hit.t * d, hit.shading == Vec3(0.0) ? hit.normal : hit.shading,
                       hit.triangle.triangle});
    }
    return out;
}

void save_png(const Image8& image, const std::string& name) {
    const fs::path dir = fs::path(JT_ARTIFACT_DIR) / "smooth_normals";
    fs::create_directories(dir);
    EXPECT_TRUE(write_png(dir / name, image).has_value());
}

TEST(SmoothNormals, AnIcosphereWithoutNormalsShadesAsTheTrueSphere) {
    ScratchDir dir;
    const fs::path obj = write_obj(dir.path() / "ico.obj", icosphere(3));  // 1280 triangles
    const std::vector<Vec3> rays = directions(400);
    double smooth_worst = 0.0, flat_worst = 0.0;
    for (const Shaded& s : shade_along(scene_of(mesh(obj, 60.0)), rays))
        smooth_worst = std::max(smooth_worst, degrees_between(s.normal, s.point));
    for (const Shaded& s : shade_along(scene_of(mesh(obj, std::nullopt)), rays))
        flat_worst = std::max(flat_worst, degrees_between(s.normal, s.point));
    EXPECT_LT(smooth_worst, 1.0);
    EXPECT_GT(flat_worst, 3.0);
    // Under a scale the generated normals turn as file normals do (M^-T): on
    // the sphere stretched to an ellipsoid x^2/4 + y^2 + z^2 = 1 the true
    // normal at P is (P.x / 4, P.y, P.z).
    Primitive stretched = mesh(obj, 60.0);
    stretched.transforms = {scale({2, 1, 1})};
    double stretched_worst = 0.0;
    for (const Shaded& s : shade_along(scene_of(stretched), rays))
        stretched_worst =
            std::max(stretched_worst,
                     degrees_between(s.normal, Vec3(s.point.x / 4.0, s.point.y, s.point.z)));
    EXPECT_LT(stretched_worst, 2.0);

    Scene look = scene_of(mesh(obj, std::nullopt));
    look.settings.width = look.settings.height = 160;
    look.settings.ambient_light = Colour(0.2);
    look.primitives[0].material.finish.edit().ambient = Colour(1.0);
    save_png(render(look), "icosphere_flat.png");
    look.primitives[0] = mesh(obj, 60.0);
    look.primitives[0].material.finish.edit().ambient = Colour(1.0);
    save_png(render(look), "icosphere_smooth_angle_60.png");
}

// The outward normal of the cube's face that holds `p`.
Vec3 face_of(const Vec3& p) {
    const Vec3 a = glm::abs(p);
    if (a.x >= a.y && a.x >= a.z) return {p.x > 0 ? 1 : -1, 0, 0};
    if (a.y >= a.z) return {0, p.y > 0 ? 1 : -1, 0};
    return {0, 0, p.z > 0 ? 1 : -1};
}

TEST(SmoothNormals, ACubeStaysFacetedAt60AndGoesRoundAt180) {
    ScratchDir dir;
    const fs::path obj = write_obj(dir.path() / "cube.obj", cube());
    const std::vector<Vec3> rays = directions(300);
    for (const Shaded& s : shade_along(scene_of(mesh(obj, 60.0)), rays))
        EXPECT_LT(degrees_between(s.normal, face_of(s.point)), 1e-6);
    // At 180, near each corner of each face (0.9 of the way along both
    // edges) the normal leans far off the face, toward the corner's diagonal.
    std::vector<Vec3> near_corners;
    for (int corner = 0; corner < 8; ++corner)
        for (int axis = 0; axis < 3; ++axis) {
            Vec3 p(corner & 1 ? 0.9 : -0.9, corner & 2 ? 0.9 : -0.9, corner & 4 ? 0.9 : -0.9);
            p[axis] = p[axis] > 0 ? 1.0 : -1.0;
            near_corners.push_back(glm::normalize(p));
        }
    const std::vector<Shaded> round = shade_along(scene_of(mesh(obj, 180.0)), near_corners);
    ASSERT_EQ(round.size(), 24u);
    for (const Shaded& s : round) EXPECT_GT(degrees_between(s.normal, face_of(s.point)), 25.0);

    Scene look = scene_of(mesh(obj, 60.0));
    look.cameras[0] = camera_at({3, 2.5, 4}, {0, 0, 0});
    look.settings.width = look.settings.height = 160;
    const Image8 faceted = render(look);
    look.primitives[0] = mesh(obj, 180.0);
    const Image8 rounded = render(look);
    save_png(faceted, "cube_smooth_angle_60.png");
    save_png(rounded, "cube_smooth_angle_180.png");
    // At 60 the cube renders as flat shading does, to the byte.
    look.primitives[0] = mesh(obj, std::nullopt, kFlatShading);
    EXPECT_TRUE(render(look) == faceted);
    EXPECT_FALSE(rounded == faceted);
}

TEST(SmoothNormals, AnStlOfSplitVerticesSmoothsAsTheIndexedObj) {
    ScratchDir dir;
    const Surface surface = icosphere(2);
    const fs::path obj = write_obj(dir.path() / "ico.obj", surface);
    const fs::path stl = write_stl(dir.path() / "ico.stl", surface);
    const std::vector<Vec3> rays = directions(300);
    for (double angle : {10.0, 60.0, 180.0}) {
        const std::vector<Shaded> a = shade_along(scene_of(mesh(obj, angle)), rays);
        const std::vector<Shaded> b = shade_along(scene_of(mesh(stl, angle)), rays);
        ASSERT_EQ(a.size(), b.size());
        for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].normal, b[i].normal) << i;
        Scene sa = scene_of(mesh(obj, angle)), sb = scene_of(mesh(stl, angle));
        sa.settings.width = sa.settings.height = sb.settings.width = sb.settings.height = 48;
        EXPECT_TRUE(render(sa) == render(sb)) << angle;
    }
}

// A model with a normal at every corner renders with smooth_angle exactly as
// without; in one with some, the triangles that have all three keep them.
TEST(SmoothNormals, TheFilesNormalsAreKept) {
    ScratchDir dir;
    const Surface s = icosphere(1);
    std::string text;
    for (const Vec3& p : s.positions) text += "v " + point_text(p) + "\nvn " + point_text(p) + "\n";
    std::string mixed = text;
    for (std::size_t t = 0; t < s.triangles.size(); ++t) {
        std::string face = "f", bare = "f";
        for (int k : s.triangles[t]) {
            face += " " + std::to_string(k + 1) + "//" + std::to_string(k + 1);
            bare += " " + std::to_string(k + 1);
        }
        text += face + "\n";
        mixed += (t % 2 ? bare : face) + "\n";  // every other triangle without normals
    }
    write_file(dir.path() / "all.obj", text);
    write_file(dir.path() / "mixed.obj", mixed);
    Scene with = scene_of(mesh(dir.path() / "all.obj", 30.0));
    Scene without = scene_of(mesh(dir.path() / "all.obj", std::nullopt));
    with.settings.width = with.settings.height = without.settings.width = without.settings.height =
        64;
    EXPECT_TRUE(render(with) == render(without));

    const std::vector<Vec3> rays = directions(300);
    const std::vector<Shaded> a = shade_along(scene_of(mesh(dir.path() / "mixed.obj", 30.0)), rays);
    const std::vector<Shaded> b =
        shade_along(scene_of(mesh(dir.path() / "mixed.obj", std::nullopt)), rays);
    ASSERT_EQ(a.size(), b.size());
    int with_normals = 0, generated = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        ASSERT_EQ(a[i].triangle, b[i].triangle);
        if (a[i].triangle % 2 == 0) {
            ++with_normals;
            EXPECT_EQ(a[i].normal, b[i].normal);  // the file's blend, as in language 1.1
        } else {
            ++generated;
            EXPECT_NE(a[i].normal, b[i].normal);  // generated here, geometric there
        }
    }
    EXPECT_GT(with_normals, 50);
    EXPECT_GT(generated, 50);
}

}  // namespace
}  // namespace jt::test
