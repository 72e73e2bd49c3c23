// A mesh's materials read from its file (docs/language.md §14.5): the parts a
// model is read with, and the errors a scene with `materials: "file"` gets at
// the mesh's `file` string when a material library or a texture cannot be
// read; with "scene" the same files change nothing.

#include "common/files.hpp"
#include "common/material_models.hpp"
#include "common/scratch_dir.hpp"
#include "jtracer/model_file.hpp"
#include "jtracer/png.hpp"
#include "jtracer/scene_file.hpp"
#include "jtracer/validate.hpp"
#include "test_util.hpp"

#include <filesystem>

namespace jt {
namespace {

namespace fs = std::filesystem;
using test::brief;
using test::write_file;

Image8 one_texel() {
    Image8 image(1, 1);
    image.rgb = {200, 100, 50};
    return image;
}

constexpr std::string_view kQuads =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
    "f 1 2 3\n"
    "usemtl red\nf 1 3 4\nf 1 2 4\n"
    "usemtl other\nf 2 3 4\n"
    "usemtl red\nf 1 2 3 4\n";

TEST(ModelMaterials, ObjPartsInTheOrderFirstUsed) {
    test::ScratchDir dir;
    write_file(dir.path() / "m.obj", "mtllib m.mtl\n" + std::string(kQuads));
    write_file(dir.path() / "m.mtl",
               "newmtl red\nKd 1 0 0  # a comment\nmap_Kd -o 0.5 0.5 -bm 1 pic.png\n");
    ASSERT_TRUE(write_png(dir.path() / "pic.png", one_texel()));
    const Expected<Model> model = read_model(dir.path() / "m.obj", dir.path(), true);
    ASSERT_TRUE(model.has_value()) << model.error().message;
    ASSERT_EQ(model->parts.size(), 2u);
    EXPECT_EQ(model->parts[0].name, "");  // before any usemtl, and "other" (unknown)
    EXPECT_FALSE(model->parts[0].has_material);
    EXPECT_EQ(model->parts[1].name, "red");
    EXPECT_TRUE(model->parts[1].has_material);
    EXPECT_EQ(model->parts[1].base, Colour(1, 0, 0));
    EXPECT_EQ(model->parts[1].texture_name, "pic.png");
    ASSERT_NE(model->parts[1].texture, nullptr);
    EXPECT_EQ(model->parts[1].texture->width, 1);
    EXPECT_EQ(model->part_of, (std::vector<std::uint32_t>{0, 1, 1, 0, 1, 1}));
    EXPECT_TRUE(model->colours.empty());

    // Without "file": nothing of it is read.
    const Expected<Model> plain = read_model(dir.path() / "m.obj", dir.path());
    ASSERT_TRUE(plain.has_value());
    EXPECT_TRUE(plain->parts.empty());
    EXPECT_TRUE(plain->part_of.empty());
    EXPECT_EQ(plain->triangles, model->triangles);
}

TEST(ModelMaterials, AMapKdFileNameMayHoldBlanks) {
    test::ScratchDir dir;
    const std::string obj = "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl x\nf 1 2 3\n";
    write_file(dir.path() / "m.obj", obj);
    ASSERT_TRUE(write_png(dir.path() / "my photo.png", one_texel()));
    ASSERT_TRUE(write_png(dir.path() / "photo.png", Image8(2, 2)));
    struct Case {
        const char* line;
        const char* read;
    };
    for (const Case& c : {Case{"map_Kd my photo.png", "my photo.png"},
                          Case{"map_Kd -s 1 1 1 -clamp on  my photo.png  ", "my photo.png"},
                          Case{"map_Kd -o 0.5 -bm 0.2 my photo.png", "my photo.png"},
                          Case{"map_Kd -mm 0 1 my\\photo.png", "my/photo.png"},
                          // An option this reader does not know: the last word, as before.
                          Case{"map_Kd -halo 3 photo.png", "photo.png"}}) {
        SCOPED_TRACE(c.line);
        if (std::string(c.read) == "my/photo.png") {
            fs::create_directories(dir.path() / "my");
            ASSERT_TRUE(write_png(dir.path() / "my" / "photo.png", one_texel()));
        }
        write_file(dir.path() / "m.mtl", std::string("newmtl x\n") + c.line + "\n");
        const Expected<Model> model = read_model(dir.path() / "m.obj", dir.path(), true);
        ASSERT_TRUE(model.has_value()) << model.error().message;
        ASSERT_EQ(model->parts.size(), 1u);
        EXPECT_EQ(model->parts[0].texture_name, c.read);
        ASSERT_NE(model->parts[0].texture, nullptr);
    }
    // A name that reads as no file: the error names the whole name and the
    // line, and photo.png, its last word, is not read in its place.
    write_file(dir.path() / "m.mtl", "newmtl x\nKd 1 1 1\nmap_Kd -bm 1 my lost photo.png\n");
    const Expected<Model> model = read_model(dir.path() / "m.obj", dir.path(), true);
    ASSERT_FALSE(model.has_value());
    EXPECT_NE(model.error().message.find("its texture 'my lost photo.png': cannot read '"),
              std::string::npos)
        << model.error().message;
    EXPECT_NE(model.error().message.find("(map_Kd on line 3 of '" +
                                         (dir.path() / "m.mtl").string() + "')"),
              std::string::npos)
        << model.error().message;
}

TEST(ModelMaterials, GltfPartsNameTheirPicture) {
    test::ScratchDir dir;
    struct Case {
        test::GltfPicture how;
        const char* file;
        const char* texture;
    };
    for (const Case& c : {Case{test::GltfPicture::external, "a.gltf", "picture.png"},
                          Case{test::GltfPicture::in_glb, "a.glb", "embedded image 0"},
                          Case{test::GltfPicture::data_uri, "b.gltf", "embedded image 0"}}) {
        SCOPED_TRACE(c.file);
        test::write_painted_gltf(dir.path() / c.file, c.how, one_texel(), {0.5, 0.25, 1.0}, 0, 0);
        const Expected<Model> model = read_model(dir.path() / c.file, dir.path(), true);
        ASSERT_TRUE(model.has_value()) << model.error().message;
        ASSERT_EQ(model->parts.size(), 2u);
        EXPECT_EQ(model->parts[0].name, "painted");
        EXPECT_EQ(model->parts[0].base, Colour(0.5, 0.25, 1.0));
        EXPECT_EQ(model->parts[0].texture_name, c.texture);
        EXPECT_NE(model->parts[0].texture, nullptr);
        EXPECT_FALSE(model->parts[1].has_material);  // the primitive without a material
        EXPECT_EQ(model->part_of, (std::vector<std::uint32_t>{0, 1}));
    }
}

TEST(ModelMaterials, VertexColoursAreClippedAndMissingOnesMarked) {
    test::ScratchDir dir;
    // Values outside [0, 1] are clipped; a part without a material but with
    // vertex colours is still coloured from the file.
    write_file(dir.path() / "c.obj", "v 0 0 0 2 -1 0.5\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nf 1 2 3\n");
    const Expected<Model> model = read_model(dir.path() / "c.obj", dir.path(), true);
    ASSERT_TRUE(model.has_value()) << model.error().message;
    ASSERT_EQ(model->colours.size(), 3u);
    EXPECT_EQ(model->colours[0], glm::vec3(1.0f, 0.0f, 0.5f));
    ASSERT_EQ(model->parts.size(), 1u);
    EXPECT_TRUE(model->parts[0].vertex_colours);
    EXPECT_FALSE(model->parts[0].has_material);
}

// The errors a scene gets: at the mesh's `file` string, naming the file that
// cannot be read; with "scene", none (flat shading: the models have no normals).
std::string check(const fs::path& folder, const std::string& model, const char* materials) {
    write_file(folder / "s.jts",
               "render_settings { width: 4; height: 4; }\n"
               "cameras { perspective_camera { } }\n"
               "scene {\n  mesh { file: \"" +
                   model + "\"; shading: \"flat\"; materials: \"" + materials + "\"; }\n}\n");
    Expected<LoadedScene> loaded = load_scene_file(folder / "s.jts");
    if (!loaded) return "not loaded: " + loaded.error().message;
    return brief(check_scene(*loaded));
}

TEST(ModelMaterials, ALibraryOrTextureThatCannotBeReadIsAnErrorAtTheFileString) {
    test::ScratchDir dir;
    const fs::path scene = dir.path() / "scene";
    fs::create_directories(scene);
    const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl x\nf 1 2 3\n";

    write_file(scene / "missing.obj", "mtllib none.mtl\n" + obj);
    std::string e = check(scene, "missing.obj", "file");
    EXPECT_EQ(e.rfind("4:16: error: mesh 1: '", 0), 0u) << e;
    EXPECT_NE(e.find("its material library '"), std::string::npos) << e;
    EXPECT_NE(e.find("none.mtl' cannot be read (no such file)"), std::string::npos) << e;
    EXPECT_EQ(check(scene, "missing.obj", "scene"), "");

    write_file(dir.path() / "outside.mtl", "newmtl x\nKd 1 0 0\n");
    write_file(scene / "escape.obj", "mtllib ../outside.mtl\n" + obj);
    e = check(scene, "escape.obj", "file");
    EXPECT_EQ(e.rfind("4:16: error: mesh 1: '", 0), 0u) << e;
    EXPECT_NE(e.find("refers to the material library '"), std::string::npos) << e;
    EXPECT_NE(e.find("outside the folder"), std::string::npos) << e;
    e = check(scene, "escape.obj", "scene");  // as in 1.1: left out with a warning
    EXPECT_EQ(e.rfind("4:16: warning: mesh 1: 'escape.obj' refers to the material library", 0), 0u)
        << e;

    write_file(scene / "t.obj", "mtllib t.mtl\n" + obj);
    write_file(scene / "t.mtl", "newmtl x\nmap_Kd gone.png\n");
    e = check(scene, "t.obj", "file");
    EXPECT_EQ(e.rfind("4:16: error: mesh 1: '", 0), 0u) << e;
    EXPECT_NE(e.find("its texture 'gone.png': cannot read '"), std::string::npos) << e;
    EXPECT_EQ(check(scene, "t.obj", "scene"), "");

    ASSERT_TRUE(write_png(dir.path() / "secret.png", one_texel()));
    write_file(scene / "t.mtl", "newmtl x\nmap_Kd ../secret.png\n");
    e = check(scene, "t.obj", "file");
    EXPECT_NE(e.find("its texture '../secret.png' lies outside the folder '"), std::string::npos)
        << e;

    write_file(scene / "t.mtl", "newmtl x\nmap_Kd broken.png\n");
    write_file(scene / "broken.png", "\x89PNG\r\n\x1a\nnot really");
    e = check(scene, "t.obj", "file");
    EXPECT_NE(e.find("its texture 'broken.png': '"), std::string::npos) << e;

    write_file(scene / "t.mtl", "newmtl x\nKd 1 nan 0\n");
    e = check(scene, "t.obj", "file");
    EXPECT_NE(e.find("has a Kd that is not one or three finite numbers: 'Kd 1 nan 0'"),
              std::string::npos)
        << e;

    test::write_painted_gltf(scene / "g.gltf", test::GltfPicture::external, one_texel(),
                             Colour(1.0), 0, 0, "lost.png");
    fs::remove(scene / "lost.png");
    e = check(scene, "g.gltf", "file");
    EXPECT_EQ(e.rfind("4:16: error: mesh 1: '", 0), 0u) << e;
    EXPECT_NE(e.find("its texture 'lost.png': cannot read '"), std::string::npos) << e;
    EXPECT_EQ(check(scene, "g.gltf", "scene"), "");
}

}  // namespace
}  // namespace jt
