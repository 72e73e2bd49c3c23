// BMP and PNG files, atomic writes and the image diff.

#include "common/files.hpp"
#include "common/image_header.hpp"
#include "common/scratch_dir.hpp"
#include "jtracer/atomic_file.hpp"
#include "jtracer/bmp.hpp"
#include "jtracer/image_diff.hpp"
#include "jtracer/image_file.hpp"
#include "jtracer/png.hpp"
#include "jtracer/texture.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

namespace jt {
namespace {

namespace fs = std::filesystem;

// A 3x2 image (row stride 9 bytes, padded to 12) whose every byte differs.
Image8 sample_image() {
    Image8 image(3, 2);
    for (std::size_t i = 0; i < image.rgb.size(); ++i)
        image.rgb[i] = static_cast<std::uint8_t>(10 + 11 * i);
    return image;
}

std::uint32_t le32(const std::vector<std::uint8_t>& b, std::size_t at) {
    return b[at] | (b[at + 1] << 8) | (b[at + 2] << 16) | (std::uint32_t(b[at + 3]) << 24);
}

using test::make_scratch_dir;

TEST(Bmp, HeaderLayoutAndBottomUpPaddedBgrRows) {
    Image8 image = sample_image();
    std::vector<std::uint8_t> b = encode_bmp(image);
    ASSERT_EQ(b.size(), 54u + 2 * 12);
    EXPECT_EQ(b[0], 'B');
    EXPECT_EQ(b[1], 'M');
    EXPECT_EQ(le32(b, 2), b.size());
    EXPECT_EQ(le32(b, 10), 54u);  // pixel data offset
    EXPECT_EQ(le32(b, 14), 40u);  // BITMAPINFOHEADER
    EXPECT_EQ(le32(b, 18), 3u);
    EXPECT_EQ(le32(b, 22), 2u);  // positive height: bottom-up
    EXPECT_EQ(b[26] | (b[27] << 8), 1);
    EXPECT_EQ(b[28] | (b[29] << 8), 24);
    EXPECT_EQ(le32(b, 30), 0u);  // BI_RGB
    EXPECT_EQ(le32(b, 34), 24u);
    // The first stored row is y = 0, in BGR order, then 3 zero bytes of padding.
    const std::uint8_t* p0 = image.pixel(0, 0);
    EXPECT_EQ(b[54], p0[2]);
    EXPECT_EQ(b[55], p0[1]);
    EXPECT_EQ(b[56], p0[0]);
    EXPECT_EQ(b[54 + 9], 0);
    EXPECT_EQ(b[54 + 10], 0);
    EXPECT_EQ(b[54 + 11], 0);
    const std::uint8_t* p1 = image.pixel(2, 1);
    EXPECT_EQ(b[54 + 12 + 6], p1[2]);
    EXPECT_EQ(b[54 + 12 + 8], p1[0]);
}

TEST(Bmp, RoundTripAndRejectsBadFiles) {
    Image8 image = sample_image();
    std::vector<std::uint8_t> bytes = encode_bmp(image);
    const Expected<Image8> back = decode_bmp(bytes);
    ASSERT_TRUE(back) << back.error().message;
    EXPECT_TRUE(*back == image);

    auto refusal = [](const std::vector<std::uint8_t>& bad) {
        const Expected<Image8> decoded = decode_bmp(bad);
        return decoded ? std::string() : decoded.error().message;
    };
    std::vector<std::uint8_t> truncated(bytes.begin(), bytes.end() - 5);
    EXPECT_NE(refusal(truncated).find("truncated"), std::string::npos);
    std::vector<std::uint8_t> not_bmp = bytes;
    not_bmp[0] = 'X';
    EXPECT_NE(refusal(not_bmp), "");
    std::vector<std::uint8_t> eight_bit = bytes;
    eight_bit[28] = 8;
    EXPECT_NE(refusal(eight_bit).find("24 bits"), std::string::npos);
}

// write_bmp makes the file a few rows at a time: every width's padding and
// every boundary between pieces must give encode_bmp's bytes.
TEST(Bmp, TheFileWrittenInPiecesIsTheEncodedImage) {
    fs::path dir = make_scratch_dir("bmp_pieces");
    // 2,000 pixels a row is 6,000 bytes: many pieces; 1-7 pixels cover every padding.
    for (const auto& [width, height] : {std::pair{2000, 200}, std::pair{1, 1}, std::pair{2, 70000},
                                        std::pair{5, 3}, std::pair{7, 40000}}) {
        Image8 image(width, height);
        for (std::size_t i = 0; i < image.rgb.size(); ++i)
            image.rgb[i] = static_cast<std::uint8_t>((i * 2654435761u) >> 13);
        const fs::path file = dir / "pieces.bmp";
        const Expected<void> written = write_bmp(file, image);
        ASSERT_TRUE(written) << written.error().message;
        const std::vector<std::uint8_t> encoded = encode_bmp(image);
        const std::string on_disk = test::read_file(file);
        ASSERT_EQ(on_disk.size(), encoded.size()) << width << "x" << height;
        EXPECT_TRUE(std::equal(encoded.begin(), encoded.end(),
                               reinterpret_cast<const std::uint8_t*>(on_disk.data())))
            << width << "x" << height;
    }
}

TEST(AtomicFile, PiecesAreWrittenOneAfterAnother) {
    fs::path dir = make_scratch_dir("atomic_pieces");
    const std::vector<std::vector<std::uint8_t>> pieces{{'a', 'b'}, {'c'}, {'d', 'e', 'f'}};
    std::size_t next = 0;
    const Expected<void> written =
        write_file_atomically(dir / "out.bin", [&]() -> std::span<const std::uint8_t> {
            if (next == pieces.size()) return {};
            return pieces[next++];
        });
    ASSERT_TRUE(written) << written.error().message;
    EXPECT_EQ(test::read_file(dir / "out.bin"), "abcdef");
    EXPECT_EQ(next, pieces.size());
}

TEST(Png, RoundTripKeepsRowOrder) {
    Image8 image = sample_image();
    std::vector<std::uint8_t> bytes = encode_png(image);
    ASSERT_GT(bytes.size(), 8u);
    EXPECT_EQ(bytes[1], 'P');
    const Expected<Image8> back = decode_png(bytes);
    ASSERT_TRUE(back) << back.error().message;
    EXPECT_TRUE(*back == image);
}

TEST(ImageFile, FormatFollowsTheExtension) {
    EXPECT_EQ(format_from_extension("a/shot.png"), ImageFormat::png);
    EXPECT_EQ(format_from_extension("SHOT.PNG"), ImageFormat::png);
    EXPECT_EQ(format_from_extension("shot.bmp"), ImageFormat::bmp);
    EXPECT_EQ(format_from_extension("shot.png.bak"), ImageFormat::bmp);
    EXPECT_EQ(format_from_extension("shot"), ImageFormat::bmp);
    EXPECT_EQ(format_named_by("SHOT.Bmp"), ImageFormat::bmp);
    EXPECT_EQ(format_named_by("a/shot.png"), ImageFormat::png);
    EXPECT_FALSE(format_named_by("shot.png.bak"));
    EXPECT_FALSE(format_named_by("shot"));

    fs::path dir = make_scratch_dir("format");
    Image8 image = sample_image();
    for (const char* name : {"x.bmp", "x.png"}) {
        const Expected<void> written = write_image(dir / name, image, format_from_extension(name));
        ASSERT_TRUE(written) << written.error().message;
        const Expected<Image8> back = read_image(dir / name);
        ASSERT_TRUE(back) << back.error().message;
        EXPECT_TRUE(*back == image) << name;
    }
    std::ifstream png(dir / "x.png", std::ios::binary);
    char magic[4] = {};
    png.read(magic, 4);
    EXPECT_EQ(std::string(magic + 1, 3), "PNG");
}

// A BMP another program saved (GIMP, Paint: 32 bits with alpha, 8 with a
// palette, rows top-down) is a reference `diff` and --expect compare, as an
// image map reads it, rather than a file they refuse.
TEST(ImageFile, ReadsTheBmpKindsAnImageMapReads) {
    const Image8 image = sample_image();  // 3x2, row 0 at the bottom
    auto put16 = [](std::vector<std::uint8_t>& b, std::size_t at, std::uint32_t v) {
        b[at] = static_cast<std::uint8_t>(v);
        b[at + 1] = static_cast<std::uint8_t>(v >> 8);
    };
    auto put32 = [&](std::vector<std::uint8_t>& b, std::size_t at, std::uint32_t v) {
        put16(b, at, v & 0xFFFF);
        put16(b, at + 2, v >> 16);
    };
    // A BITMAPINFOHEADER file: 32 bits (BGRA) or 8 (a palette of every pixel).
    auto bmp = [&](int bits, bool top_down) {
        const std::size_t palette = bits == 8 ? 4 * 6 : 0;
        const std::size_t stride = bits == 32 ? 12 : 4;
        std::vector<std::uint8_t> b(54 + palette + stride * 2, 0);
        b[0] = 'B';
        b[1] = 'M';
        put32(b, 2, static_cast<std::uint32_t>(b.size()));
        put32(b, 10, static_cast<std::uint32_t>(54 + palette));
        put32(b, 14, 40);
        put32(b, 18, 3);
        put32(b, 22, top_down ? static_cast<std::uint32_t>(-2) : 2u);
        put16(b, 26, 1);
        put16(b, 28, static_cast<std::uint32_t>(bits));
        if (bits == 8) put32(b, 46, 6);
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 3; ++x) {
                const std::uint8_t* p = image.pixel(x, y);
                const int stored = top_down ? 1 - y : y;
                std::uint8_t* row = b.data() + 54 + palette + stride * stored;
                const int index = 3 * y + x;
                if (bits == 8) {
                    row[x] = static_cast<std::uint8_t>(index);
                    std::uint8_t* entry = b.data() + 54 + 4 * index;
                    entry[0] = p[2];
                    entry[1] = p[1];
                    entry[2] = p[0];
                } else {
                    row[4 * x] = p[2];
                    row[4 * x + 1] = p[1];
                    row[4 * x + 2] = p[0];
                    row[4 * x + 3] = 255;
                }
            }
        return b;
    };
    const fs::path dir = make_scratch_dir("bmp_kinds");
    for (const auto& [bits, top_down] :
         {std::pair{32, false}, std::pair{32, true}, std::pair{8, false}}) {
        const std::vector<std::uint8_t> bytes = bmp(bits, top_down);
        const fs::path file = dir / "ref.bmp";
        std::ofstream(file, std::ios::binary)
            .write(reinterpret_cast<const char*>(bytes.data()),
                   static_cast<std::streamsize>(bytes.size()));
        const Expected<Image8> back = read_image(file);
        ASSERT_TRUE(back) << bits << " bits: " << back.error().message;
        EXPECT_TRUE(*back == image) << bits << " bits, top-down " << top_down;
    }
}

// An OS/2 1.x BMP (the 12-byte BITMAPCOREHEADER, as ImageMagick's bmp2:
// writes it) of 24 bits is an image map; read_image and diff read it too,
// rather than refusing it as the 24-bit reader of jtracer's own files does.
TEST(ImageFile, ReadsAnOs2BmpAsAnImageMapDoes) {
    const Image8 image = sample_image();  // 3x2, row 0 at the bottom
    const std::size_t stride = 12;        // 9 bytes of BGR, padded to 4
    std::vector<std::uint8_t> b(14 + 12 + stride * 2, 0);
    b[0] = 'B';
    b[1] = 'M';
    b[2] = static_cast<std::uint8_t>(b.size());
    b[10] = 14 + 12;  // the pixels' offset
    b[14] = 12;       // the core header's size
    b[18] = 3;        // width and height, 16 bits each
    b[20] = 2;
    b[22] = 1;   // planes
    b[24] = 24;  // bits a pixel
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 3; ++x)
            for (int c = 0; c < 3; ++c)
                b[26 + stride * static_cast<std::size_t>(y) + 3 * x + c] = image.pixel(x, y)[2 - c];
    const Expected<Texture> map = decode_texture(b);
    ASSERT_TRUE(map) << map.error().message;
    EXPECT_EQ(map->width, 3);
    const fs::path file = make_scratch_dir("bmp_os2") / "os2.bmp";
    std::ofstream(file, std::ios::binary)
        .write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size()));
    for (const auto& read : {read_image, read_shown_image}) {
        const Expected<Image8> back = read(file);
        ASSERT_TRUE(back) << back.error().message;
        EXPECT_TRUE(*back == image);
    }
}

