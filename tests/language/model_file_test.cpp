// Model files for `mesh` (docs/language.md §13.5): each format through real
// files of Debian's assimp-testmodels, node transforms, normals, fanning, and
// the hostile cases, all through read_model, the loader's one entry point.

#include "jtracer/model_file.hpp"
#include "common/files.hpp"
#include "common/scratch_dir.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <filesystem>
#include <string>

namespace jt::test {
namespace {

namespace fs = std::filesystem;

const fs::path kModels = "/usr/share/assimp/models";

Model read_ok(const fs::path& file) {
    Expected<Model> model = read_model(file, file.parent_path());
    EXPECT_TRUE(model.has_value()) << (model ? "" : model.error().message);
    return model ? *model : Model{};
}

std::string read_error(const fs::path& file, const fs::path& folder) {
    Expected<Model> model = read_model(file, folder);
    return model ? "(it loaded)" : model.error().message;
}

TEST(ModelFile, ObjQuadsAreFannedIntoTwoTrianglesEach) {
    const Model m = read_ok(kModels / "OBJ/box.obj");  // a cube of 6 quads
    EXPECT_EQ(m.triangles.size(), 12u);
    // A fan from the first vertex: both triangles of a face share its corner 0.
    EXPECT_EQ(m.triangles[0][0], m.triangles[1][0]);
    EXPECT_EQ(m.triangles[0][2], m.triangles[1][1]);
}

TEST(ModelFile, PlyAsciiAndBinaryReadTheSameCube) {
    const Model ascii = read_ok(kModels / "PLY/cube.ply");
    const Model binary = read_ok(kModels / "PLY/cube_binary.ply");
    EXPECT_EQ(ascii.triangles.size(), 12u);
    EXPECT_EQ(binary.triangles.size(), 12u);
}

TEST(ModelFile, PlyTextureCoordinatesAreKept) {
    const Model m = read_ok(kModels / "PLY/cube_uv.ply");
    EXPECT_EQ(m.triangles.size(), 12u);
    ASSERT_EQ(m.uvs.size(), m.positions.size());
}

TEST(ModelFile, StlFacetNormalsAreNotVertexNormals) {
    const Model m = read_ok(kModels / "STL/Spider_binary.stl");
    EXPECT_GT(m.triangles.size(), 1000u);
    EXPECT_TRUE(m.normals.empty());
    const Model ascii = read_ok(kModels / "STL/Spider_ascii.stl");
    EXPECT_EQ(ascii.triangles.size(), m.triangles.size());
}

TEST(ModelFile, GltfAndGlbWithNormalsAndTextureCoordinates) {
    for (const char* file : {"glTF2/BoxTextured-glTF/BoxTextured.gltf",
                             "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb"}) {
        const Model m = read_ok(kModels / file);
        EXPECT_EQ(m.triangles.size(), 12u) << file;
        EXPECT_EQ(m.normals.size(), m.positions.size()) << file;
        EXPECT_EQ(m.uvs.size(), m.positions.size()) << file;
        // The node's matrix turns the unit box about x: it stays in [-0.5, 0.5]^3.
        for (const glm::vec3& p : m.positions) EXPECT_LE(glm::length(p), 0.87f) << file;
    }
}

// A triangle (0,0,0) (1,0,0) (0,1,0) in a buffer written into the file,
// under a child node translated by (0,0,5) inside a parent scaled by 2.
constexpr std::string_view kNestedGltf = R"({
  "asset": {"version": "2.0"},
  "scene": 0, "scenes": [{"nodes": [0]}],
  "nodes": [{"scale": [2, 2, 2], "children": [1]}, {"translation": [0, 0, 5], "mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
  "buffers": [{"byteLength": 36,
               "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
  "bufferViews": [{"buffer": 0, "byteLength": 36}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                 "min": [0, 0, 0], "max": [1, 1, 0]}]
})";

TEST(ModelFile, GltfNodeTransformsApplyParentsLast) {
    ScratchDir dir;
    write_file(dir.path() / "nested.gltf", kNestedGltf);
    const Model m = read_ok(dir.path() / "nested.gltf");
    ASSERT_EQ(m.triangles.size(), 1u);
    const auto& t = m.triangles[0];
    EXPECT_EQ(m.positions[t[0]], glm::vec3(0, 0, 10));
    EXPECT_EQ(m.positions[t[1]], glm::vec3(2, 0, 10));
    EXPECT_EQ(m.positions[t[2]], glm::vec3(0, 2, 10));
    EXPECT_TRUE(m.normals.empty());
}

TEST(ModelFile, ObjVertexNormalsAndAFanOfAPentagon) {
    ScratchDir dir;
    write_file(dir.path() / "pentagon.obj",
               "v 0 0 0\nv 1 0 0\nv 1.5 1 0\nv 0.5 2 0\nv -0.5 1 0\n"
               "vn 0 0 1\nvn 0 0.6 0.8\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\n"
               "f 1//1 2//2 3//3 4//4 5//5\n");
    const Model m = read_ok(dir.path() / "pentagon.obj");
    ASSERT_EQ(m.triangles.size(), 3u);
    for (const auto& t : m.triangles) EXPECT_EQ(m.positions[t[0]], glm::vec3(0, 0, 0));
    ASSERT_EQ(m.normals.size(), m.positions.size());
    EXPECT_EQ(m.normals[m.triangles[0][1]], glm::vec3(0, 0.6f, 0.8f));
}

TEST(ModelFile, ZeroAreaTrianglesAreSkippedAndNoneLeftIsAnEmptyModel) {
    ScratchDir dir;
    write_file(dir.path() / "flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 4\n");
    EXPECT_EQ(read_ok(dir.path() / "flat.obj").triangles.size(), 1u);
    write_file(dir.path() / "line.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
    EXPECT_TRUE(read_ok(dir.path() / "line.obj").triangles.empty());
}

TEST(ModelFile, MissingAndMalformedFilesAreErrorsNamingTheFile) {
    ScratchDir dir;
    EXPECT_NE(read_error(dir.path() / "none.obj", dir.path()).find("No such file"),
              std::string::npos);
    write_file(dir.path() / "broken.gltf", "{ \"asset\": { \"version\": ");
    const std::string broken = read_error(dir.path() / "broken.gltf", dir.path());
    EXPECT_NE(broken.find("broken.gltf"), std::string::npos) << broken;
    write_file(dir.path() / "broken.glb", "glTF\x02\0\0\0garbage");
    EXPECT_NE(read_error(dir.path() / "broken.glb", dir.path()), "(it loaded)");
    EXPECT_NE(read_error(dir.path(), dir.path()).find("not a regular file"), std::string::npos);
}

TEST(ModelFile, ReferencesOutsideTheSceneFolderAreRefused) {
    ScratchDir dir;
    fs::create_directories(dir.path() / "scene");
    write_file(dir.path() / "secret.mtl", "newmtl x\nKd 1 0 0\n");
    write_file(dir.path() / "scene/escape.obj",
               "mtllib ../secret.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const std::string obj = read_error(dir.path() / "scene/escape.obj", dir.path() / "scene");
    EXPECT_NE(obj.find("outside the folder"), std::string::npos) << obj;

    std::string gltf(kNestedGltf);
    const std::string data =
        "data:application/octet-stream;base64,"
        "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA";
    gltf.replace(gltf.find(data), data.size(), "../buffer.bin");
    write_file(dir.path() / "buffer.bin", std::string(36, '\0'));
    write_file(dir.path() / "scene/escape.gltf", gltf);
    const std::string buffer = read_error(dir.path() / "scene/escape.gltf", dir.path() / "scene");
    EXPECT_NE(buffer.find("outside the folder"), std::string::npos) << buffer;
}

TEST(ModelFile, AbsurdCountsAndHugeFilesAreRefusedBeforeReading) {
    ScratchDir dir;
    write_file(dir.path() / "claims.ply",
               "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\n"
               "property float x\nproperty float y\nproperty float z\nend_header\n");
    const std::string claims = read_error(dir.path() / "claims.ply", dir.path());
    EXPECT_NE(claims.find("claims"), std::string::npos) << claims;
    // A sparse file: its size is what counts, nothing is read.
    write_file(dir.path() / "huge.stl", "solid x\n");
    fs::resize_file(dir.path() / "huge.stl", kMaxModelFileBytes + 1);
    const std::string huge = read_error(dir.path() / "huge.stl", dir.path());
    EXPECT_NE(huge.find("too large"), std::string::npos) << huge;
}

TEST(ModelFile, TheBoxHoldsTheCornersTheTrianglesName) {
    Model model;
    model.positions = {{0, 0, 0}, {2, 1, 0}, {0, 3, -1}, {100, 100, 100}};  // the last unused
    model.triangles = {{0, 1, 2}};
    const ModelBox box = model_box(model);
    ASSERT_FALSE(box.empty());
    EXPECT_EQ(box.lower, glm::dvec3(0, 0, -1));
    EXPECT_EQ(box.upper, glm::dvec3(2, 3, 0));
    model.triangles.clear();
    EXPECT_TRUE(model_box(model).empty());
}

}  // namespace
}  // namespace jt::test
