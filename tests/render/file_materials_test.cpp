// Materials from the model file (docs/language.md §14.5), worked out by hand:
// a surface facing the camera with ambient 1 under ambient light 1 and no
// light shows its pigment exactly, so each pixel is the quantised pigment:
// OBJ Kd and map_Kd per usemtl part, faces outside any part, glTF's base
// colour factor and texture held three ways, and vertex colours (PLY, OBJ).

#include "common/files.hpp"
#include "common/material_models.hpp"
#include "common/scratch_dir.hpp"
#include "jtracer/bmp.hpp"
#include "jtracer/png.hpp"
#include "scene_builder.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace jt::test {
namespace {

namespace fs = std::filesystem;

const Colour kBlock(0.2, 0.4, 0.6);  // the mesh block's own pigment

// The pixel of a 1x1 image whose one ray runs straight down -z through (x, y).
Rgb probe(const fs::path& file, std::string_view materials, double x, double y,
          const Material& m = glowing(kBlock)) {
    Scene s = scene_with_camera(camera_at({x, y, 10}, {x, y, 0}, {0, 1, 0}, 1.0));
    s.settings.ambient_light = Colour(1.0);
    s.settings.background = Colour(0.0);
    Mesh mesh;
    mesh.file = file.string();
    mesh.materials = std::string(materials);
    s.primitives.push_back(Primitive{mesh, m, {}});
    return at(render(s), 0, 0);
}

// A picture of two texels: (200, 100, 50) on the left, (10, 20, 30) on the right.
Image8 two_texels() {
    Image8 image(2, 1);
    const std::uint8_t texels[] = {200, 100, 50, 10, 20, 30};
    std::copy(std::begin(texels), std::end(texels), image.rgb.begin());
    return image;
}

Colour texel(int r, int g, int b) {
    return {static_cast<float>(r) / 255.0f, static_cast<float>(g) / 255.0f,
            static_cast<float>(b) / 255.0f};
}

// Six squares along x, 2 wide: [-6, -4] before any usemtl, then red, an
// unknown name, a textured material, one with neither Kd nor map_Kd, and a
// BMP-textured one. Every corner at uv (0.25, 0.5): the left texel exactly.
fs::path write_parts_obj(const fs::path& dir) {
    std::string obj = "mtllib m.mtl\nvt 0.25 0.5\n";
    const char* parts[] = {nullptr, "red", "nosuch", "painted", "plain", "bitmap"};
    for (int k = 0; k < 6; ++k) {
        const int x0 = -6 + 2 * k;
        for (const auto& [x, y] : {std::pair{x0, -1}, {x0 + 2, -1}, {x0 + 2, 1}, {x0, 1}})
            obj += "v " + std::to_string(x) + " " + std::to_string(y) + " 0\n";
        if (parts[k]) obj += std::string("usemtl ") + parts[k] + "\n";
        const int v = 4 * k + 1;
        obj += "f " + std::to_string(v) + "/1 " + std::to_string(v + 1) + "/1 " +
               std::to_string(v + 2) + "/1 " + std::to_string(v + 3) + "/1\n";
    }
    write_file(dir / "m.obj", obj);
    write_file(dir / "m.mtl",
               "newmtl red\nKd 0.8 0.4 0.2\n"
               "newmtl painted\nKd 0.5 1 1\nmap_Kd -s 1 1 1 -clamp on maps/pic.png\n"
               "newmtl plain\nNs 10\n"
               "newmtl bitmap\nmap_Kd pic.bmp\n");
    fs::create_directories(dir / "maps");
    EXPECT_TRUE(write_png(dir / "maps/pic.png", two_texels()));
    EXPECT_TRUE(write_bmp(dir / "pic.bmp", two_texels()));
    return dir / "m.obj";
}

// The square starting at x0, away from its diagonal.
double square(int k) {
    return -6 + 2 * k + 1.5;
}

TEST(FileMaterials, ObjPartsTakeKdAndMapKdAndTheRestKeepTheBlock) {
    ScratchDir dir;
    const fs::path obj = write_parts_obj(dir.path());
    EXPECT_EQ(probe(obj, "file", square(0), -0.3), expected(kBlock));  // before any usemtl
    EXPECT_EQ(probe(obj, "file", square(1), -0.3), expected({0.8, 0.4, 0.2}));
    EXPECT_EQ(probe(obj, "file", square(2), -0.3), expected(kBlock));  // unknown name
    EXPECT_EQ(probe(obj, "file", square(3), -0.3),
              expected(texel(200, 100, 50) * Colour(0.5, 1.0, 1.0)));
    EXPECT_EQ(probe(obj, "file", square(4), -0.3), expected(Colour(1.0)));  // no Kd: 1
    EXPECT_EQ(probe(obj, "file", square(5), -0.3), expected(texel(200, 100, 50)));
    // A part's colours replace the block's pattern too; (-2.5, 0.3) lies in an
    // odd cube of a checker of size 1, which "scene" shows.
    Material checkered = glowing(kBlock);
    checkered.finish.edit().checker = Colour(0.9, 0.1, 0.1);
    EXPECT_EQ(probe(obj, "file", square(1), 0.3, checkered), expected({0.8, 0.4, 0.2}));
    EXPECT_EQ(probe(obj, "scene", square(1), 0.3, checkered), expected(*checkered.finish->checker));
    // "scene" (the default): the block everywhere, as in language 1.1.
    for (int k = 0; k < 6; ++k) {
        SCOPED_TRACE(k);
        EXPECT_EQ(probe(obj, "scene", square(k), -0.3), expected(kBlock));
    }
}

// The triangle (0, 0), (4, 0), (0, 4) seen at (1, 0.5): barycentric weights
// w = 0.625, u = 0.25, v = 0.125 of its three corners.
constexpr double kW = 0.625, kU = 0.25, kV = 0.125;

TEST(FileMaterials, ObjVertexColoursBlendAndClip) {
    ScratchDir dir;
    write_file(dir.path() / "c.obj", "v 0 0 0 2 0 -1\nv 4 0 0 0 1 0\nv 0 4 0 0 0 0.6\nf 1 2 3\n");
    const Colour blend =
        kW * Colour(1, 0, 0) + kU * Colour(0, 1, 0) + kV * Colour(0, 0, static_cast<double>(0.6f));
    EXPECT_EQ(probe(dir.path() / "c.obj", "file", 1.0, 0.5), expected(blend));
    EXPECT_EQ(probe(dir.path() / "c.obj", "scene", 1.0, 0.5), expected(kBlock));
    // With a material of the library: vertex colour x base colour.
    write_file(dir.path() / "k.mtl", "newmtl tint\nKd 0.5 0.5 0.5\n");
    write_file(dir.path() / "k.obj",
               "mtllib k.mtl\nusemtl tint\n" + read_file(dir.path() / "c.obj"));
    EXPECT_EQ(probe(dir.path() / "k.obj", "file", 1.0, 0.5), expected(blend * Colour(0.5)));
}

TEST(FileMaterials, PlyVertexColoursAreBytesOver255) {
    ScratchDir dir;
    write_file(dir.path() / "c.ply",
               "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
               "property float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
               "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
               "0 0 0 255 0 0\n4 0 0 0 255 0\n0 4 0 0 0 153\n3 0 1 2\n");
    const Colour blend = kW * Colour(1, 0, 0) + kU * Colour(0, 1, 0) +
                         kV * Colour(0, 0, static_cast<double>(153.0f / 255.0f));
    EXPECT_EQ(probe(dir.path() / "c.ply", "file", 1.0, 0.5), expected(blend));
    EXPECT_EQ(probe(dir.path() / "c.ply", "scene", 1.0, 0.5), expected(kBlock));
}

// A picture one texel wide: (200, 100, 50) on top, (10, 20, 30) below (an
// Image8's row 0 is its bottom). glTF's v = 0.25 is a quarter down from the
// top: v = 0.75 in the language, the top texel's centre.
Image8 top_and_bottom() {
    Image8 image(1, 2);
    const std::uint8_t texels[] = {10, 20, 30, 200, 100, 50};
    std::copy(std::begin(texels), std::end(texels), image.rgb.begin());
    return image;
}

TEST(FileMaterials, GltfBaseColourTimesTextureHoweverThePictureIsHeld) {
    const Colour factor(0.5, 0.25, 1.0);
    for (const GltfPicture how :
         {GltfPicture::external, GltfPicture::in_glb, GltfPicture::data_uri}) {
        SCOPED_TRACE(static_cast<int>(how));
        ScratchDir dir;
        const fs::path file =
            dir.path() / (how == GltfPicture::in_glb ? "painted.glb" : "painted.gltf");
        write_painted_gltf(file, how, top_and_bottom(), factor, 0.3, 0.25);
        EXPECT_EQ(probe(file, "file", -2.0, -1.0), expected(texel(200, 100, 50) * factor));
        EXPECT_EQ(probe(file, "file", 2.0, -1.0), expected(kBlock));  // no material
        EXPECT_EQ(probe(file, "scene", -2.0, -1.0), expected(kBlock));
    }
}

// Real models of Assimp's test set (assimp-testmodels), looked at: glTF's
// BoxTextured with its picture beside it, in a .glb and in a data URI gives
// one image, byte for byte; the spider OBJ's four textured parts leave no
// pixel of the block's magenta.
Image8 render_model(const fs::path& file, std::string_view materials, const Vec3& eye) {
    Scene s = scene_with_camera(camera_at(eye, {0, 0, 0}, {0, 1, 0}, 45.0, 1.0), 48, 48);
    s.settings.ambient_light = Colour(0.4);
    Material m = glowing(Colour(1, 0, 1));
    m.finish.edit().diffuse = Colour(0.7);
    Mesh mesh;
    mesh.file = file.string();
    mesh.materials = std::string(materials);
    s.primitives.push_back(Primitive{mesh, m, {}});
    s.lights.push_back(PointLight{eye * 2.0, Colour(0.8)});
    return render(s);
}

int magenta_pixels(const Image8& image) {
    int n = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const Rgb c = at(image, x, y);
            n += c.r > 100 && c.g < 30 && c.b > 100;
        }
    return n;
}