// A picture in a format image maps do not read says which format it is (a
// GIF from /usr/share/doc, a PPM from netpbm), not stb_image's "unknown image
// type"; an empty file says it is empty.
TEST(ImageMapFile, AFormatNotReadIsNamed) {
    auto problem = [](const std::string& text) {
        const std::vector<std::uint8_t> bytes(text.begin(), text.end());
        const Expected<Texture> t = decode_texture(bytes);
        return t ? std::string("(decoded)") : t.error().message;
    };
    const std::string pad(64, '\x01');
    EXPECT_EQ(problem(""), "the file is empty");
    const struct {
        std::string bytes, format;
    } cases[] = {
        {"GIF89a" + pad, "a GIF image"},
        {"GIF87a" + pad, "a GIF image"},
        {"P6\n4 4\n255\n" + pad, "a Netpbm image (PBM, PGM or PPM)"},
        {"P3 4 4 255 " + pad, "a Netpbm image (PBM, PGM or PPM)"},
        {std::string("II*\0", 4) + pad, "a TIFF image"},
        {std::string("MM\0*", 4) + pad, "a TIFF image"},
        {std::string("RIFF\x10\0\0\0WEBPVP8 ", 16) + pad, "a WebP image"},
        {pad + std::string("\0\0\0\0\0\0\0\0TRUEVISION-XFILE.\0", 26), "a TGA image"},
    };
    for (const auto& c : cases)
        EXPECT_EQ(problem(c.bytes),
                  "not a readable PNG, JPEG or BMP image: it is " + c.format + "; save it as PNG")
            << c.format;
    EXPECT_EQ(problem(pad), "not a readable PNG, JPEG or BMP image: unknown image type");
}

