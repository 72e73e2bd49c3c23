// Files from strangers named by a scene: pictures whose headers claim sizes
// no machine could hold, or whose tables made stb_image write out of bounds; models that claim more
// vertices than their bytes hold or whose buffers lie outside the scene's folder. Each is refused
// before anything is decoded or allocated, with an error at the image_map or mesh file string,
// through --check and through a render alike.

#include "cli_sandbox.hpp"

#include <filesystem>
#include <string>

namespace jt::test {
namespace {

namespace fs = std::filesystem;

const fs::path hostile = fs::path(JT_SOURCE_DIR) / "tests/hardening/regressions/image_map";

class HostileImageMaps : public CliSandbox {
  protected:
    // A scene whose one image_map string starts at line 4, column 16.
    void write_scene_naming(const std::string& picture) {
        picture_ = picture;
        fs::copy_file(hostile / picture, dir / picture);
        write_file(dir / "hostile.jts",
                   "render_settings { width: 8; height: 8; }\n"
                   "cameras { perspective_camera { position: <0, 0, 5>; look_at: <0, 0, 0>; } }\n"
                   "scene { sphere { material {\n"
                   "    image_map: \"" +
                       picture + "\"; } } }\n");
    }
    // The render's own words for the picture, at its string.
    void expect_refused(const ProgramRun& r, const std::string& problem) const {
        EXPECT_EQ(r.code, 1) << r.err;
        EXPECT_EQ(
            r.err.rfind("hostile.jts:4:16: error: image_map: '" + picture_ + "': " + problem + "\n",
                        0),
            0u)
            << r.err;
        EXPECT_FALSE(exists("out.bmp"));
        EXPECT_TRUE(temporary_files().empty());
    }
    std::string picture_;
};

TEST_F(HostileImageMaps, SizesNoMachineCouldHoldAreRefusedAtTheImageMapString) {
    const std::pair<const char*, const char*> pictures[] = {
        {"claims-100000x100000.png", "100000x100000"},
        {"claims-100000x100000.bmp", "100000x100000"},
        // Found by the fuzzer: the product of the two sides overflowed.
        {"png-claiming-4294967295x4294967295.png", "4294967295x4294967295"},
    };
    for (const auto& [picture, claimed] : pictures) {
        SCOPED_TRACE(picture);
        write_scene_naming(picture);
        const std::string problem = "the image is too large (" + std::string(claimed) +
                                    " texels; an image map has at most 268435456)";
        expect_refused(run({"hostile.jts", "--check"}), problem);
        expect_refused(run({"hostile.jts", "-o", "out.bmp"}), problem);
    }
}

// Found by fuzz/image_map_fuzzer: stb_image 2.27 wrote past its Huffman tables
// for the JPEGs (which libjpeg-turbo now reads, io/jpeg.hpp), spent a minute decoding zeros into
// the 58 million pixels the 90-byte BMP claims (io/image_claims.hpp), decoded a BMP of no pixels,
// which sampling would have divided by, and copied a PNG's empty first IDAT chunk to a null pointer
// (io/png_chunks.hpp; the second PNG is otherwise sound), and reserved the
// memory a PNG's IDAT chunk claimed before reading it.
TEST_F(HostileImageMaps, FilesThatMisledStbImageAreRefused) {
    const std::pair<const char*, const char*> pictures[] = {
        {"jpeg-huffman-table-of-too-many-codes.jpg",
         "cannot read the JPEG: Bogus Huffman table definition"},
        {"jpeg-huffman-counts-past-the-end.jpg",  // stb_image read zeros past the end
         "cannot read the JPEG: Bogus Huffman table definition"},
        // libjpeg's own limit, checked before anything is allocated.
        {"claims-65535x65535.jpg",
         "cannot read the JPEG: Maximum supported image dimension is 65500 pixels"},
        {"bmp-90-bytes-claiming-5x11665411.bmp",
         "the file is too short for the 5x11665411 pixels its header claims (90 bytes)"},
        {"bmp-of-0x0-pixels.bmp", "the image has no pixels (0x0)"},
        // Its header ends before its bit count: stb_image filled 90 million texels.
        {"bmp-29-bytes-claiming-43x2097154.bmp", "the file ends inside its BMP header (29 bytes)"},
        {"png-first-idat-empty.png", "a PNG whose first IDAT chunk is empty (at byte 33)"},
        {"png-4x3-empty-idat-first.png", "a PNG whose first IDAT chunk is empty (at byte 33)"},
        // stb_image reserved the 1.9 GB this IDAT chunk claims before reading it.
        {"png-idat-claiming-past-the-end.png",
         "a PNG whose IDAT chunk at byte 64 claims 1929379853 bytes, past the end of the file "
         "(108 bytes)"},
    };
    for (const auto& [picture, problem] : pictures) {
        SCOPED_TRACE(picture);
        write_scene_naming(picture);
        expect_refused(run({"hostile.jts", "--check"}), problem);
        expect_refused(run({"hostile.jts", "-o", "out.bmp"}), problem);
    }
}

// Found by fuzz/image_map_fuzzer: on this JPEG, whose entropy-coded data ends
// early, stb_image 2.27 shifted an int by 32 (undefined). Its header is sound,
// but --check decodes what the render decodes: both refuse it at its string.
TEST_F(HostileImageMaps, AJpegWhoseDataEndsEarlyIsRefusedByTheCheckAsByTheRender) {
    write_scene_naming("jpeg-entropy-data-ending-early.jpg");
    const std::string problem =
        "cannot read the JPEG: Corrupt JPEG data: premature end of data "
        "segment";
    expect_refused(run({"hostile.jts", "--check"}), problem);
    expect_refused(run({"hostile.jts", "-o", "out.bmp"}), problem);
}

// A sky map is read by the image maps' reader, with its limits: the same
// pictures are refused at the background_map string (line 2, column 21), by
// --check and the render alike, and so are a missing file, a directory and "".
class HostileBackgroundMaps : public CliSandbox {
  protected:
    void write_scene_naming(const std::string& picture) {
        write_file(dir / "sky.jts",
                   "render_settings { width: 8; height: 8;\n"
                   "    background_map: \"" +
                       picture +
                       "\"; }\n"
                       "cameras { perspective_camera { } }\n"
                       "scene { }\n");
    }
    void expect_refused_everywhere(const std::string& message) const {
        for (const auto& args : {std::vector<std::string>{"sky.jts", "--check"},
                                 std::vector<std::string>{"sky.jts", "-o", "out.bmp"}}) {
            const ProgramRun r = run(args);
            EXPECT_EQ(r.code, 1) << r.err;
            EXPECT_EQ(r.err.rfind("sky.jts:2:21: error: background_map: " + message + "\n", 0), 0u)
                << r.err;
            EXPECT_FALSE(exists("out.bmp"));
            EXPECT_TRUE(temporary_files().empty());
        }
    }
};

TEST_F(HostileBackgroundMaps, PicturesRefusedAsImageMapsAreRefusedAtTheString) {
    const std::pair<const char*, const char*> pictures[] = {
        {"claims-100000x100000.png",
         "the image is too large (100000x100000 texels; an image map has at most 268435456)"},
        {"bmp-90-bytes-claiming-5x11665411.bmp",
         "the file is too short for the 5x11665411 pixels its header claims (90 bytes)"},
        {"jpeg-entropy-data-ending-early.jpg",
         "cannot read the JPEG: Corrupt JPEG data: premature end of data segment"},
    };
    for (const auto& [picture, problem] : pictures) {
        SCOPED_TRACE(picture);
        fs::copy_file(hostile / picture, dir / picture, fs::copy_options::overwrite_existing);
        write_scene_naming(picture);
        expect_refused_everywhere("'" + std::string(picture) + "': " + problem);
    }
}

TEST_F(HostileBackgroundMaps, MissingFilesDirectoriesAndEmptyNamesAreRefusedAtTheString) {
    write_scene_naming("nowhere.png");
    expect_refused_everywhere("cannot read 'nowhere.png': no such file");
    fs::create_directory(dir / "maps");
    write_scene_naming("maps");
    expect_refused_everywhere("cannot read 'maps': it is a directory, not a file");
    write_scene_naming("");
    expect_refused_everywhere(
        "the file name is empty (leave 'background_map' out to show the background colour)");
}

class HostileModels : public CliSandbox {
  protected:
    void SetUp() override {
        CliSandbox::SetUp();
        fs::create_directories(dir / "scene");
        // What a hostile model may try to reach: a file beside the scene's folder.
        write_file(dir / "outside.bin", std::string(36, '\0'));
    }
    // scene/hostile.jts, whose one mesh's file string starts at line 4, column 18.
    void write_scene_naming(const std::string& model, const std::string& bytes) {
        write_file(dir / "scene" / model, bytes);
        write_file(dir / "scene/hostile.jts",
                   "render_settings { width: 8; height: 8; }\n"
                   "cameras { perspective_camera { position: <0, 0, 5>; look_at: <0, 0, 0>; } }\n"
                   "scene {\n"
                   "    mesh { file: \"" +
                       model + "\"; } }\n");
    }
    void expect_refused(const ProgramRun& r, const std::string& model,
                        const std::string& problem) const {
        EXPECT_EQ(r.code, 1) << r.err;
        const std::string where =
            "scene/hostile.jts:4:18: error: mesh 1: 'scene/" + model + "': " + problem + "\n";
        EXPECT_EQ(r.err.rfind(where, 0), 0u) << r.err;
        EXPECT_FALSE(exists("out.bmp"));
        EXPECT_TRUE(temporary_files().empty());
    }
    void expect_refused_everywhere(const std::string& model, const std::string& problem) {
        expect_refused(run({"scene/hostile.jts", "--check"}), model, problem);
        expect_refused(run({"scene/hostile.jts", "-o", "out.bmp"}), model, problem);
    }
};

// A model fuzz/model_fuzzer found (tests/hardening/regressions/model): its
// first byte picked the importer, the rest is the file.
struct FuzzedModel {
    char importer = 0;
    std::string bytes;
};
FuzzedModel fuzzed_model(const std::string& input) {
    const std::string all =
        read_file(fs::path(JT_SOURCE_DIR) / "tests/hardening/regressions/model" / input);
    if (all.empty()) return {};
    return {all[0], all.substr(1)};
}

// A triangle's three positions in a glTF buffer at `uri`.
std::string gltf_with_buffer(const std::string& uri) {
    return R"({"asset": {"version": "2.0"}, "buffers": [{"uri": ")" + uri +
           R"(", "byteLength": 36}], "bufferViews": [{"buffer": 0, "byteLength": 36}],
"accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
"max": [1, 1, 0], "min": [0, 0, 0]}], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
"nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})";
}

TEST_F(HostileModels, PlyClaimingTwoToTheFortyVerticesIsRefusedFromItsHeader) {
    write_scene_naming("claims.ply",
                       "ply\nformat binary_little_endian 1.0\nelement vertex 1099511627776\n"
                       "property float x\nproperty float y\nproperty float z\nend_header\n");
    expect_refused_everywhere(
        "claims.ply",
        "its header claims vertex 1099511627776, more than the file's 127 bytes can hold");
}

// Debian's assimp-testmodels invalid/OutOfMemory.off: 309 bytes whose header
// claims 353535235358 vertices. Assimp 5.2 took the count modulo 2^32 (1.3
// billion), allocated 16 GB for them and filled it: the CLI grew past 7 GB
// in 20 s. An OFF header's counts must fit in the file, as a PLY's must,
// however the keyword is spelt (COFF, nOFF, none).
TEST_F(HostileModels, OffClaimingBillionsOfVerticesIsRefusedFromItsHeader) {
    const std::string cube_rest =
        "-0.5 -0.5 0.5\n0.5 -0.5 0.5\n-0.5 0.5 0.5\n0.5 0.5 0.5\n-0.5 0.5 -0.5\n0.5 0.5 -0.5\n"
        "-0.5 -0.5 -0.5\n0.5 -0.5 -0.5\n4 0 1 3 2\n4 2 3 5 4\n4 4 5 7 6\n4 6 7 1 0\n"
        "4 1 7 5 3\n4 6 0 2 4\n";
    const auto bytes = [&](const std::string& header) {
        return std::to_string(header.size() + cube_rest.size());
    };
    write_scene_naming("OutOfMemory.off", "OFF\n353535235358 6 0\n" + cube_rest);
    expect_refused_everywhere("OutOfMemory.off",
                              "its OFF header claims 353535235358 vertices, more than the file's " +
                                  bytes("OFF\n353535235358 6 0\n") + " bytes can hold");
    // Faces too, after a comment and a keyword with prefixes.
    write_scene_naming("faces.off", "# made by hand\nCOFF 8 4000000000 0\n" + cube_rest);
    expect_refused_everywhere(
        "faces.off", "its OFF header claims 4000000000 faces, more than the file's " +
                         bytes("# made by hand\nCOFF 8 4000000000 0\n") + " bytes can hold");
    // Assimp reads a file that starts with OFF as one, whatever its extension.
    write_scene_naming("shape.txt", "OFF\n4000000000 6 0\n" + cube_rest);
    expect_refused_everywhere("shape.txt",
                              "its OFF header claims 4000000000 vertices, more than the file's " +
                                  bytes("OFF\n4000000000 6 0\n") + " bytes can hold");
    // A .off file may leave the keyword out and start with the counts.
    write_scene_naming("bare.off", "4000000000 6 0\n" + cube_rest);
    expect_refused_everywhere("bare.off",
                              "its OFF header claims 4000000000 vertices, more than the file's " +
                                  bytes("4000000000 6 0\n") + " bytes can hold");
    // The honest cube loads.
    write_scene_naming("cube.off", "OFF\n8 6 0\n" + cube_rest);
    const ProgramRun r = run({"scene/hostile.jts", "--check"});
    EXPECT_EQ(r.code, 0) << r.err;
}

