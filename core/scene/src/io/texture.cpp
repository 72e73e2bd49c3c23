#include "jtracer/texture.hpp"

#include "io/bmp_header.hpp"
#include "io/exif_orientation.hpp"
#include "io/file_bytes.hpp"
#include "io/image_claims.hpp"
#include "io/jpeg.hpp"
#include "io/png_chunks.hpp"
#include "io/png_reader.hpp"
#include "io/stamped_cache.hpp"
#include "io/stb_failure.hpp"
#include "jtracer/bmp.hpp"
#include "jtracer/file_stamp.hpp"
#include "jtracer/image.hpp"
#include "jtracer/png.hpp"

#include <stb_image.h>

#include <algorithm>
#include <cctype>
#include <limits>
#include <optional>
#include <string_view>
#include <utility>
#include <variant>

namespace jt {

namespace {

// Pictures held after their last user lets go: a scene's few maps, between
// its validation and its render.
constexpr std::size_t kept_textures = 4;

struct StbFree {
    void operator()(void* p) const { stbi_image_free(p); }
};

std::string too_large(std::int64_t width, std::int64_t height) {
    return "the image is too large (" + std::to_string(width) + "x" + std::to_string(height) +
           " texels; an image map has at most " + std::to_string(kMaxTextureTexels) + ")";
}

// Each side below the cap first, so that the product cannot overflow.
bool exceeds_cap(std::pair<std::int64_t, std::int64_t> size) {
    return size.first > kMaxTextureTexels || size.second > kMaxTextureTexels ||
           size.first * size.second > kMaxTextureTexels;
}

// The header's verdict: "" or why the picture cannot be decoded. JPEGs go to
// libjpeg-turbo (io/jpeg.hpp), BMPs to stb_image once their header is read
// here (io/bmp_header.hpp), PNGs to libpng (io/png_reader.hpp) once stb_image
// has read their header.
std::string header_problem(std::span<const std::uint8_t> bytes, int& width, int& height) {
    if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
        return "the file is too large";
    if (bytes.empty()) return "the file is empty";
    if (has_jpeg_signature(bytes)) {
        const Expected<JpegSize> size = read_jpeg_size(bytes);
        if (!size) return size.error().message;
        width = size->width;
        height = size->height;
    } else if (has_bmp_signature(bytes)) {
        const std::optional<BmpHeader> header = read_bmp_header(bytes);
        if (!header)
            return "the file ends inside its BMP header (" + std::to_string(bytes.size()) +
                   " bytes)";
        if (std::string problem = bmp_header_problem(*header); !problem.empty()) return problem;
        // Rows stored top-down have a negative height; stb_image reads both.
        const std::int64_t rows = header->height < 0 ? -header->height : header->height;
        if (header->width <= 0 || rows == 0)
            return "the image has no pixels (" + std::to_string(header->width) + "x" +
                   std::to_string(rows) + ")";
        if (exceeds_cap({header->width, rows})) return too_large(header->width, rows);
        int channels = 0;
        if (!stbi_info_from_memory(bytes.data(), static_cast<int>(bytes.size()), &width, &height,
                                   &channels))
            return "not a readable BMP image: its header is damaged";
        width = static_cast<int>(header->width);
        height = static_cast<int>(rows);
    } else {
        if (const auto claimed = png_claimed_size(bytes); claimed && exceeds_cap(*claimed))
            return too_large(claimed->first, claimed->second);
        if (std::string problem = png_chunk_problem(bytes); !problem.empty()) return problem;
        int channels = 0;
        forget_stb_failure();
        if (!stbi_info_from_memory(bytes.data(), static_cast<int>(bytes.size()), &width, &height,
                                   &channels)) {
            if (std::string format = format_not_read(bytes); !format.empty())
                return "not a readable PNG, JPEG or BMP image: it is " + format +
                       "; save it as PNG";
            return std::string("not a readable PNG, JPEG or BMP image: ") + stb_failure_reason();
        }
    }
    if (width <= 0 || height <= 0)
        return "the image has no pixels (" + std::to_string(width) + "x" + std::to_string(height) +
               ")";
    if (exceeds_cap({width, height})) return too_large(width, height);
    if (bytes.size() < fewest_bytes_for(bytes, width, height))
        return "the file is too short for the " + std::to_string(width) + "x" +
               std::to_string(height) + " pixels its header claims (" +
               std::to_string(bytes.size()) + " bytes)";
    return "";
}

// stb_image's top-down rows (a BMP's), bottom-up.
template <class Sample>
std::vector<Sample> bottom_up(const Sample* samples, int width, int height) {
    std::vector<Sample> out(static_cast<std::size_t>(width) * height * 3);
    const std::size_t row = static_cast<std::size_t>(width) * 3;
    for (int j = 0; j < height; ++j)
        std::copy_n(samples + row * static_cast<std::size_t>(flipped_row(j, height)), row,
                    out.data() + row * static_cast<std::size_t>(j));
    return out;
}

// A TGA before version 2 has no signature to tell it by: its name does.
std::string named_by_extension(const std::filesystem::path& path, const Error& error) {
    constexpr std::string_view kUnknown =
        "not a readable PNG, JPEG or BMP image: unknown image type";
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (error.message == kUnknown && extension == ".tga")
        return "not a readable PNG, JPEG or BMP image: it is a TGA image; save it as PNG";
    return error.message;
}

}  // namespace

Expected<Texture> decode_texture(std::span<const std::uint8_t> bytes, TextureLayout layout) {
    int header_width = 0, header_height = 0;
    if (std::string problem = header_problem(bytes, header_width, header_height); !problem.empty())
        return Error{problem};
    // The pixels must be the size the header was checked for.
    int width = 0, height = 0, channels = 0;
    auto as_checked = [&] { return width == header_width && height == header_height; };
    if (has_jpeg_signature(bytes)) {
        Expected<std::vector<std::uint8_t>> rgb = decode_jpeg(bytes, {header_width, header_height});
        if (!rgb) return rgb.error();
        const int orientation = layout == TextureLayout::as_shown ? exif_orientation(bytes) : 1;
        if (orientation == 1) return Texture{header_width, header_height, std::move(*rgb), {}};
        std::vector<std::uint8_t> upright =
            turn_upright(*rgb, header_width, header_height, orientation);
        if (swaps_sides(orientation)) std::swap(header_width, header_height);
        return Texture{header_width, header_height, std::move(upright), {}};
    }
    if (has_png_signature(bytes)) {
        Expected<PngPixels> png = read_png_pixels(bytes, true);
        if (!png) return Error{"cannot decode the image: " + png.error().message};
        width = png->width;
        height = png->height;
        if (!as_checked())
            return Error{"cannot decode the image: its pixels are not the size its header gives"};
        return Texture{width, height, std::move(png->rgb8), std::move(png->rgb16)};
    }
    // A BMP of 24 bits a pixel uncompressed, the kind JTracer and most
    // programs write, is read by decode_bmp straight into the rows kept:
    // stb_image's texels, then turned round, held the picture twice. Any
    // other kind (and one decode_bmp refuses) goes to stb_image.
    // Its pixels must start where stb_image would take them, past the headers
    // and at most 1024 bytes after them; stb_image refuses the rest.
    auto pixels_where_stb_reads = [&](const BmpHeader& header) {
        const std::uint64_t offset = std::uint64_t{bytes[10]} | std::uint64_t{bytes[11]} << 8 |
                                     std::uint64_t{bytes[12]} << 16 |
                                     std::uint64_t{bytes[13]} << 24;
        const std::uint64_t headers = 14 + std::uint64_t{header.info_size};
        return offset >= headers && offset - headers <= 1024;
    };
    if (const std::optional<BmpHeader> header = read_bmp_header(bytes);
        header && header->bits_per_pixel == 24 && header->compression == 0 &&
        header->info_size >= 40 && pixels_where_stb_reads(*header)) {
        if (Expected<Image8> image = decode_bmp(bytes);
            image && image->width == header_width && image->height == header_height)
            return Texture{image->width, image->height, std::move(image->rgb), {}};
    }
    // Any other BMP: 8-bit samples.
    forget_stb_failure();
    std::unique_ptr<stbi_uc, StbFree> samples(stbi_load_from_memory(
        bytes.data(), static_cast<int>(bytes.size()), &width, &height, &channels, 3));
    if (samples && as_checked())
        return Texture{width, height, bottom_up(samples.get(), width, height), {}};
    const bool decoded = samples != nullptr;
    if (decoded)
        return Error{"cannot decode the image: its pixels are not the size its header gives"};
    return Error{std::string("cannot decode the image: ") + stb_failure_reason()};
}

Expected<std::shared_ptr<const Texture>> load_texture(const std::filesystem::path& path,
                                                      TextureLayout layout) {
    // A picture the same in both layouts is held under its path and nullopt;
    // a JPEG its EXIF orientation turns, once for each layout.
    using Key = std::pair<std::string, std::optional<TextureLayout>>;
    static StampedCache<Key, Texture> cache(kept_textures);
    std::error_code error;
    const std::filesystem::path absolute = std::filesystem::absolute(path, error);
    const FileStamp stamp = file_stamp(absolute);
    auto decode = [&](std::span<const std::uint8_t> bytes) -> Expected<Texture> {
        Expected<Texture> texture = decode_texture(bytes, layout);
        if (!texture) return Error{file_message(path, named_by_extension(path, texture.error()))};
        return texture;
    };
    const std::string name = absolute.lexically_normal().string();
    if (!error && stamp.exists) {
        if (std::shared_ptr<const Texture> held = cache.find({name, std::nullopt}, stamp))
            return held;
        if (std::shared_ptr<const Texture> held = cache.find({name, layout}, stamp)) return held;
    }
    Expected<std::vector<std::uint8_t>> bytes = read_file_bytes(path);
    if (!bytes) return bytes.error();
    if (error || !stamp.exists) {
        Expected<Texture> texture = decode(*bytes);
        if (!texture) return texture.error();
        return std::make_shared<const Texture>(std::move(*texture));
    }
    const bool turned = has_jpeg_signature(*bytes) && exif_orientation(*bytes) != 1;
    const Key key{name, turned ? std::optional(layout) : std::nullopt};
    return cache.get(key, stamp, [&] { return decode(*bytes); });
}

std::filesystem::path asset_path(const Scene& scene, const std::string& name) {
    const std::filesystem::path file(name);
    if (file.is_absolute() || scene.asset_folder.empty()) return file;
    return std::filesystem::path(scene.asset_folder) / file;
}

NamedFiles named_files(const Scene& scene) {
    NamedFiles files;
    auto add = [&](std::vector<std::filesystem::path>& to, const std::string& name) {
        if (name.empty()) return;
        const std::filesystem::path path = asset_path(scene, name);
        if (std::find(to.begin(), to.end(), path) == to.end()) to.push_back(path);
    };
    add(files.images, scene.settings.background_map);
    for (const Primitive& p : scene.primitives) {
        if (const auto* mesh = shape_if<Mesh>(&p.shape)) add(files.models, mesh->file);
        add(files.images, p.material.finish->image_map);
    }
    return files;
}

}  // namespace jt