// A BMP cut short by less than its headers and palette take (a download
// stopped near its end) decoded with its last rows black: stb_image reads
// zeros past the end. An uncompressed BMP's size is exact, so it is refused.
TEST(ImageMapFile, ABmpMissingItsLastRowsIsRefused) {
    const std::vector<std::uint8_t> whole = encode_bmp(sample_image());  // 54 + 2 rows of 12
    ASSERT_TRUE(decode_texture(whole));
    for (std::size_t cut : {1u, 5u, 12u}) {
        const std::vector<std::uint8_t> short_file(whole.begin(), whole.end() - cut);
        const Expected<Texture> t = decode_texture(short_file);
        ASSERT_FALSE(t) << cut << " bytes cut";
        EXPECT_EQ(t.error().message,
                  "the file is too short for the 3x2 pixels its header claims (" +
                      std::to_string(short_file.size()) + " bytes)");
    }
}

// A TGA before version 2 has no signature, so its name tells it: OBJ files
// exported from games and older tools name .tga textures (assimp-testmodels'
// SMD/holygrail.tga, Collada/duckCM.tga).
TEST(ImageMapFile, ATgaIsNamedByItsName) {
    const fs::path dir = make_scratch_dir("tga");
    // An uncompressed 2x1 true-colour TGA: an 18-byte header, then BGR pixels.
    std::string tga(18, '\0');
    tga[2] = 2;
    tga[12] = 2;
    tga[14] = 1;
    tga[16] = 24;
    tga += std::string(6, '\x7f');
    for (const char* name : {"wood.tga", "WOOD.TGA"}) {
        test::write_file(dir / name, tga);
        const auto texture = load_texture(dir / name);
        ASSERT_FALSE(texture) << name;
        EXPECT_EQ(
            texture.error().message,
            "'" + (dir / name).string() +
                "': not a readable PNG, JPEG or BMP image: it is a TGA image; save it as PNG");
    }
    test::write_file(dir / "wood.png", tga);
    const auto named_png = load_texture(dir / "wood.png");
    ASSERT_FALSE(named_png);
    EXPECT_EQ(named_png.error().message.find("TGA"), std::string::npos);
}

