// The triangle and mesh blocks (docs/language.md §13.5): parsed, checked,
// written back, edited in place, and their model files checked by the
// validator at the `file` string.

#include "common/files.hpp"
#include "common/scratch_dir.hpp"
#include "jtracer/scene_file.hpp"
#include "jtracer/serializer.hpp"
#include "jtracer/source_edit.hpp"
#include "jtracer/validate.hpp"
#include "test_util.hpp"

#include <filesystem>

namespace jt {
namespace {

using test::brief;

constexpr std::string_view kHead =
    "render_settings { width: 4; height: 4; }\n"
    "cameras { perspective_camera { } }\n";

TEST(TriangleMesh, ParseWithTheirDefaults) {
    const ParseResult r = test::parse_clean(std::string(kHead) +
                                            "scene {\n"
                                            "  triangle { b: <2, 0, 0>; uv_c: <0, 2, 0>; }\n"
                                            "  mesh { file: \"m.obj\"; shading: \"flat\";\n"
                                            "         material { pigment: <1, 0, 0>; } }\n"
                                            "}\n");
    ASSERT_EQ(r.scene.primitives.size(), 2u);
    const auto& t = shape_as<Triangle>(r.scene.primitives[0].shape);
    EXPECT_EQ(t.a, Vec3(0, 0, 0));
    EXPECT_EQ(t.b, Vec3(2, 0, 0));
    EXPECT_EQ(t.c, Vec3(0, 1, 0));
    EXPECT_EQ(t.uv_b, Vec3(1, 0, 0));
    EXPECT_EQ(t.uv_c, Vec3(0, 2, 0));
    const auto& m = shape_as<Mesh>(r.scene.primitives[1].shape);
    EXPECT_EQ(m.file, "m.obj");
    EXPECT_EQ(m.shading, "flat");
    EXPECT_EQ(r.scene.primitives[1].material.pigment, Colour(1, 0, 0));
}

TEST(TriangleMesh, MistakesAreLocatedWithSuggestions) {
    EXPECT_EQ(brief(std::string(kHead) + "scene { triangel { } }"),
              "3:9: error: unknown block 'triangel' in 'scene'; did you mean 'triangle'? "
              "(allowed: sphere, plane, cylinder, triangle, mesh, point_light, include)");
    EXPECT_EQ(brief(std::string(kHead) + "scene { mesh { fille: \"a.obj\"; } }"),
              "3:16: error: unknown property 'fille' in 'mesh'; did you mean 'file'? "
              "(allowed: file, shading, smooth_angle, materials, material, transform)");
    EXPECT_EQ(brief(std::string(kHead) + "scene { mesh { file: \"a\"; shading: \"smoth\"; } }"),
              "3:36: error: 'shading' must be \"smooth\" or \"flat\", got \"smoth\"");
    // Quoted, so that a case slip, a stray space or nothing at all shows.
    EXPECT_EQ(brief(std::string(kHead) + "scene { mesh { file: \"a\"; materials: \"file \"; } }"),
              "3:38: error: 'materials' must be \"scene\" or \"file\", got \"file \"");
    EXPECT_EQ(brief(std::string(kHead) + "scene { mesh { file: \"a\"; materials: \"\"; } }"),
              "3:38: error: 'materials' must be \"scene\" or \"file\", got \"\"");
    EXPECT_EQ(brief(std::string(kHead) + "scene { triangle { a: 1; } }"),
              "3:23: error: 'a' takes a vector like <0, 1, 0>, got the number 1");
}

TEST(TriangleMesh, RoundTripThroughTheSerializer) {
    const ParseResult r = test::parse_clean(
        std::string(kHead) +
        "scene { triangle { a: <0.5, 0, 1>; uv_a: <0.25, 0.5, 0>; }\n"
        "        mesh { file: \"models/x.ply\"; transform { yrotate: 30; } } }\n");
    const std::string text = serialize_scene(r.scene);
    EXPECT_NE(text.find("mesh {\n        file: \"models/x.ply\";\n"), std::string::npos) << text;
    EXPECT_EQ(text.find("shading"), std::string::npos) << "the default is not written";
    EXPECT_EQ(text.find("uv_b"), std::string::npos) << "unset uvs are not written";
    EXPECT_EQ(test::parse_clean(text).scene, r.scene);
}

TEST(TriangleMesh, EditedInPlace) {
    const std::string text = std::string(kHead) +
                             "scene {\n    triangle { c: <0, 3, 0>; }  # keep\n"
                             "    mesh { file: \"a.obj\"; }\n}\n";
    const ParseResult base = test::parse_clean(text);
    Scene edited = base.scene;
    shape_as<Triangle>(edited.primitives[0].shape).c = {0, 4, 0};
    shape_as<Mesh>(edited.primitives[1].shape).shading = "flat";
    const SourceEditResult result = apply_scene_edits(text, base.source, base.scene, edited);
    ASSERT_TRUE(result.ok()) << result.error;
    EXPECT_NE(result.text.find("triangle { c: <0, 4, 0>; }  # keep"), std::string::npos)
        << result.text;
    EXPECT_EQ(test::parse_clean(result.text).scene, edited);
}

std::string validate(std::string_view text) {
    const ParseResult r = test::parse_clean(text);
    return brief(validate_scene(r.scene, r.source));
}

TEST(TriangleMesh, AZeroAreaTriangleWarnsAtItsKeyword) {
    EXPECT_EQ(validate(std::string(kHead) +
                       "scene { triangle { a: <0, 0, 0>; b: <1, 1, 1>; c: <2, 2, 2>; } }"),
              "3:9: warning: triangle 1: its corners <0, 0, 0>, <1, 1, 1>, <2, 2, 2> lie on one "
              "line (zero area): it is left out");
    EXPECT_EQ(validate(std::string(kHead) + "scene { triangle { } }"), "");
}

TEST(TriangleMesh, AMeshNeedsAFile) {
    EXPECT_EQ(validate(std::string(kHead) + "scene { mesh { } }"),
              "3:9: error: mesh 1: 'file' must not be empty");
}

// Through load_scene_file: the path is relative to the scene's folder.
TEST(TriangleMesh, ModelProblemsAreLocatedAtTheFileString) {
    test::ScratchDir dir;
    std::filesystem::create_directories(dir.path() / "models");
    // With its normals: a smooth mesh without them is warned about.
    test::write_file(dir.path() / "models/ok.obj",
                     "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n");
    test::write_file(dir.path() / "models/line.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
    test::write_file(dir.path() / "s.jts", std::string(kHead) +
                                               "scene {\n"
                                               "  mesh { file: \"models/ok.obj\"; }\n"
                                               "  mesh { file: \"models/line.obj\"; }\n"
                                               "  mesh { file: \"models/none.obj\"; }\n"
                                               "}\n");
    Expected<LoadedScene> loaded = load_scene_file(dir.path() / "s.jts");
    ASSERT_TRUE(loaded.has_value());
    const std::string all = brief(check_scene(*loaded));
    EXPECT_EQ(all.find("4:"), std::string::npos) << all;  // ok.obj is fine
    EXPECT_NE(all.find("5:16: warning: mesh 2: 'models/line.obj' holds no triangle of non-zero "
                       "area: the mesh is left out"),
              std::string::npos)
        << all;
    EXPECT_NE(all.find("6:16: error: mesh 3: cannot read '"), std::string::npos) << all;
    EXPECT_NE(all.find("none.obj': no such file"), std::string::npos) << all;
}

// A model that loads in part warns at its file string, once for each reason,
// and is not an error: assimp-testmodels' IndexOutOfRange has a triangle
// naming a corner it lacks; an OBJ's material library outside the folder is
// left out unopened.
TEST(TriangleMesh, WhatAModelLeavesOutIsAWarningAtTheFileString) {
    test::ScratchDir dir;
    const std::filesystem::path gltf = "/usr/share/assimp/models/glTF2/IndexOutOfRange";
    std::filesystem::create_directories(dir.path() / "scene");
    for (const char* file : {"IndexOutOfRange.gltf", "IndexOutOfRange.bin"})
        std::filesystem::copy_file(gltf / file, dir.path() / "scene" / file);
    test::write_file(dir.path() / "scene/m.obj",
                     "mtllib ../m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n");
    test::write_file(dir.path() / "scene/s.jts", std::string(kHead) +
                                                     "scene {\n"
                                                     "  mesh { file: \"IndexOutOfRange.gltf\"; }\n"
                                                     "  mesh { file: \"m.obj\"; }\n"
                                                     "}\n");
    Expected<LoadedScene> loaded = load_scene_file(dir.path() / "scene/s.jts");
    ASSERT_TRUE(loaded.has_value());
    const std::string folder = std::filesystem::weakly_canonical(dir.path() / "scene").string();
    EXPECT_EQ(brief(check_scene(*loaded)),
              "4:16: warning: mesh 1: 'IndexOutOfRange.gltf' has 1 of its 12 triangles left out: "
              "1 names a corner the file does not have (an index out of range)\n"
              "5:16: warning: mesh 2: 'm.obj' refers to the material library '../m.mtl', "
              "outside the folder '" +
                  folder + "': that file is left out");
}

}  // namespace
}  // namespace jt