// Found by fuzz/model_fuzzer: Assimp reads a PLY header that never ends for ever.
TEST_F(HostileModels, PlyHeaderThatNeverEndsIsRefusedInsteadOfReadForEver) {
    write_scene_naming("endless.ply",
                       "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                       "property float y\nproperty float z\n0 0 0\n1 0 0\n0 1 0\n");
    expect_refused_everywhere(
        "endless.ply", "its PLY header does not end (no end_header line within 10000 lines)");
}

// Found by fuzz/model_fuzzer: Assimp also reads for ever when the data starts
// on the end_header line itself.
TEST_F(HostileModels, PlyWhoseDataStartsOnTheEndHeaderLineIsRefused) {
    write_scene_naming("joined.ply",
                       "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                       "property float y\nproperty float z\nend_header0 0 0\n1 0 0\n0 1 0\n");
    expect_refused_everywhere("joined.ply",
                              "its PLY header's end_header line has more on it (the data must "
                              "start on the next line)");
}

// Found by fuzz/model_fuzzer: Assimp takes the magic word in any case, so the
// header's checks do too ("Ply" and "PLY" read for ever as "ply" did).
TEST_F(HostileModels, PlyHeaderChecksTakeTheMagicWordInAnyCase) {
    const FuzzedModel model = fuzzed_model("ply-capital-magic-data-on-end-header-line");
    ASSERT_EQ(model.bytes.rfind("Ply\n", 0), 0u);
    write_scene_naming("fuzzed.ply", model.bytes);
    expect_refused_everywhere("fuzzed.ply",
                              "its PLY header's end_header line has more on it (the data must "
                              "start on the next line)");
    write_scene_naming("endless.ply",
                       "PLY\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                       "property float y\nproperty float z\n0 0 0\n1 0 0\n0 1 0\n");
    expect_refused_everywhere(
        "endless.ply", "its PLY header does not end (no end_header line within 10000 lines)");
    // The same header with its end, in capitals, loads.
    write_scene_naming("capital.ply",
                       "PLY\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                       "property float y\nproperty float z\nelement face 1\n"
                       "property list uchar int vertex_indices\nend_header\n"
                       "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    const ProgramRun r = run({"scene/hostile.jts", "--check"});
    EXPECT_EQ(r.code, 0) << r.err;
}

// Found by fuzz/model_fuzzer: Assimp corrupts its heap (the program aborts)
// on a binary PLY whose header declares its vertices twice.
TEST_F(HostileModels, PlyDeclaringAnElementTwiceIsRefused) {
    write_scene_naming("twice.ply",
                       "ply\nformat binary_little_endian 1.0\nelement vertex 3\n"
                       "property float x\nelement vertex 3\nproperty float y\nend_header\n" +
                           std::string(24, '\0'));
    expect_refused_everywhere("twice.ply", "its PLY header declares the element 'vertex' twice");
}

// Found by fuzz/model_fuzzer: Assimp's glTF 1.0 importer fails its own
// assertions (an abort in Debian's build) and reads past its buffers on
// malformed files; glTF 1.0 is refused, as the language reads glTF 2.0.
TEST_F(HostileModels, GltfOneIsRefusedByItsVersion) {
    const std::pair<std::string, std::string> cases[] = {
        {"glb-failing-an-assimp-assertion",
         "it is binary glTF version 1 (.glb), which is not read: only glTF 2.0 is (convert the "
         "file to glTF 2.0)"},
        {"gltf1-reading-past-its-buffer",
         "it is glTF 1.0, which is not read: only glTF 2.0 is (convert the file to glTF 2.0)"},
    };
    for (const auto& [input, problem] : cases) {
        SCOPED_TRACE(input);
        const FuzzedModel model = fuzzed_model(input);
        ASSERT_GT(model.bytes.size(), 1000u);
        const std::string name = model.importer == 4 ? "v1.glb" : "v1.gltf";
        write_scene_naming(name, model.bytes);
        expect_refused_everywhere(name, problem);
    }
}

// Found by fuzz/model_fuzzer: Assimp 5.2 reads a glTF 2.0 accessor's elements
// without checking them against its buffer view; an animation's output moved
// 48 bytes on had it read past the end of its buffer.
TEST_F(HostileModels, GltfAccessorPastItsBufferViewIsRefused) {
    const FuzzedModel model = fuzzed_model("gltf-animation-reading-past-its-view");
    ASSERT_GT(model.bytes.size(), 1000u);
    write_scene_naming("skin.gltf", model.bytes);
    expect_refused_everywhere(
        "skin.gltf",
        "its glTF accessor 6 would read 12 elements of 16 bytes from byte 96 of "
        "buffer view 4, which holds 240");
}

// A triangle's positions in a 36-byte buffer, with the buffer view, the
// accessor and the buffer's own fields given; JSON for a .gltf file.
std::string gltf_triangle(const std::string& buffer, const std::string& view,
                          const std::string& accessor) {
    return R"({"asset": {"version": "2.0"}, "buffers": [{)" + buffer +
           R"(}], "bufferViews": [{"buffer": 0, )" + view +
           R"(}], "accessors": [{"bufferView": 0, "componentType": 5126, "type": "VEC3", )" +
           accessor + R"(}], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
"nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})";
}

const std::string kZeros36 =
    R"("uri": "data:application/octet-stream;base64,)" + std::string(48, 'A') + R"(", )";

// The same in a .glb: a header, the JSON chunk and a binary chunk of 36 bytes.
std::string glb(const std::string& json) {
    std::string padded = json;
    padded.resize((padded.size() + 3) / 4 * 4, ' ');
    const auto u32 = [](std::size_t v) {
        std::string bytes(4, '\0');
        for (int i = 0; i < 4; ++i)
            bytes[static_cast<std::size_t>(i)] = static_cast<char>(v >> (8 * i));
        return bytes;
    };
    const std::size_t total = 12 + 8 + padded.size() + 8 + 36;
    return "glTF" + u32(2) + u32(total) + u32(padded.size()) + "JSON" + padded + u32(36) +
           std::string("BIN\0", 4) + std::string(36, '\0');
}

// Every range a glTF file claims must lie inside what holds it: the view in
// its buffer, the accessor's elements (and a sparse accessor's indices) in
// their view, a .glb's buffer in its binary chunk. A file that claims more is
// refused before Assimp reads it, saying which part and by how much.
TEST_F(HostileModels, GltfRangesPastWhatHoldsThemAreRefused) {
    const struct {
        std::string name, model, problem;
    } cases[] = {
        {"view.gltf",
         gltf_triangle(kZeros36 + R"("byteLength": 36)", R"("byteOffset": 8, "byteLength": 36)",
                       R"("count": 3)"),
         "its glTF buffer view 0 takes bytes 8 to 44 of buffer 0, which holds 36"},
        {"count.gltf",
         gltf_triangle(kZeros36 + R"("byteLength": 36)", R"("byteLength": 36)", R"("count": 4)"),
         "its glTF accessor 0 would read 4 elements of 12 bytes from byte 0 of buffer view 0, "
         "which holds 36"},
        {"huge.gltf",
         gltf_triangle(kZeros36 + R"("byteLength": 36)", R"("byteLength": 36)",
                       R"("count": 18446744073709551615)"),
         "its glTF accessor 0 would read 18446744073709551615 elements of 12 bytes from byte 0 of "
         "buffer view 0, which holds 36"},
        {"stride.gltf",
         gltf_triangle(kZeros36 + R"("byteLength": 36)", R"("byteLength": 36, "byteStride": 16)",
                       R"("count": 3)"),
         "its glTF accessor 0 would read 3 elements of 12 bytes from byte 0 of buffer view 0, "
         "which holds 36"},
        {"sparse.gltf",
         gltf_triangle(kZeros36 + R"("byteLength": 36)", R"("byteLength": 36)",
                       R"("count": 3, "sparse": {"count": 2, "indices": {"bufferView": 0, )"
                       R"("byteOffset": 32, "componentType": 5125}, "values": {"bufferView": 0}})"),
         "its glTF accessor 0's sparse indices would read 2 elements of 4 bytes from byte 32 of "
         "buffer view 0, which holds 36"},
        {"chunk.glb",
         glb(gltf_triangle(R"("byteLength": 100)", R"("byteLength": 36)", R"("count": 3)")),
         "its glTF buffer 0 claims 100 bytes, more than the binary chunk's 36"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        write_scene_naming(c.name, c.model);
        expect_refused_everywhere(c.name, c.problem);
    }
    // The same files with every range inside load.
    write_scene_naming("fits.gltf", gltf_triangle(kZeros36 + R"("byteLength": 36)",
                                                  R"("byteLength": 36)", R"("count": 3)"));
    EXPECT_EQ(run({"scene/hostile.jts", "--check"}).code, 0);
    write_scene_naming("fits.glb", glb(gltf_triangle(R"("byteLength": 36)", R"("byteLength": 36)",
                                                     R"("count": 3)")));
    const ProgramRun r = run({"scene/hostile.jts", "--check"});
    EXPECT_EQ(r.code, 0) << r.err;
}

// Found by fuzz/model_fuzzer: Assimp 5.2 follows a skin's inverseBindMatrices
// without checking there is one (glTF lets a skin leave them out), and the
// program died; its JSON reader takes text that is not UTF-8, which the checks
// above must read too (the fuzzer's input: a key of simple_skin with bytes
// inserted, which hid its inverseBindMatrices).
TEST_F(HostileModels, GltfSkinWithoutInverseBindMatricesAndJsonThatDoesNotParseAreRefused) {
    std::string skinned =
        gltf_triangle(kZeros36 + R"("byteLength": 36)", R"("byteLength": 36)", R"("count": 3)");
    skinned.replace(skinned.find(R"("nodes": [{"mesh": 0}])"), 22,
                    R"("nodes": [{"mesh": 0, "skin": 0}], "skins": [{"joints": [0]}])");
    write_scene_naming("skin.gltf", skinned);
    expect_refused_everywhere("skin.gltf",
                              "its glTF skin 0 has no inverseBindMatrices (glTF allows that, but "
                              "the model reader, Assimp 5.2, fails on it)");

    const FuzzedModel model = fuzzed_model("gltf-skin-key-not-utf8");
    ASSERT_GT(model.bytes.size(), 1000u);
    write_scene_naming("bytes.gltf", model.bytes);
    expect_refused_everywhere(
        "bytes.gltf",
        "its glTF JSON does not parse: line 29, column 17: syntax error while "
        "parsing object key - invalid string: ill-formed UTF-8 byte");
}

// Assimp opens an absolute buffer path below the model's folder ("scene//etc/passwd"),
// which the confinement allows and which does not exist; a path that leaves
// the folder (..) is the confinement's to refuse.
TEST_F(HostileModels, GltfBuffersOutsideTheScenesFolderAreRefused) {
    const std::string outside = fs::absolute(dir / "outside.bin").string();
    const std::pair<std::string, std::string> cases[] = {
        {"/etc/passwd", "GLTF: could not open referenced file \"/etc/passwd\""},
        {outside, "GLTF: could not open referenced file \"" + outside + "\""},
        // Named as the file writes it, from the model's folder.
        {"../outside.bin", "it refers to '../outside.bin', outside the folder '" +
                               fs::weakly_canonical(fs::absolute(dir / "scene")).string() + "'"},
    };
    for (const auto& [uri, problem] : cases) {
        SCOPED_TRACE(uri);
        write_scene_naming("hostile.gltf", gltf_with_buffer(uri));
        expect_refused_everywhere("hostile.gltf", problem);
    }
    // The same buffer inside the folder is read (a triangle of zero area, left out).
    fs::copy_file(dir / "outside.bin", dir / "scene/inside.bin");
    write_scene_naming("hostile.gltf", gltf_with_buffer("inside.bin"));
    const ProgramRun r = run({"scene/hostile.jts", "--check"});
    EXPECT_EQ(r.code, 0) << r.err;
}

// A mesh shrunk far past what Embree's single-precision instance transform
// holds: Embree moves each ray that meets the mesh's box into the mesh's space
// by the inverse of its float map, and Debian's build aborts (assertion
// `ray.valid()`) when a component there passes 1.8e18. A quad scaled by 1e-20
// with a light 3 units away (its shadow ray's direction grows to 1e20 there),
// and a quad scaled by 1e-10 seen from 1e9 (the camera ray's origin grows to
// 1e19), each aborted the CLI.
class ShrunkMeshes : public CliSandbox {
  protected:
    // Pixel (x, y) of out.bmp counted from the bottom left (9x9, 24-bit,
    // bottom-up rows of 28 bytes), as its 3 bytes.
    std::string pixel(int x, int y) const {
        const std::string bmp = read_file(dir / "out.bmp");
        const std::size_t at = 54 + static_cast<std::size_t>(y) * 28 + x * 3;
        return bmp.size() >= at + 3 ? bmp.substr(at, 3) : "(no image)";
    }
    ProgramRun render(const std::string& camera, const std::string& meshes) const {
        write_file(dir / "quad.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n");
        write_file(dir / "shrunk.jts",
                   "render_settings { width: 9; height: 9; ambient_light: <1, 1, 1>; }\n"
                   "cameras { perspective_camera { position: " +
                       camera + "; look_at: <0, 0, 0>; aspect: 1; } }\nscene {\n" + meshes + "}\n");
        return run({"shrunk.jts", "-q", "-o", "out.bmp"});
    }
    static std::string quad(const std::string& transform) {
        return "mesh { file: \"quad.obj\"; material { pigment: <1, 1, 1>; ambient: <1, 1, 1>; } "
               "transform { " +
               transform + " } }\n";
    }
    const std::string white = std::string(3, '\xff'), black = std::string(3, '\0');
};

TEST_F(ShrunkMeshes, AMeshShrunkBy1e20LitFromThreeUnitsAwayRenders) {
    const ProgramRun r =
        render("<0, 0, 5>", quad("scale: <1e-20, 1e-20, 1e-20>;") +
                                "point_light { position: <0, 3, 0>; intensity: <1, 1, 1>; }\n");
    EXPECT_EQ(r.signal, 0) << r.err;
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(pixel(0, 0), black);
}

TEST_F(ShrunkMeshes, AMeshShrunkBy1e10SeenFromAfarIsMetByTheRayThroughIt) {
    const ProgramRun r = render("<0, 0, 1e9>", quad("scale: <1e-10, 1e-10, 1e-10>;"));
    EXPECT_EQ(r.signal, 0) << r.err;
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(pixel(4, 4), white) << "the centre pixel's ray passes through the quad's centre";
    EXPECT_EQ(pixel(0, 0), black);
}

// Rays that start past Embree's float range: each number of a scene is within
// 1e9, but a mirror scaled by 1e9 twice sends its reflections from 1e27 away,
// and Debian's Embree aborts (assertion `ray.valid()`) on a ray whose origin
// has a component past 1.8e18. The camera sits at the centre of the mirror
// (or in front of it), so the centre pixel's ray comes straight back and meets
// what stands behind the camera: it shows white, every other pixel black.
class FarRays : public CliSandbox {
  protected:
    std::string pixel(int x, int y) const {
        const std::string bmp = read_file(dir / "out.bmp");
        const std::size_t at = 54 + static_cast<std::size_t>(y) * 28 + x * 3;
        return bmp.size() >= at + 3 ? bmp.substr(at, 3) : "(no image)";
    }
    ProgramRun render(const std::string& items) const {
        write_file(dir / "quad.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n");
        write_file(dir / "far.jts",
                   "render_settings { width: 9; height: 9; ambient_light: <1, 1, 1>; "
                   "recurse_depth: 2; }\n"
                   "cameras { perspective_camera { position: <0, 0, 0>; look_at: <0, 0, -1>; "
                   "aspect: 1; } }\nscene {\n" +
                       items + "}\n");
        return run({"far.jts", "-q", "-o", "out.bmp"});
    }
    static constexpr const char* mirror_sphere =
        "sphere { radius: 1e9; material { pigment: <0, 0, 0>; reflection: 1; } "
        "transform { scale: <1e9, 1e9, 1e9>; scale: <1e9, 1e9, 1e9>; } }\n";
    static constexpr const char* white_quad_behind =
        "mesh { file: \"quad.obj\"; material { pigment: <1, 1, 1>; ambient: <1, 1, 1>; } "
        "transform { translate: <0, 0, 1>; } }\n";
    const std::string white = std::string(3, '\xff'), black = std::string(3, '\0');
};

TEST_F(FarRays, AMeshSeenInAMirrorScaledPastFloatRangeRenders) {
    const ProgramRun r = render(std::string(mirror_sphere) + white_quad_behind);
    EXPECT_EQ(r.signal, 0) << r.err;
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(pixel(4, 4), white) << "the reflection of the centre pixel's ray meets the quad";
    EXPECT_EQ(pixel(0, 0), black);
}

TEST_F(FarRays, ShadowAndSoftShadowRaysFromPastFloatRangeRender) {
    const ProgramRun r =
        render(std::string(mirror_sphere) + white_quad_behind +
               "point_light { position: <0, 0, 0.2>; intensity: <1, 1, 1>; }\n"
               "point_light { position: <0, 0, 0.3>; radius: 0.01; intensity: <1, 1, 1>; }\n");
    EXPECT_EQ(r.signal, 0) << r.err;
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(pixel(4, 4), white);
    EXPECT_EQ(pixel(0, 0), black);
}

TEST_F(FarRays, SpheresInTheirBvhSeenInAPlaneScaledPastFloatRangeRender) {
    // Ten spheres: more than are tested without a BVH.
    std::string items =
        "plane { normal: <0, 0, 1>; distance: -1; material { pigment: <0, 0, 0>; "
        "reflection: 1; } transform { scale: <1e9, 1e9, 1e9>; scale: <1e9, 1e9, 1e9>; "
        "scale: <3, 3, 3>; } }\n";
    for (int i = 0; i < 10; ++i)
        items += "sphere { radius: 0.5; center: <" + std::to_string(2 * i) +
                 ", 0, 1>; material { pigment: <1, 1, 1>; ambient: <1, 1, 1>; } }\n";
    const ProgramRun r = render(items);
    EXPECT_EQ(r.signal, 0) << r.err;
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(pixel(4, 4), white) << "the reflection of the centre pixel's ray meets a sphere";
    EXPECT_EQ(pixel(0, 0), black);
}

// Shapes whose bounds pass Embree's float range (1.8e18): its BVH leaves
// them out, so they are tested exactly on every ray instead. Each fills the
// whole view (or its reflection) 1 unit from the camera; every pixel shows it
// white.
class HugeShapes : public FarRays {
  protected:
    std::string all_white() const {
        std::string wrong;
        for (int y = 0; y < 9; ++y)
            for (int x = 0; x < 9; ++x)
                if (pixel(x, y) != white)
                    wrong += " (" + std::to_string(x) + ", " + std::to_string(y) + ")";
        return wrong;
    }
    // Nine small spheres off to the side: more than are tested without a BVH.
    static std::string small_spheres() {
        std::string items;
        for (int i = 0; i < 9; ++i)
            items += "sphere { radius: 0.1; center: <" + std::to_string(100 + i) + ", 0, 0>; }\n";
        return items;
    }
    static constexpr const char* huge = "scale: <1e9, 1e9, 1e9>; scale: <1e9, 1e9, 1e9>; ";
    static constexpr const char* lit = "material { pigment: <1, 1, 1>; ambient: <1, 1, 1>; } ";
    // A black mirror filling the view at z = -1: the reflected rays, which no
    // table lists shapes for, walk the BVH.
    static constexpr const char* mirror =
        "plane { normal: <0, 0, 1>; distance: -1; material { pigment: <0, 0, 0>; reflection: 1; "
        "} }\n";
};

TEST_F(HugeShapes, AMeshPastFloatRangeIsNotLeftOut) {
    const ProgramRun r = render(std::string("mesh { file: \"quad.obj\"; ") + lit + "transform { " +
                                huge + "scale: <9, 9, 1>; translate: <0, 0, -1>; } }\n");
    EXPECT_EQ(r.signal, 0) << r.err;
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(all_white(), "") << "pixels that miss the quad";
}

TEST_F(HugeShapes, AMeshWhoseFileIsPastFloatRangeIsNotLeftOut) {
    write_file(dir / "big.obj",
               "v -9e19 -9e19 0\nv 9e19 -9e19 0\nv 9e19 9e19 0\nv -9e19 9e19 0\nf 1 2 3 4\n");
    const ProgramRun r = render(std::string("mesh { file: \"big.obj\"; ") + lit +
                                "transform { scale: <0.1, 0.1, 0.1>; translate: <0, 0, -1>; } }\n");
    EXPECT_EQ(r.signal, 0) << r.err;
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(all_white(), "") << "pixels that miss the quad";
}

TEST_F(HugeShapes, ATrianglePastFloatRangeIsNotLeftOut) {
    const ProgramRun r =
        render(std::string("triangle { a: <-1, -1, 0>; b: <3, -1, 0>; c: <-1, 3, 0>; ") + lit +
               "transform { " + huge + "scale: <9, 9, 1>; translate: <0, 0, -1>; } }\n");
    EXPECT_EQ(r.signal, 0) << r.err;
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(all_white(), "") << "pixels that miss the triangle";
}

TEST_F(HugeShapes, AMeshPastFloatRangeCastsItsShadow) {
    // A white floor at z = -1 lit from z = 3 through the quad at z = 2.
    const ProgramRun r = render(
        "plane { normal: <0, 0, 1>; distance: -1; material { pigment: <1, 1, 1>; "
        "diffuse: <1, 1, 1>; } }\n"
        "point_light { position: <0, 0, 3>; intensity: <1, 1, 1>; }\n"
        "mesh { file: \"quad.obj\"; transform { " +
        std::string(huge) + "scale: <9, 9, 1>; translate: <0, 0, 2>; } }\n");
    EXPECT_EQ(r.signal, 0) << r.err;
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(pixel(4, 4), black) << "the quad shadows the floor";
    EXPECT_EQ(pixel(0, 0), black);
}

TEST_F(HugeShapes, ASpherePastFloatRangeAmongOthersIsNotLeftOut) {
    // Centre 9e18 behind the camera, its surface at z = 1, seen in the mirror.
    const ProgramRun r =
        render(small_spheres() + mirror + "sphere { center: <0, 0, 1>; " + lit + "transform { " +
               huge + "scale: <9, 9, 9>; translate: <0, 0, 1>; } }\n");
    EXPECT_EQ(r.signal, 0) << r.err;
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(all_white(), "") << "pixels whose reflection misses the sphere";
}

TEST_F(HugeShapes, AnEllipsoidPastFloatRangeAmongOthersIsNotLeftOut) {
    const ProgramRun r =
        render(small_spheres() + mirror + "sphere { center: <0, 0, 1>; " + lit + "transform { " +
               huge + "scale: <9, 9, 1e-18>; translate: <0, 0, 1>; } }\n");
    EXPECT_EQ(r.signal, 0) << r.err;
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(all_white(), "") << "pixels whose reflection misses the ellipsoid";
}

}  // namespace
}  // namespace jt::test