// diff and --expect compare BMP and PNG: a reference saved as JPEG (lossy,
// so never an exact reference) or GIF says what it is, not that it does not
// start with the PNG signature.
TEST(ImageFile, AReferenceInAnotherFormatSaysWhichItIs) {
    const fs::path dir = make_scratch_dir("other_formats");
    const struct {
        std::string name, bytes, format;
    } cases[] = {
        {"ref.jpg", std::string("\xFF\xD8\xFF\xE0\0\x10JFIF", 10), "a JPEG image"},
        {"ref.gif", "GIF89a\x01\0\x01\0", "a GIF image"},
        {"ref.ppm", "P6\n1 1\n255\nabc", "a Netpbm image (PBM, PGM or PPM)"},
    };
    for (const auto& c : cases) {
        test::write_file(dir / c.name, c.bytes);
        const Expected<Image8> read = read_image(dir / c.name);
        ASSERT_FALSE(read) << c.name;
        EXPECT_EQ(read.error().message, "'" + (dir / c.name).string() + "': it is " + c.format +
                                            ", not a BMP or PNG image: save it as PNG")
            << c.name;
    }
}

// read_shown_image (jtracer.read_image's) reads what an image map reads; a
// file that is no picture is named for the formats it is not.
TEST(ImageFile, AShownImageOfAnotherKindNamesTheFormatsRead) {
    const fs::path dir = make_scratch_dir("shown_formats");
    const struct {
        std::string name, bytes, message;
    } cases[] = {
        {"model.obj", "v 0 0 0\nf 1 1 1\n", "it is not a BMP, PNG or JPEG image"},
        {"gif.png", "GIF89a\x01\0\x01\0",
         "it is a GIF image, not a BMP, PNG or JPEG image: save it as PNG"},
    };
    for (const auto& c : cases) {
        test::write_file(dir / c.name, c.bytes);
        const Expected<Image8> read = read_shown_image(dir / c.name);
        ASSERT_FALSE(read) << c.name;
        EXPECT_EQ(read.error().message, "'" + (dir / c.name).string() + "': " + c.message);
    }
    // A BMP or PNG reads as read_image reads it.
    ASSERT_TRUE(write_png(dir / "a.png", sample_image()));
    const Expected<Image8> png = read_shown_image(dir / "a.png");
    ASSERT_TRUE(png) << png.error().message;
    EXPECT_TRUE(*png == sample_image());
}

