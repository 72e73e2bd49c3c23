#pragma once
// Model files with materials, written by tests (docs/language.md §14.5):
// glTF 2.0 files with a base colour factor and texture in each of the three
// ways a glTF holds a picture.

#include "jtracer/image.hpp"
#include "jtracer/scene.hpp"

#include <filesystem>
#include <string>
#include <string_view>

namespace jt::test {

std::string base64(std::string_view bytes);

// A PNG file's bytes.
std::string png_file(const Image8& image);

enum class GltfPicture { external, in_glb, data_uri };

// Two triangles in the plane z = 0, counter-clockwise seen from +z: the first,
// (-4, -2), (0, -2), (-2, 2), is a primitive with material "painted"
// (baseColorFactor `factor`, alpha 0.5; baseColorTexture `picture`; every
// corner at glTF texture coordinates `uv`); the second, (0, -2), (4, -2),
// (2, 2), a primitive without a material. `file` ends in .gltf, or .glb for
// GltfPicture::in_glb; an external picture is written beside it as
// `picture_name`.
void write_painted_gltf(const std::filesystem::path& file, GltfPicture how, const Image8& picture,
                        const Colour& factor, double u, double v,
                        const std::string& picture_name = "picture.png");

}  // namespace jt::test
