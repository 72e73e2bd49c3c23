#pragma once
// Image maps (docs/language.md §13.4): a picture decoded once into linear
// texel values, shared by every material that names its file.

#include "jtracer/error.hpp"
#include "jtracer/scene.hpp"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace jt {

// The samples as decoded, 8 bits a channel (16 for a 16-bit PNG, then in
// rgb16 and rgb8 is empty): 3 or 6 bytes a texel rather than 12 as floats,
// which held a 16000 x 12000 JPEG in 2.3 GB. Texel (i, j) starts at
// 3 * (j * width + i), row j = 0 at the bottom of the picture.
struct Texture {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgb8;
    std::vector<std::uint16_t> rgb16;
};

// Texel (i, j)'s channels: byte / 255 (16-bit samples: value / 65535) in
// single precision, as docs/language.md §13.4 says, no gamma.
inline Colour texel(const Texture& t, int i, int j) {
    const std::size_t at = 3 * (static_cast<std::size_t>(j) * t.width + i);
    if (!t.rgb16.empty()) {
        const std::uint16_t* p = &t.rgb16[at];
        return {static_cast<float>(p[0]) / 65535.0f, static_cast<float>(p[1]) / 65535.0f,
                static_cast<float>(p[2]) / 65535.0f};
    }
    const std::uint8_t* p = &t.rgb8[at];
    return {static_cast<float>(p[0]) / 255.0f, static_cast<float>(p[1]) / 255.0f,
            static_cast<float>(p[2]) / 255.0f};
}

// Pictures larger than this many texels are refused rather than decoded.
inline constexpr std::int64_t kMaxTextureTexels = std::int64_t{1} << 28;

// Whether a JPEG's EXIF orientation (tag 274) turns its texels. A scene's
// image_map and background_map are a user's pictures, read as viewers show
// them (as_shown). A model's textures are read as stored: its UVs were made
// in a 3D tool against the stored texels, and such tools (Blender, Assimp,
// glTF viewers) ignore the tag (docs/language.md §13.4, §14.5).
enum class TextureLayout { as_shown, as_stored };

// A PNG, JPEG or BMP; grey, palette and alpha images become RGB.
Expected<Texture> decode_texture(std::span<const std::uint8_t> bytes,
                                 TextureLayout layout = TextureLayout::as_shown);

// The file decoded, from memory when an unchanged copy is held: the validator
// decodes every image map, so that --check refuses what the render would
// (a JPEG whose data ends early), and the render that follows decodes it no
// more (io/stamped_cache.hpp). A picture the layout leaves as it is (any but
// a JPEG turned by its EXIF orientation) is held once for both layouts.
// Errors name the file.
Expected<std::shared_ptr<const Texture>> load_texture(
    const std::filesystem::path& path, TextureLayout layout = TextureLayout::as_shown);

// Where a file name of the scene is found: relative names from its asset_folder.
std::filesystem::path asset_path(const Scene& scene, const std::string& name);

// Every file the scene names, each once in scene order, as asset_path finds it.
struct NamedFiles {
    std::vector<std::filesystem::path> models;  // of meshes
    std::vector<std::filesystem::path> images;  // the background map, then image maps
};
NamedFiles named_files(const Scene& scene);

}  // namespace jt