TEST(AtomicFile, ReplacesWholeAndLeavesNoTemporary) {
    fs::path dir = make_scratch_dir("atomic");
    fs::path target = dir / "out.bmp";
    { std::ofstream(target) << "old contents"; }
    const Expected<void> written = write_bmp(target, sample_image());
    ASSERT_TRUE(written) << written.error().message;
    const Expected<Image8> back = read_bmp(target);
    ASSERT_TRUE(back) << back.error().message;
    EXPECT_TRUE(*back == sample_image());
    int entries = 0;
    for (auto& e : fs::directory_iterator(dir)) {
        (void)e;
        ++entries;
    }
    EXPECT_EQ(entries, 1) << "no temporary file left beside the target";
}

// What a handler of SIGINT or SIGTERM calls before the process ends: the
// temporary file of the write under way goes, the old file stays whole.
TEST(AtomicFile, AnUnfinishedFileIsRemovedForASignalHandler) {
    fs::path dir = make_scratch_dir("atomic_unfinished");
    const fs::path target = dir / "out.bin";
    test::write_file(target, "old");
    const std::vector<std::uint8_t> piece{'n', 'e', 'w'};
    int calls = 0;
    std::vector<std::string> during;
    const Expected<void> written =
        write_file_atomically(target, [&]() -> std::span<const std::uint8_t> {
            if (++calls == 2) {
                for (const auto& e : fs::directory_iterator(dir))
                    during.push_back(e.path().filename().string());
                remove_unfinished_file();
            }
            return calls <= 2 ? std::span<const std::uint8_t>(piece)
                              : std::span<const std::uint8_t>();
        });
    EXPECT_EQ(during.size(), 2u) << "the temporary file was there while written";
    EXPECT_FALSE(written) << "the rename of a removed file fails";
    EXPECT_EQ(test::read_file(target), "old");
    std::vector<std::string> left;
    for (const auto& e : fs::directory_iterator(dir)) left.push_back(e.path().filename().string());
    EXPECT_EQ(left, std::vector<std::string>{"out.bin"});

    // Once a write is done there is nothing unfinished: the file stays.
    ASSERT_TRUE(write_file_atomically(target, piece));
    remove_unfinished_file();
    EXPECT_EQ(test::read_file(target), "new");
}

