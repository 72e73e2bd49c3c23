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

// Texel (i, j) is rgb[3 * (j * width + i)], row j = 0 at the bottom of the
// picture; values are byte / 255 (16-bit samples: value / 65535), no gamma.
struct Texture {
    int width = 0;
    int height = 0;
    std::vector<float> rgb;
};

// Pictures larger than this many texels are refused rather than decoded.
inline constexpr std::int64_t kMaxTextureTexels = std::int64_t{1} << 28;

// A PNG, JPEG or BMP; grey, palette and alpha images become RGB.
Expected<Texture> decode_texture(std::span<const std::uint8_t> bytes);

// The file decoded, from memory when an unchanged copy is held: the validator
// decodes every image map, so that --check refuses what the render would
// (a JPEG whose data ends early), and the render that follows decodes it no
// more (io/stamped_cache.hpp). Errors name the file.
Expected<std::shared_ptr<const Texture>> load_texture(const std::filesystem::path& path);

// Where a file name of the scene is found: relative names from its asset_folder.
std::filesystem::path asset_path(const Scene& scene, const std::string& name);

// Every file the scene names, each once in scene order, as asset_path finds it.
struct NamedFiles {
    std::vector<std::filesystem::path> models;  // of meshes
    std::vector<std::filesystem::path> images;  // of image maps
};
NamedFiles named_files(const Scene& scene);

}  // namespace jt
