#include "jtracer/bmp.hpp"

#include "io/reserve_records.hpp"

#include "io/file_bytes.hpp"
#include "jtracer/atomic_file.hpp"
#include "jtracer/limits.hpp"

#include <algorithm>
#include <cstdlib>

namespace jt {

namespace {

constexpr std::size_t file_header_size = 14;
constexpr std::size_t info_header_size = 40;
constexpr std::size_t header_size = file_header_size + info_header_size;

std::size_t row_stride(int width) {
    return (static_cast<std::size_t>(width) * 3 + 3) & ~std::size_t{3};
}

void put16(std::uint8_t* p, std::uint32_t v) {
    p[0] = static_cast<std::uint8_t>(v);
    p[1] = static_cast<std::uint8_t>(v >> 8);
}

void put32(std::uint8_t* p, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) p[i] = static_cast<std::uint8_t>(v >> (8 * i));
}

std::uint32_t get16(const std::uint8_t* p) {
    return p[0] | (std::uint32_t{p[1]} << 8);
}

std::uint32_t get32(const std::uint8_t* p) {
    return p[0] | (std::uint32_t{p[1]} << 8) | (std::uint32_t{p[2]} << 16) |
           (std::uint32_t{p[3]} << 24);
}

// A piece of a BMP written at a time, so that it stays in the cache between
// being made and being written.
constexpr std::size_t bmp_piece_bytes = std::size_t{256} << 10;

std::size_t pixel_bytes(const Image8& image) {
    return row_stride(image.width) * static_cast<std::size_t>(image.height);
}

void put_header(const Image8& image, std::uint8_t* h) {
    const std::size_t pixels = pixel_bytes(image);
    h[0] = 'B';
    h[1] = 'M';
    put32(h + 2, static_cast<std::uint32_t>(header_size + pixels));
    put32(h + 10, header_size);  // offset of the pixels
    put32(h + 14, info_header_size);
    put32(h + 18, static_cast<std::uint32_t>(image.width));
    put32(h + 22, static_cast<std::uint32_t>(image.height));  // positive: bottom-up
    put16(h + 26, 1);                                         // planes
    put16(h + 28, 24);                                        // bits per pixel
    put32(h + 30, 0);                                         // BI_RGB
    put32(h + 34, static_cast<std::uint32_t>(pixels));
    put32(h + 38, 2835);  // 72 dpi, in pixels per metre
    put32(h + 42, 2835);
}

// Rows [y0, y1) as the file stores them (BGR, each padded with zeros to 4
// bytes), from `out` on.
void put_rows(const Image8& image, int y0, int y1, std::uint8_t* out) {
    const std::size_t stride = row_stride(image.width);
    for (int y = y0; y < y1; ++y) {
        std::uint8_t* row = out + stride * static_cast<std::size_t>(y - y0);
        const std::uint8_t* src = image.pixel(0, y);
        for (int x = 0; x < image.width; ++x) {
            row[3 * x + 0] = src[3 * x + 2];
            row[3 * x + 1] = src[3 * x + 1];
            row[3 * x + 2] = src[3 * x + 0];
        }
        std::fill(row + 3 * static_cast<std::size_t>(image.width), row + stride, std::uint8_t{0});
    }
}

}  // namespace

std::vector<std::uint8_t> encode_bmp(const Image8& image) {
    std::vector<std::uint8_t> out = zeroed_records<std::uint8_t>(header_size + pixel_bytes(image));
    put_header(image, out.data());
    put_rows(image, 0, image.height, out.data() + header_size);
    return out;
}

Expected<Image8> decode_bmp(std::span<const std::uint8_t> bytes) {
    if (bytes.size() < 2 || bytes[0] != 'B' || bytes[1] != 'M')
        return Error{"not a BMP file (no 'BM' header)"};
    if (bytes.size() < header_size)
        return Error{"BMP file is truncated: " + std::to_string(bytes.size()) +
                     " bytes, fewer than its headers take"};
    const std::uint8_t* h = bytes.data();
    std::uint32_t offset = get32(h + 10);
    std::uint32_t info_size = get32(h + 14);
    auto width = static_cast<std::int32_t>(get32(h + 18));
    auto height = static_cast<std::int32_t>(get32(h + 22));
    if (info_size < info_header_size)
        return Error{"unsupported BMP header (older than BITMAPINFOHEADER)"};
    if (get16(h + 28) != 24) return Error{"unsupported BMP: only 24 bits per pixel are read"};
    if (get32(h + 30) != 0) return Error{"unsupported BMP: compressed (only BI_RGB is read)"};
    bool top_down = height < 0;
    std::int64_t rows = std::llabs(static_cast<std::int64_t>(height));
    if (width <= 0 || rows == 0 || width > kMaxImageSide || rows > kMaxImageSide)
        return Error{std::string("BMP size out of range: ") + std::to_string(width) + " by " +
                     std::to_string(rows)};
    const std::size_t stride = row_stride(width);
    if (offset > bytes.size() || bytes.size() - offset < stride * static_cast<std::size_t>(rows))
        return Error{"BMP file is truncated"};
    Image8 image(width, static_cast<int>(rows));
    for (int y = 0; y < image.height; ++y) {
        int stored = top_down ? flipped_row(y, image.height) : y;
        const std::uint8_t* row = h + offset + stride * static_cast<std::size_t>(stored);
        std::uint8_t* dst = image.pixel(0, y);
        for (int x = 0; x < width; ++x) {
            dst[3 * x + 0] = row[3 * x + 2];
            dst[3 * x + 1] = row[3 * x + 1];
            dst[3 * x + 2] = row[3 * x + 0];
        }
    }
    return image;
}

Expected<void> write_bmp(const std::filesystem::path& path, const Image8& image) {
    if (header_size + row_stride(image.width) * static_cast<std::size_t>(image.height) >
        kMaxBmpFileBytes)
        return Error{"cannot write " +
                     file_message(path, "the image is too large for a BMP (4 GiB)")};
    // The header, then as many rows a piece as fit bmp_piece_bytes (one at least).
    const std::size_t stride = row_stride(image.width);
    const int rows_a_piece = static_cast<int>(std::max<std::size_t>(1, bmp_piece_bytes / stride));
    std::vector<std::uint8_t> piece(std::max(
        header_size, stride * static_cast<std::size_t>(std::min(rows_a_piece, image.height))));
    bool header_written = false;
    int next_row = 0;
    return write_file_atomically(path, [&]() -> std::span<const std::uint8_t> {
        if (!header_written) {
            header_written = true;
            put_header(image, piece.data());
            return {piece.data(), header_size};
        }
        if (next_row >= image.height) return {};
        const int end = std::min(image.height, next_row + rows_a_piece);
        put_rows(image, next_row, end, piece.data());
        const std::size_t bytes = stride * static_cast<std::size_t>(end - next_row);
        next_row = end;
        return {piece.data(), bytes};
    });
}

Expected<Image8> read_bmp(const std::filesystem::path& path) {
    Expected<std::vector<std::uint8_t>> bytes = read_file_bytes(path);
    if (!bytes) return bytes.error();
    Expected<Image8> image = decode_bmp(*bytes);
    if (!image) return Error{file_message(path, image.error().message)};
    return image;
}

}  // namespace jt