TEST(FileMaterials, AssimpsTexturedModelsRenderWithTheirOwnColours) {
    const fs::path models = "/usr/share/assimp/models";
    if (!fs::exists(models / "OBJ/spider.obj")) GTEST_SKIP() << "assimp-testmodels is missing";
    const fs::path box = models / "glTF2";
    const Vec3 eye(1.5, 1.2, 2.0);
    const Image8 external = render_model(box / "BoxTextured-glTF/BoxTextured.gltf", "file", eye);
    EXPECT_EQ(render_model(box / "BoxTextured-glTF-Binary/BoxTextured.glb", "file", eye), external);
    EXPECT_EQ(render_model(box / "BoxTextured-glTF-Embedded/BoxTextured.gltf", "file", eye),
              external);
    EXPECT_EQ(magenta_pixels(external), 0);
    EXPECT_GT(magenta_pixels(render_model(box / "BoxTextured-glTF/BoxTextured.gltf", "scene", eye)),
              100);
    const Image8 spider = render_model(models / "OBJ/spider.obj", "file", {0, 60, 160});
    EXPECT_EQ(magenta_pixels(spider), 0);
    EXPECT_GT(magenta_pixels(render_model(models / "OBJ/spider.obj", "scene", {0, 60, 160})), 100);
}

}  // namespace
}  // namespace jt::test
