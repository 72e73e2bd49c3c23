#include "common/material_models.hpp"

#include "common/files.hpp"
#include "jtracer/png.hpp"

#include <cstdint>
#include <cstring>
#include <sstream>

namespace jt::test {

namespace {

std::string floats(std::initializer_list<float> values) {
    std::string bytes(values.size() * 4, '\0');
    std::size_t at = 0;
    for (const float f : values) {
        std::memcpy(&bytes[at], &f, 4);  // x86-64: little-endian, as glTF stores them
        at += 4;
    }
    return bytes;
}

void pad4(std::string& bytes, char with) {
    while (bytes.size() % 4 != 0) bytes.push_back(with);
}

std::string u32(std::uint32_t value) {
    std::string bytes(4, '\0');
    std::memcpy(bytes.data(), &value, 4);
    return bytes;
}

}  // namespace

std::string base64(std::string_view bytes) {
    static constexpr char digits[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        std::uint32_t n = static_cast<std::uint8_t>(bytes[i]) << 16;
        if (i + 1 < bytes.size()) n |= static_cast<std::uint8_t>(bytes[i + 1]) << 8;
        if (i + 2 < bytes.size()) n |= static_cast<std::uint8_t>(bytes[i + 2]);
        out.push_back(digits[(n >> 18) & 63]);
        out.push_back(digits[(n >> 12) & 63]);
        out.push_back(i + 1 < bytes.size() ? digits[(n >> 6) & 63] : '=');
        out.push_back(i + 2 < bytes.size() ? digits[n & 63] : '=');
    }
    return out;
}

std::string png_file(const Image8& image) {
    const std::vector<std::uint8_t> bytes = encode_png(image);
    return {bytes.begin(), bytes.end()};
}

void write_painted_gltf(const std::filesystem::path& file, GltfPicture how, const Image8& picture,
                        const Colour& factor, double u, double v, const std::string& picture_name) {
    const auto fu = static_cast<float>(u), fv = static_cast<float>(v);
    std::string bin = floats({-4, -2, 0, 0, -2, 0, -2, 2, 0}) +
                      floats({0, -2, 0, 4, -2, 0, 2, 2, 0}) + floats({fu, fv, fu, fv, fu, fv});
    const std::string png = png_file(picture);
    std::ostringstream json;
    json.precision(17);
    json << R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],)"
         << R"("nodes":[{"mesh":0}],"meshes":[{"primitives":[)"
         << R"({"attributes":{"POSITION":0,"TEXCOORD_0":2},"material":0},)"
         << R"({"attributes":{"POSITION":1}}]}],)"
         << R"("materials":[{"name":"painted","pbrMetallicRoughness":{"baseColorFactor":[)"
         << factor.x << "," << factor.y << "," << factor.z
         << R"(,0.5],"baseColorTexture":{"index":0}}}],)"
         << R"("textures":[{"source":0}],)";
    if (how == GltfPicture::external) {
        write_file(file.parent_path() / picture_name, png);
        json << R"("images":[{"uri":")" << picture_name << R"("}],)";
    } else if (how == GltfPicture::data_uri) {
        json << R"("images":[{"uri":"data:image/png;base64,)" << base64(png) << R"("}],)";
    } else {
        json << R"("images":[{"bufferView":3,"mimeType":"image/png"}],)";
    }
    const std::size_t total = bin.size() + (how == GltfPicture::in_glb ? png.size() : 0);
    json
        << R"("accessors":[)"
        << R"({"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[-4,-2,0],"max":[0,2,0]},)"
        << R"({"bufferView":1,"componentType":5126,"count":3,"type":"VEC3","min":[0,-2,0],"max":[4,2,0]},)"
        << R"({"bufferView":2,"componentType":5126,"count":3,"type":"VEC2"}],)"
        << R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36},)"
        << R"({"buffer":0,"byteOffset":36,"byteLength":36},)"
        << R"({"buffer":0,"byteOffset":72,"byteLength":24})";
    if (how == GltfPicture::in_glb)
        json << R"(,{"buffer":0,"byteOffset":96,"byteLength":)" << png.size() << "}";
    json << R"(],"buffers":[{"byteLength":)" << total;
    if (how != GltfPicture::in_glb)
        json << R"(,"uri":"data:application/octet-stream;base64,)" << base64(bin) << R"("}]})";
    else
        json << "}]}";
    if (how != GltfPicture::in_glb) {
        write_file(file, json.str());
        return;
    }
    bin += png;
    pad4(bin, '\0');
    std::string text = json.str();
    pad4(text, ' ');
    const std::string glb =
        "glTF" + u32(2) + u32(static_cast<std::uint32_t>(12 + 8 + text.size() + 8 + bin.size())) +
        u32(static_cast<std::uint32_t>(text.size())) + "JSON" + text +
        u32(static_cast<std::uint32_t>(bin.size())) + std::string("BIN\0", 4) + bin;
    write_file(file, glb);
}

}  // namespace jt::test
