#include "jtracer/frontend/existing_output.hpp"

#include "jtracer/frontend/command_line.hpp"

#include "jtracer/bmp.hpp"
#include "jtracer/png.hpp"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <vector>

#include <zlib.h>

namespace jt::frontend {

namespace {

std::uint32_t big_endian32(const std::uint8_t* p) {
    return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) |
           p[3];
}

std::uint32_t little_endian32(const std::uint8_t* p) {
    return p[0] | (std::uint32_t{p[1]} << 8) | (std::uint32_t{p[2]} << 16) |
           (std::uint32_t{p[3]} << 24);
}

// A PNG chunk's bytes besides its data: its length, type and checksum, four
// bytes each.
constexpr std::size_t png_chunk_overhead = 12;

// The smallest BMP: its file header (14 bytes) and BITMAPINFOHEADER (40).
constexpr std::size_t bmp_headers_bytes = 54;

// Why a PNG's bytes are not whole: the PNG decoder fills in what a truncated
// stream lacks rather than refuse it, so the chunks are walked here, each
// with its checksum, up to an IEND that ends the file.
std::optional<std::string> png_damage(const std::vector<std::uint8_t>& bytes) {
    static constexpr std::uint8_t signature[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    if (bytes.size() < std::size(signature) ||
        !std::equal(std::begin(signature), std::end(signature), bytes.begin()))
        return "it is not a PNG";
    std::size_t at = std::size(signature);
    while (bytes.size() - at >= png_chunk_overhead) {
        const std::uint64_t length = big_endian32(&bytes[at]);
        if (length > bytes.size() - at - png_chunk_overhead)
            return "it is cut short (a chunk runs past its end)";
        const std::uint8_t* type = &bytes[at + 4];
        if (crc32_z(0, type, length + 4) != big_endian32(type + 4 + length))
            return "it is damaged (a chunk's checksum does not match)";
        at += png_chunk_overhead + length;
        if (std::equal(type, type + 4, "IEND"))
            return at == bytes.size() ? std::nullopt
                                      : std::optional<std::string>("bytes follow its end");
    }
    return "it is cut short (no IEND chunk)";
}

std::optional<std::string> bmp_damage(const std::vector<std::uint8_t>& bytes) {
    if (bytes.size() < bmp_headers_bytes || bytes[0] != 'B' || bytes[1] != 'M')
        return "it is not a BMP";
    if (little_endian32(&bytes[2]) != bytes.size())
        return "it is cut short (" + std::to_string(bytes.size()) + " bytes, its header says " +
               std::to_string(little_endian32(&bytes[2])) + ")";
    return std::nullopt;
}

std::string size_text(int width, int height) {
    return std::to_string(width) + "x" + std::to_string(height);
}

// Why a region part there is not the one wanted: another region, or this
// region of another render (a stale part of an earlier version of the scene).
std::string part_difference(const RegionPlacement& there, const RegionPlacement& wanted) {
    if (there.frame_width != wanted.frame_width || there.frame_height != wanted.frame_height ||
        !(there.region == wanted.region))
        return "it holds another region (" + format_frame_region(there.region) + " of a " +
               size_text(there.frame_width, there.frame_height) + " frame)";
    if (!there.fingerprint || !wanted.fingerprint)
        return "it is this region, but records no render fingerprint (an older jtracer-cli)";
    const RenderFingerprint& a = *there.fingerprint;
    const RenderFingerprint& b = *wanted.fingerprint;
    std::string what;
    auto add = [&](const char* name) { what += (what.empty() ? "" : ", ") + std::string(name); };
    if (a.scene != b.scene) add("the scene's content");
    if (a.samples != b.samples) add("samples");
    if (a.camera != b.camera || a.camera_name != b.camera_name) add("camera");
    if (a.clock != b.clock) add("clock");
    return "it is this region of another render (differing in " + what + ")";
}

}  // namespace

ExistingOutput check_existing_output(const std::string& path, const WantedOutput& wanted) {
    ExistingOutput existing;
    std::error_code error;
    const auto status = std::filesystem::status(path, error);
    if (!std::filesystem::exists(status)) return existing;
    existing.exists = true;
    auto refuse = [&](std::string why) {
        existing.why_not = std::move(why);
        return existing;
    };
    if (!std::filesystem::is_regular_file(status)) return refuse("it is not a regular file");
    std::ifstream in(path, std::ios::binary);
    std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                    std::istreambuf_iterator<char>());
    if (!in.good() && !in.eof()) return refuse("it cannot be read");
    const std::optional<std::string> damage =
        wanted.format == ImageFormat::png ? png_damage(bytes) : bmp_damage(bytes);
    if (damage) return refuse(*damage);
    if (wanted.placement) {
        Expected<RegionPart> part = read_region_bmp(path);
        if (!part) return refuse(part.error().message);
        if (!(part->placement == *wanted.placement))
            return refuse(part_difference(part->placement, *wanted.placement));
        existing.keep = true;
        return existing;
    }
    Expected<Image8> image =
        wanted.format == ImageFormat::png ? decode_png(bytes) : decode_bmp(bytes);
    if (!image) return refuse(image.error().message);
    if (image->width != wanted.width || image->height != wanted.height)
        return refuse("it is " + size_text(image->width, image->height) + ", not " +
                      size_text(wanted.width, wanted.height));
    existing.keep = true;
    return existing;
}

bool keep_existing_output(std::string_view program, bool quiet, const std::string& path,
                          const WantedOutput& wanted, const std::string& what) {
    const ExistingOutput existing = check_existing_output(path, wanted);
    if (!quiet) {
        if (existing.keep)
            std::cerr << "kept " << path << what << ": already there and complete\n";
        else if (existing.exists)
            std::cerr << program << ": note: " << path << " is there, but " << existing.why_not
                      << ": rendering it again\n";
    }
    return existing.keep;
}

std::optional<std::string> skip_existing_refusal(const RenderFlags& flags) {
    if (flags.output_is_stdout) return "standard output (-o -) holds no earlier image to keep";
    if (flags.output && is_stream(*flags.output))
        return "'" + *flags.output + "' is a device or a pipe, not a file to keep";
    return std::nullopt;
}

}  // namespace jt::frontend