// A writable file in a folder that is not: the message names the folder, not
// just "Permission denied" about a file that may be written. As root (where
// permissions do not bind) the check runs in a child as nobody.
TEST(AtomicFile, AFolderWithoutWritePermissionIsNamed) {
    const fs::path dir = make_scratch_dir("atomic_folder");
    const fs::path folder = dir / "shared";
    fs::create_directories(folder);
    const fs::path target = folder / "out.bmp";
    test::write_file(target, "old");
    fs::permissions(dir, fs::perms::all & ~fs::perms::group_write & ~fs::perms::others_write);
    fs::permissions(target, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read |
                                fs::perms::group_write | fs::perms::others_read |
                                fs::perms::others_write);
    fs::permissions(folder, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                                fs::perms::group_exec | fs::perms::others_read |
                                fs::perms::others_exec);
    std::string message;
    if (::geteuid() == 0) {
        int pipe_ends[2];
        ASSERT_EQ(::pipe(pipe_ends), 0);
        const pid_t child = ::fork();
        ASSERT_GE(child, 0);
        if (child == 0) {
            ::close(pipe_ends[0]);
            if (::setgid(65534) != 0 || ::setuid(65534) != 0) ::_exit(2);
            const Expected<void> checked = check_atomic_write(target);
            const std::string text = checked ? "written" : checked.error().message;
            const bool sent = ::write(pipe_ends[1], text.data(), text.size()) ==
                              static_cast<ssize_t>(text.size());
            ::_exit(sent ? 0 : 3);
        }
        ::close(pipe_ends[1]);
        char buffer[512];
        for (ssize_t n; (n = ::read(pipe_ends[0], buffer, sizeof buffer)) > 0;)
            message.append(buffer, static_cast<std::size_t>(n));
        ::close(pipe_ends[0]);
        int status = 0;
        ::waitpid(child, &status, 0);
        ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
    } else {
        const Expected<void> checked = check_atomic_write(target);
        message = checked ? "written" : checked.error().message;
    }
    fs::permissions(folder, fs::perms::owner_all, fs::perm_options::add);
    EXPECT_NE(message.find("Permission denied"), std::string::npos) << message;
    EXPECT_NE(message.find("temporary file in '" + folder.string() + "'"), std::string::npos)
        << message;
    EXPECT_NE(message.find("that folder must be writable"), std::string::npos) << message;
    EXPECT_EQ(test::read_file(target), "old");
}

TEST(AtomicFile, FailureNamesTheFileAndWritesNothing) {
    fs::path dir = make_scratch_dir("atomic_fail");
    const Expected<void> written = write_bmp(dir / "missing" / "out.bmp", sample_image());
    ASSERT_FALSE(written);
    const std::string& error = written.error().message;
    EXPECT_NE(error.find("missing/out.bmp"), std::string::npos) << error;
    EXPECT_NE(error.find("No such file"), std::string::npos) << error;
    EXPECT_FALSE(fs::exists(dir / "missing"));
    // A directory in the way is refused, not replaced.
    fs::create_directory(dir / "taken.bmp");
    const Expected<void> over_directory = write_bmp(dir / "taken.bmp", sample_image());
    ASSERT_FALSE(over_directory);
    EXPECT_NE(over_directory.error().message.find("directory"), std::string::npos);
    EXPECT_TRUE(fs::is_directory(dir / "taken.bmp"));
}

