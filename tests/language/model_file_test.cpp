// Model files for `mesh` (docs/language.md §13.5): each format through real
// files of Debian's assimp-testmodels, node transforms, normals, fanning, and
// the hostile cases, all through read_model, the loader's one entry point.

#include "jtracer/model_file.hpp"
#include "common/files.hpp"
#include "common/scratch_dir.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace jt::test {
namespace {

namespace fs = std::filesystem;

const fs::path kModels = "/usr/share/assimp/models";

Model read_ok(const fs::path& file) {
    Expected<Model> model = read_model(file, file.parent_path());
    EXPECT_TRUE(model.has_value()) << (model ? "" : model.error().message);
    return model ? *model : Model{};
}

std::string read_error(const fs::path& file, const fs::path& folder, bool file_materials = false) {
    Expected<Model> model = read_model(file, folder, file_materials);
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

// The triangles' areas, each counted as a positive area, and their winding
// against `normal`: a cut that covers the polygon covers it once, wound as
// the polygon is.
struct Coverage {
    double area = 0.0;
    std::size_t wound_against = 0;
};
Coverage coverage(const Model& m, const glm::dvec3& normal) {
    Coverage c;
    for (const auto& t : m.triangles) {
        const glm::dvec3 a(m.positions[t[0]]), b(m.positions[t[1]]), d(m.positions[t[2]]);
        const glm::dvec3 n = glm::cross(b - a, d - a);
        c.area += glm::length(n) / 2.0;
        if (glm::dot(n, normal) <= 0.0) ++c.wound_against;
    }
    return c;
}

TEST(ModelFile, AConcavePolygonIsCutInsideItsEdges) {
    // An L of area 3, written from the corner beside the notch as a 3D tool
    // may write it: a fan from there covers the notch too (area 3.5, one
    // triangle wound backwards over the others).
    ScratchDir dir;
    write_file(dir.path() / "l.obj",
               "v 2 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\nv 0 0 0\nv 2 0 0\nf 1 2 3 4 5 6\n");
    const Model m = read_ok(dir.path() / "l.obj");
    EXPECT_EQ(m.triangles.size(), 4u);
    const Coverage c = coverage(m, {0, 0, 1});
    EXPECT_NEAR(c.area, 3.0, 1e-9);
    EXPECT_EQ(c.wound_against, 0u);
    for (const auto& t : m.triangles) {
        const glm::vec3 centre = (m.positions[t[0]] + m.positions[t[1]] + m.positions[t[2]]) / 3.0f;
        EXPECT_FALSE(centre.x > 1.0f && centre.y > 1.0f) << "a triangle in the notch";
    }
}

TEST(ModelFile, AConvexPolygonIsStillAFan) {
    // Collinear corners (an edge split in two) leave it convex.
    ScratchDir dir;
    write_file(dir.path() / "square.obj",
               "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 2 2 0\nv 0 2 0\nf 1 2 3 4 5\n");
    const Model m = read_ok(dir.path() / "square.obj");
    ASSERT_EQ(m.triangles.size(), 2u);  // the fan's first triangle has no area
    for (const auto& t : m.triangles) EXPECT_EQ(m.positions[t[0]], glm::vec3(0, 0, 0));
    EXPECT_NEAR(coverage(m, {0, 0, 1}).area, 4.0, 1e-9);
}

TEST(ModelFile, APolygonRoundItsHoleThroughASeamIsARing) {
    // assimp-testmodels' concave_polygon.obj: one face of 66 corners that goes
    // round a circle, along a seam to a smaller circle, round it the other way
    // and back: a ring in the plane x = -1.146. A fan filled the hole.
    const Model m = read_ok(kModels / "OBJ/concave_polygon.obj");
    ASSERT_FALSE(m.triangles.empty());
    // The ring's area by the shoelace formula over the face's corners, in y
    // and z; its sign is the side the face's winding faces, along x.
    std::ifstream in(kModels / "OBJ/concave_polygon.obj");
    std::vector<glm::dvec2> v;
    std::vector<std::size_t> face;
    for (std::string line; std::getline(in, line);) {
        std::istringstream words(line);
        std::string kind;
        words >> kind;
        double x = 0, y = 0, z = 0;
        if (kind == "v" && words >> x >> y >> z) v.emplace_back(y, z);
        if (kind == "f")
            for (std::string corner; words >> corner;) face.push_back(std::stoul(corner) - 1);
    }
    ASSERT_EQ(face.size(), 66u);
    double twice = 0.0;
    for (std::size_t i = 0; i < face.size(); ++i) {
        const glm::dvec2 a = v[face[i]], b = v[face[(i + 1) % face.size()]];
        twice += a.x * b.y - a.y * b.x;
    }
    const double ring = std::abs(twice) / 2.0;
    const Coverage c = coverage(m, {twice > 0.0 ? 1.0 : -1.0, 0.0, 0.0});
    EXPECT_NEAR(c.area, ring, 1e-4 * ring);
    EXPECT_EQ(c.wound_against, 0u);
}

TEST(ModelFile, AHugeConcavePolygonReadsInTime) {
    // A comb of 1500 teeth (6002 corners): past the corners that are cut ear
    // by ear, it is fanned; one of 1000 teeth (4002) is cut, each tooth an ear.
    for (const int teeth : {1000, 1500}) {
        ScratchDir dir;
        std::string obj;
        for (int k = 0; k < teeth; ++k) {
            const int x = 2 * k;
            obj += "v " + std::to_string(x) + " 0 0\nv " + std::to_string(x + 1) + " 0 0\n";
            obj += "v " + std::to_string(x + 1) + " 1 0\nv " + std::to_string(x + 2) + " 1 0\n";
        }
        obj += "v " + std::to_string(2 * teeth) + " 5 0\nv 0 5 0\nf";
        for (int k = 1; k <= 4 * teeth + 2; ++k) obj += " " + std::to_string(k);
        write_file(dir.path() / "comb.obj", obj + "\n");
        const auto start = std::chrono::steady_clock::now();
        const Model m = read_ok(dir.path() / "comb.obj");
        EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(20)) << teeth;
        EXPECT_GE(m.triangles.size(), static_cast<std::size_t>(teeth)) << teeth;
        if (teeth == 1000) {  // the comb's area: 2 x 5 a tooth less its 1 x 1 notch
            EXPECT_NEAR(coverage(m, {0, 0, 1}).area, 9.0 * teeth, 1e-6 * teeth);
        }
    }
}

// The warnings of `file` read with materials "file" (or "scene"), joined.
std::string material_warnings(const fs::path& file, bool file_materials = true) {
    const Expected<Model> m = read_model(file, file.parent_path(), file_materials);
    EXPECT_TRUE(m.has_value()) << (m ? "" : m.error().message);
    std::string joined;
    if (m)
        for (const std::string& w : model_warnings(*m)) joined += w + "\n";
    return joined;
}

TEST(ModelFile, FileMaterialsOfAFormatWhoseColoursAreNotReadSaySo) {
    // A Collada duck with its texture, and cubes with vertex colours: asked
    // for the file's materials, they rendered in the block's pigment silently.
    EXPECT_NE(material_warnings(kModels / "Collada/duck.dae")
                  .find("holds textures that materials: \"file\" does not read"),
              std::string::npos);
    EXPECT_NE(
        material_warnings(kModels / "Collada/kwxport_test_vcolors.dae").find("vertex colours"),
        std::string::npos);
    EXPECT_NE(material_warnings(kModels / "MD2/faerie.md2").find("textures"), std::string::npos);
    // Not asked for, not said; formats that are read, or hold nothing to read, say nothing.
    EXPECT_EQ(material_warnings(kModels / "Collada/duck.dae", false), "");
    for (const char* file : {"OBJ/spider.obj", "glTF2/BoxTextured-glTF/BoxTextured.gltf",
                             "PLY/float-color.ply", "STL/Spider_binary.stl", "OFF/Cube.off"})
        EXPECT_EQ(material_warnings(kModels / file).find("does not read"), std::string::npos)
            << file;
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
    EXPECT_NE(read_error(dir.path() / "none.obj", dir.path()).find("none.obj': no such file"),
              std::string::npos);
    write_file(dir.path() / "broken.gltf", "{ \"asset\": { \"version\": ");
    const std::string broken = read_error(dir.path() / "broken.gltf", dir.path());
    EXPECT_NE(broken.find("broken.gltf"), std::string::npos) << broken;
    write_file(dir.path() / "broken.glb", "glTF\x02\0\0\0garbage");
    EXPECT_NE(read_error(dir.path() / "broken.glb", dir.path()), "(it loaded)");
    EXPECT_NE(read_error(dir.path(), dir.path()).find("not a regular file"), std::string::npos);
}

// A file outside the folder is never opened. An OBJ's material library is
// not needed (materials in the file are ignored): the model loads and says
// what it left out, whether the library exists or not.
TEST(ModelFile, ReferencesOutsideTheSceneFolderAreRefused) {
    ScratchDir dir;
    fs::create_directories(dir.path() / "scene");
    write_file(dir.path() / "secret.mtl", "newmtl x\nKd 1 0 0\n");
    for (const char* library : {"../secret.mtl", "../none.mtl"}) {
        SCOPED_TRACE(library);
        write_file(dir.path() / "scene/escape.obj",
                   std::string("mtllib ") + library + "\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        const Expected<Model> obj =
            read_model(dir.path() / "scene/escape.obj", dir.path() / "scene");
        ASSERT_TRUE(obj.has_value()) << obj.error().message;
        EXPECT_EQ(obj->triangles.size(), 1u);
        const std::vector<std::string> warnings = model_warnings(*obj);
        ASSERT_EQ(warnings.size(), 1u);
        EXPECT_EQ(warnings[0].rfind("refers to the material library '", 0), 0u) << warnings[0];
        EXPECT_NE(warnings[0].find(library), std::string::npos) << warnings[0];
        EXPECT_NE(warnings[0].find("outside the folder"), std::string::npos) << warnings[0];
        EXPECT_NE(warnings[0].find("that file is left out"), std::string::npos) << warnings[0];
    }

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

// A LightWave scene names its object by a relative name ("LoadObjectLayer 1
// 10000000 simple_cube.lwo"): taken from the scene's folder, not from the
// working directory, it loads with no warning wherever the program runs,
// and a model named by a relative path still loads.
TEST(ModelFile, RelativeReferencesAreTakenFromTheModelsFolder) {
    ScratchDir dir;
    fs::create_directories(dir.path() / "scene");
    for (const char* name : {"move_x.lws", "simple_cube.lwo"})
        fs::copy_file(kModels / "LWS" / name, dir.path() / "scene" / name);
    const fs::path cwd = fs::current_path();
    for (const fs::path& from : {dir.path(), dir.path() / "scene", fs::path("/")}) {
        SCOPED_TRACE(from.string());
        fs::current_path(from);
        const Expected<Model> absolute =
            read_model(dir.path() / "scene/move_x.lws", dir.path() / "scene");
        const Expected<Model> relative = read_model(fs::relative(dir.path() / "scene/move_x.lws"),
                                                    fs::relative(dir.path() / "scene"));
        fs::current_path(cwd);
        for (const Expected<Model>* model : {&absolute, &relative}) {
            ASSERT_TRUE(model->has_value()) << (*model).error().message;
            EXPECT_EQ((*model)->triangles.size(), 12u);  // the cube
            EXPECT_EQ(model_warnings(**model), std::vector<std::string>{});
        }
    }
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

std::vector<std::string> warnings_of(const fs::path& file) {
    return model_warnings(read_ok(file));
}

// Assimp drops a glTF face whose indices are out of range with a log line
// only; the file's accessors say how many there were.
TEST(ModelFile, TrianglesAReaderDropsAreCountedAndNamed) {
    const Model m = read_ok(kModels / "glTF2/IndexOutOfRange/IndexOutOfRange.gltf");
    EXPECT_EQ(m.triangles.size(), 11u);
    EXPECT_EQ(m.left_out.out_of_range, 1u);
    EXPECT_EQ(model_warnings(m),
              std::vector<std::string>{"has 1 of its 12 triangles left out: 1 names a corner "
                                       "the file does not have (an index out of range)"});
    EXPECT_EQ(read_error(kModels / "glTF2/IndexOutOfRange/AllIndicesOutOfRange.gltf", kModels),
              "'" + (kModels / "glTF2/IndexOutOfRange/AllIndicesOutOfRange.gltf").string() +
                  "': none of its 12 triangles can be read: they name corners the file does not "
                  "have (indices out of range)");
    // Our own reading drops the same, and corners that are not finite.
    ScratchDir dir;
    write_file(dir.path() / "bad.ply",
               "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
               "property float z\nelement face 3\nproperty list uchar int vertex_indices\n"
               "end_header\n0 0 0\n1 0 0\n0 1 0\n1e39 0 0\n3 0 1 2\n3 0 1 3\n3 0 1 9\n");
    const Model ply = read_ok(dir.path() / "bad.ply");
    EXPECT_EQ(ply.triangles.size(), 1u);
    EXPECT_EQ(model_warnings(ply),
              std::vector<std::string>{
                  "has 2 of its 3 triangles left out: 1 names a corner the file does not have (an "
                  "index out of range), 1 has a corner at infinity or NaN"});
    EXPECT_EQ(warnings_of(kModels / "glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb"),
              std::vector<std::string>{"holds no usable triangle (12 have a corner at infinity "
                                       "or NaN): the mesh is left out"});
    EXPECT_TRUE(warnings_of(kModels / "OBJ/box.obj").empty());
}

TEST(ModelFile, PointCloudsAndLinesSayWhatTheyHold) {
    EXPECT_EQ(warnings_of(kModels / "PLY/points.ply"),
              std::vector<std::string>{"holds only 4 points, no triangle: the mesh is left out"});
    EXPECT_EQ(warnings_of(kModels / "OBJ/testpoints.obj"),
              std::vector<std::string>{"holds only 24 points, no triangle: the mesh is left out"});
    EXPECT_EQ(warnings_of(kModels / "OBJ/testline.obj"),
              std::vector<std::string>{"holds only 18 lines, no triangle: the mesh is left out"});
    ScratchDir dir;
    write_file(dir.path() / "flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
    EXPECT_EQ(warnings_of(dir.path() / "flat.obj"),
              std::vector<std::string>{"holds no triangle of non-zero area: the mesh is left out"});
}

// Assimp's words named another cause (or printed 200 bytes of the file).
TEST(ModelFile, ReaderFailuresNameTheirCause) {
    const std::string only_2 = "which is not read: only glTF 2.0 is (convert the file to glTF 2.0)";
    for (const auto& [file, what] : std::vector<std::pair<std::string, std::string>>{
             {"glTF/TwoBoxes/TwoBoxes.gltf", "glTF 1.0"},
             {"glTF/CesiumMilkTruck/CesiumMilkTruck.gltf", "glTF 1"},
             {"glTF/BoxTextured-glTF-Binary/BoxTextured.glb", "binary glTF version 1 (.glb)"}}) {
        const std::string error = read_error(kModels / file, kModels);
        EXPECT_NE(error.find("': it is " + what + ", " + only_2), std::string::npos) << error;
    }
    for (const char* file :
         {"OBJ/box_UTF16BE.obj", "AC/SphereWithLight_UTF16LE.ac", "Collada/cube_UTF16LE.dae"}) {
        const std::string error = read_error(kModels / file, kModels);
        EXPECT_NE(error.find("': the file is UTF-16 text (it starts with a byte order mark), which "
                             "the model reader does not read: save it as UTF-8"),
                  std::string::npos)
            << error;
    }

    ScratchDir dir;
    write_file(dir.path() / "bad.stl",
               "solid x\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n"
               "   vertex 1 0 0\n   vertex abc 1 0\n  endloop\n endfacet\nendsolid x\n");
    EXPECT_EQ(read_error(dir.path() / "bad.stl", dir.path()),
              "'" + (dir.path() / "bad.stl").string() +
                  "': line 6, column 11 (byte 83): a number was expected, not 'abc'");

    // A bad number in an OBJ's material library is located there, not at
    // the first place its text occurs in the model ('x' inside "usemtl tex");
    // a number missing at a line's end names the library too. Only the
    // file's materials need the library: with the scene's the model loads
    // without it, and the fault is a warning.
    write_file(dir.path() / "lib.obj",
               "mtllib lib.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl tex\nf 1 2 3\n");
    write_file(dir.path() / "lib.mtl", "newmtl tex\nKd 1 0.2 x\n");
    EXPECT_EQ(read_error(dir.path() / "lib.obj", dir.path(), true),
              "'" + (dir.path() / "lib.obj").string() +
                  "': its material library 'lib.mtl', line 2, column 10 (byte 20): a number was "
                  "expected, not 'x'");
    Expected<Model> scene_materials = read_model(dir.path() / "lib.obj", dir.path());
    ASSERT_TRUE(scene_materials.has_value()) << scene_materials.error().message;
    EXPECT_EQ(scene_materials->triangles.size(), 1u);
    EXPECT_EQ(model_warnings(*scene_materials),
              std::vector<std::string>{
                  "refers to the material library 'lib.mtl', which cannot be read (line 2, "
                  "column 10 (byte 20): a number was expected, not 'x'): that file is left out"});
    write_file(dir.path() / "lib.mtl", "newmtl tex\nKd 1 0.2\n");
    EXPECT_EQ(read_error(dir.path() / "lib.obj", dir.path(), true),
              "'" + (dir.path() / "lib.obj").string() +
                  "': a line of the file or of its material library 'lib.mtl' ends where a "
                  "number was expected");
    scene_materials = read_model(dir.path() / "lib.obj", dir.path());
    ASSERT_TRUE(scene_materials.has_value()) << scene_materials.error().message;
    EXPECT_EQ(scene_materials->triangles.size(), 1u);
    EXPECT_EQ(model_warnings(*scene_materials),
              std::vector<std::string>{
                  "refers to the material library 'lib.mtl', which cannot be read (a line of it "
                  "ends where a number was expected): that file is left out"});
    // A fault of the model itself stays an error with the scene's materials,
    // and is the one reported, not the library's before it.
    write_file(dir.path() / "lib.obj",
               "mtllib lib.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl tex\nf 1 2 4\n");
    EXPECT_NE(read_error(dir.path() / "lib.obj", dir.path()).find("vertex index out of range"),
              std::string::npos);

    // Assimp's Collada reader does not skip the spaces before a number
    // ("<color>  0.0 0.0 0.0 1.0  </color>"): the message says so, rather than
    // that a number was expected and "nothing" found.
    EXPECT_EQ(read_error(kModels / "Collada/library_animation_clips.dae", kModels),
              "'" + (kModels / "Collada/library_animation_clips.dae").string() +
                  "': line 21, column 14 (byte 637): a number was expected, not the white space "
                  "before '0.0' (the model reader does not skip it there)");

    const std::string box = read_file(kModels / "3MF/box.3mf");
    ASSERT_GT(box.size(), 1000u);
    write_file(dir.path() / "cut.3mf", box.substr(0, 600));
    EXPECT_NE(read_error(dir.path() / "cut.3mf", dir.path())
                  .find("': its zip archive cannot be read: it is cut short or damaged"),
              std::string::npos);
    write_file(dir.path() / "text.3mf", "v 0 0 0\n");
    EXPECT_NE(read_error(dir.path() / "text.3mf", dir.path())
                  .find("': the file is not a zip archive, as a 3MF file must be"),
              std::string::npos);
    write_file(dir.path() / "zipped.amf", box);
    EXPECT_NE(read_error(dir.path() / "zipped.amf", dir.path())
                  .find("': the file is a zip archive (a zipped AMF?), which the model reader "
                        "opens only as 3MF: unzip it first"),
              std::string::npos);
    write_file(dir.path() / "gzipped.amf", std::string("\x1f\x8b\x08\0\0\0\0\0", 8));
    EXPECT_NE(read_error(dir.path() / "gzipped.amf", dir.path()).find("gzip-compressed"),
              std::string::npos);
    EXPECT_EQ(read_ok(kModels / "3MF/box.3mf").triangles.size(), 12u);
}

// Formats Debian's Assimp is built without: it takes a VRML file for a
// Blender one ("BLEND: BLENDER magic bytes are missing"), a Model 3D file for
// OBJ ("OBJ: Invalid face index"), or reads one as a model of nothing, which
// left the mesh out with a warning that it holds no triangle.
TEST(ModelFile, AFormatTheReaderLacksIsNamedFromTheFilesFirstBytes) {
    for (const char* file : {"WRL/Wuson.wrl", "WRL/MotionCaptureROM.WRL"}) {
        const std::string error = read_error(kModels / file, kModels);
        EXPECT_NE(error.find("': the file is VRML, which the model reader does not read"),
                  std::string::npos)
            << error;
    }
    for (const char* file : {"M3D/WusonBlitz1.m3d", "M3D/cube_normals.m3d", "M3D/suzanne.m3d",
                             "M3D/cube_with_vertexcolors.a3d"}) {
        const std::string error = read_error(kModels / file, kModels);
        EXPECT_NE(error.find("': the file is Model 3D (.m3d, .a3d), which the model reader does "
                             "not read"),
                  std::string::npos)
            << file << ": " << error;
    }
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

namespace jt::test {
namespace {

TEST(ModelFile, WhatTheReaderPrintsIsAWarningOfTheFileNotATerminalLine) {
    // Assimp's OpenGEX reader writes this line to std::cerr for a structure
    // it cannot make (here an empty camera), once for each.
    std::ostringstream terminal;
    std::streambuf* const stderr_buffer = std::cerr.rdbuf(terminal.rdbuf());
    const Expected<Model> model =
        read_model(kModels / "OpenGEX/empty_camera.ogex", kModels / "OpenGEX");
    std::cerr.rdbuf(stderr_buffer);
    ASSERT_TRUE(model.has_value()) << model.error().message;
    EXPECT_EQ(terminal.str(), "");
    ASSERT_EQ(model->left_out.reader_said.size(), 1u);
    EXPECT_EQ(model->left_out.reader_said[0].first, "nullptr returned by creating DDLNode.");
    const std::vector<std::string> warnings = model_warnings(*model);
    EXPECT_NE(std::find(warnings.begin(), warnings.end(),
                        "made the model reader (Assimp) print 'nullptr returned by creating "
                        "DDLNode.'"),
              warnings.end());

    // The same line five times is one warning that counts them.
    ScratchDir dir;
    write_file(dir.path() / "bad.ogex",
               "Metric {(key = \"distance\") {float {1.0}}}\n{{{{ zz = , ]\n");
    const Expected<Model> bad = read_model(dir.path() / "bad.ogex", dir.path());
    ASSERT_TRUE(bad.has_value()) << bad.error().message;
    ASSERT_EQ(bad->left_out.reader_said.size(), 1u);
    EXPECT_EQ(bad->left_out.reader_said[0].second, 5u);
    EXPECT_EQ(model_warnings(*bad).front(),
              "made the model reader (Assimp) print 'nullptr returned by creating DDLNode.' 5 "
              "times");
}

}  // namespace
}  // namespace jt::test