// A file replaced keeps its permissions (the temporary file would give it 0644).
TEST(AtomicFile, AReplacedFileKeepsItsMode) {
    const fs::path dir = make_scratch_dir("keeps_mode");
    const fs::path target = dir / "private.bin";
    const std::vector<std::uint8_t> first{1, 2, 3}, second{4, 5};
    ASSERT_TRUE(write_file_atomically(target, first));
    EXPECT_EQ(fs::status(target).permissions() & fs::perms::all,
              fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read |
                  fs::perms::others_read);
    const fs::perms mode = fs::perms::owner_all | fs::perms::group_read;
    fs::permissions(target, mode);
    const Expected<void> written = write_file_atomically(target, second);
    ASSERT_TRUE(written) << written.error().message;
    EXPECT_EQ(test::read_file(target), std::string("\x04\x05"));
    EXPECT_EQ(fs::status(target).permissions() & fs::perms::all, mode);
}

// A link stays a link, also when the file it names is not made yet (a link to
// where renders are kept) and through a chain of relative links.
TEST(AtomicFile, AWriteThroughALinkWritesTheFileItNames) {
    const fs::path dir = make_scratch_dir("through_link");
    fs::create_directory(dir / "renders");
    fs::create_symlink("renders/out.bin", dir / "first.bin");
    fs::create_symlink("first.bin", dir / "second.bin");
    const std::vector<std::uint8_t> bytes{7, 8, 9};
    const Expected<void> written = write_file_atomically(dir / "second.bin", bytes);
    ASSERT_TRUE(written) << written.error().message;
    EXPECT_TRUE(fs::is_symlink(dir / "second.bin"));
    EXPECT_TRUE(fs::is_symlink(dir / "first.bin"));
    EXPECT_EQ(test::read_file(dir / "renders/out.bin"), std::string("\x07\x08\x09"));
    EXPECT_EQ(file_behind_links(dir / "second.bin"), (dir / "renders/out.bin").lexically_normal());
    // A loop is left for the write to fail on, naming the file asked for.
    fs::create_symlink("loop_b", dir / "loop_a");
    fs::create_symlink("loop_a", dir / "loop_b");
    EXPECT_EQ(file_behind_links(dir / "loop_a"), dir / "loop_a");
    EXPECT_TRUE(check_atomic_write(dir / "second.bin")) << "the write's own check agrees";
    EXPECT_FALSE(check_atomic_write(dir / "loop_a"));
    const Expected<void> looped = write_file_atomically(dir / "loop_a", bytes);
    ASSERT_FALSE(looped);
    EXPECT_NE(looped.error().message.find("loop_a"), std::string::npos) << looped.error().message;
}

TEST(AtomicFile, NewFileNeverReplacesOneAndLeavesNoTemporary) {
    fs::path dir = make_scratch_dir("new_file");
    const fs::path target = dir / "new.bin";
    const std::vector<std::uint8_t> first{1, 2, 3}, second{4, 5};
    const Expected<bool> written = write_new_file(target, first);
    ASSERT_TRUE(written) << written.error().message;
    EXPECT_TRUE(*written);
    EXPECT_EQ(fs::status(target).permissions() & fs::perms::all,
              fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read |
                  fs::perms::others_read);
    const Expected<bool> again = write_new_file(target, second);
    ASSERT_TRUE(again) << again.error().message;
    EXPECT_FALSE(*again) << "the name is taken";
    EXPECT_EQ(test::read_file(target), std::string("\x01\x02\x03"));
    const Expected<bool> nowhere = write_new_file(dir / "missing" / "x.bin", first);
    ASSERT_FALSE(nowhere);
    EXPECT_NE(nowhere.error().message.find("missing/x.bin"), std::string::npos)
        << nowhere.error().message;
    int entries = 0;
    for (auto& e : fs::directory_iterator(dir)) {
        (void)e;
        ++entries;
    }
    EXPECT_EQ(entries, 1) << "no temporary file left beside the target";
}

TEST(ImageDiff, CountsPixelsOverTheThreshold) {
    Image8 a = sample_image();
    Image8 b = a;
    EXPECT_EQ(diff_images(a, b).max_channel_difference, 0);
    EXPECT_EQ(diff_images(a, b).pixels_over, 0u);
    b.pixel(1, 1)[2] = static_cast<std::uint8_t>(b.pixel(1, 1)[2] + 3);
    b.pixel(2, 0)[0] = static_cast<std::uint8_t>(b.pixel(2, 0)[0] - 1);
    ImageDiff d = diff_images(a, b, 1);
    EXPECT_TRUE(d.same_size);
    EXPECT_EQ(d.max_channel_difference, 3);
    EXPECT_EQ(d.pixels_over, 1u);
    EXPECT_NEAR(d.percent_over, 100.0 / 6.0, 1e-12);
    EXPECT_EQ(d.image.width, 3);
    // Over the threshold: a heat colour; under it: a dim grey of `expected`.
    std::uint8_t heat[3];
    heat_colour(3, heat);
    EXPECT_EQ(std::vector<std::uint8_t>(d.image.pixel(1, 1), d.image.pixel(1, 1) + 3),
              std::vector<std::uint8_t>(heat, heat + 3));
    const std::uint8_t* grey = d.image.pixel(2, 0);
    EXPECT_TRUE(grey[0] == grey[1] && grey[1] == grey[2] && grey[0] <= 85);
    EXPECT_EQ(diff_images(a, b, 0).pixels_over, 2u);
    EXPECT_FALSE(diff_images(a, Image8(2, 2)).same_size);
}

TEST(ImageDiff, MeanAbsoluteErrorAndPsnr) {
    Image8 a = sample_image();  // 3x2: 18 channels
    EXPECT_TRUE(std::isinf(diff_images(a, a).psnr));
    EXPECT_EQ(diff_images(a, a).mean_absolute_error, 0.0);
    Image8 b = a;
    b.pixel(0, 0)[0] = static_cast<std::uint8_t>(b.pixel(0, 0)[0] ^ 6);  // some channel off by 2..6
    const int off = std::abs(int{a.pixel(0, 0)[0]} - int{b.pixel(0, 0)[0]});
    ImageDiff d = diff_images(a, b);
    EXPECT_NEAR(d.mean_absolute_error, off / 18.0, 1e-12);
    EXPECT_NEAR(d.psnr, 10.0 * std::log10(255.0 * 255.0 * 18.0 / (off * off)), 1e-9);
    EXPECT_EQ(d.pixels, 6u);
}

TEST(ImageDiff, HeatColoursRunFromRedThroughYellowToWhite) {
    std::uint8_t small[3], middle[3], large[3];
    heat_colour(1, small);
    heat_colour(64, middle);
    heat_colour(255, large);
    EXPECT_EQ(small[0], 255);
    EXPECT_LT(small[1], 40);
    EXPECT_EQ(small[2], 0);
    EXPECT_EQ(middle[0], 255);
    EXPECT_GE(middle[1], 250);
    EXPECT_LT(middle[2], 10);
    EXPECT_EQ(large[0], 255);
    EXPECT_EQ(large[1], 255);
    EXPECT_EQ(large[2], 255);
}

}  // namespace
}  // namespace jt

namespace jt {
namespace {

TEST(Png, APngClaimingTenBillionPixelsIsTooLargeNotOutOfMemory) {
    // 100000 x 100000 in its IHDR, a few bytes of image data: refused from
    // the header, before the 30 GB it claims are reserved.
    std::vector<std::uint8_t> bytes = test::png_signature();
    auto chunk = [&](const char* type, const std::vector<std::uint8_t>& data) {
        test::append_png_chunk(bytes, type, data);
    };
    chunk("IHDR", {0, 1, 0x86, 0xa0, 0, 1, 0x86, 0xa0, 8, 2, 0, 0, 0});
    chunk("IDAT", {0x78, 0x01, 0x03, 0x00});
    chunk("IEND", {});
    const Expected<Image8> image = decode_png(bytes);
    ASSERT_FALSE(image);
    EXPECT_EQ(image.error().message,
              "not a readable PNG: too large (100000x100000 pixels; at most 268435456)");
}

}  // namespace
}  // namespace jt
