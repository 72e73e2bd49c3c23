#include "diff_command.hpp"

#include "jtracer/frontend/render_flags.hpp"
#include "jtracer/image_diff.hpp"
#include "jtracer/image_file.hpp"

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <new>

namespace jt::cli {

using namespace frontend;

namespace {

bool within(const ImageDiff& d, const Tolerance& tolerance) {
    return d.same_size && d.percent_over <= tolerance.max_percent;
}

std::string size_text(const Image8& image) {
    return std::to_string(image.width) + "x" + std::to_string(image.height);
}

// The comparison as "name: value" lines, the same for diff and --expect.
std::string report(const ImageDiff& d, const Tolerance& tolerance) {
    char text[512];
    const std::string psnr = std::isinf(d.psnr) ? "inf (identical)" : [&] {
        char db[32];
        std::snprintf(db, sizeof db, "%.2f dB", d.psnr);
        return std::string(db);
    }();
    std::snprintf(text, sizeof text,
                  "max channel difference: %d\n"
                  "pixels over threshold %d: %zu of %zu (%.4f%%, allowed %g%%)\n"
                  "mean absolute error: %.4f\n"
                  "PSNR: %s\n",
                  d.max_channel_difference, tolerance.threshold, d.pixels_over, d.pixels,
                  d.percent_over, tolerance.max_percent, d.mean_absolute_error, psnr.c_str());
    return text;
}

}  // namespace

void add_tolerance_flags(CLI::App& app, Tolerance& tolerance) {
    app.add_option("--threshold", tolerance.threshold,
                   "Largest difference of a channel (0-255) still counted as equal (default 0)")
        ->check(CLI::Range(0, 255));
    app.add_option("--max-pixels", tolerance.max_percent,
                   "Percentage of the pixels allowed over the threshold (default 0)")
        ->check(CLI::Range(0.0, 100.0));
}

int run_diff_command(int argc, char** argv) {
    std::string expected_path, actual_path;
    std::string heat_map_path;
    Tolerance tolerance;
    bool quiet = false;
    CLI::App app{"jtracer-cli diff: compares two images (BMP or PNG, any mix) pixel by pixel.",
                 "jtracer-cli diff"};
    app.footer(
        "Prints both sizes, the largest channel difference, the pixels over the threshold\n"
        "(count and percentage), the mean absolute error and the PSNR.\n"
        "\n"
        "Examples:\n"
        "  jtracer-cli diff reference.png render.png                    exact match\n"
        "  jtracer-cli diff reference.png render.bmp --threshold 2 --max-pixels 0.1 -o diff.png\n"
        "\n"
        "Exit codes: 0 within the tolerance, 1 outside it (or the sizes differ), 2 bad\n"
        "command line, 3 an image that cannot be read or a heat map that cannot be written.\n");
    app.add_option("expected", expected_path, "The reference image (BMP or PNG)")->required();
    app.add_option("actual", actual_path, "The image to check against it (BMP or PNG)")->required();
    app.add_option("-o,--output", heat_map_path,
                   "Write a heat map of the differences here (PNG, or BMP for a .bmp name): "
                   "pixels over the threshold from red to white, the rest dim grey");
    add_tolerance_flags(app, tolerance);
    app.add_flag("-q,--quiet", quiet, "Print nothing but errors; the exit code tells the result");
    if (std::optional<int> code = parse_command_line(app, argc, argv, "jtracer-cli diff"))
        return *code;

    try {
        Expected<Image8> expected = read_image(expected_path);
        Expected<Image8> actual = expected ? read_image(actual_path) : Expected<Image8>(Image8{});
        for (const Expected<Image8>* image : {&expected, &actual})
            if (!*image) {
                std::cerr << "jtracer-cli diff: " << image->error().message << "\n";
                return exit_io_error;
            }
        const ImageDiff d = diff_images(*expected, *actual, tolerance.threshold);
        const bool ok = within(d, tolerance);
        if (!quiet) {
            std::cout << expected_path << ": " << size_text(*expected) << "\n"
                      << actual_path << ": " << size_text(*actual) << "\n";
            if (d.same_size)
                std::cout << report(d, tolerance);
            else
                std::cout << "the sizes differ\n";
            std::cout << (ok ? "within the tolerance\n" : "OUTSIDE the tolerance\n");
        }
        if (!heat_map_path.empty()) {
            if (!d.same_size) {
                std::cerr << "jtracer-cli diff: the sizes differ, so no heat map was written\n";
            } else if (const Expected<void> written = write_image(
                           heat_map_path, d.image, format_from_extension(heat_map_path));
                       !written) {
                std::cerr << "jtracer-cli diff: " << written.error().message << "\n";
                return exit_io_error;
            }
        }
        return ok ? exit_ok : exit_outside_tolerance;
    } catch (const std::bad_alloc&) {
        std::cerr << "jtracer-cli diff: out of memory\n";
        return exit_io_error;
    }
}

int check_expected(const Image8& render, const std::string& render_path,
                   const std::string& reference, const Tolerance& tolerance, bool quiet) {
    const Expected<Image8> expected = read_image(reference);
    if (!expected) {
        std::cerr << "jtracer-cli: --expect: " << expected.error().message << "\n";
        return exit_io_error;
    }
    const ImageDiff d = diff_images(*expected, render, tolerance.threshold);
    if (within(d, tolerance)) {
        if (!quiet) std::cerr << "matches " << reference << "\n";
        return exit_ok;
    }
    if (!d.same_size) {
        std::cerr << "jtracer-cli: the render (" << size_text(render) << ", in " << render_path
                  << ") is not the size of " << reference << " (" << size_text(*expected) << ")\n";
        return exit_outside_tolerance;
    }
    const std::string heat_map_path =
        std::filesystem::path(render_path).replace_extension(".diff.png").string();
    std::cerr << "jtracer-cli: the render differs from " << reference << ":\n"
              << report(d, tolerance);
    if (const Expected<void> written = write_image(heat_map_path, d.image, ImageFormat::png);
        !written) {
        std::cerr << "jtracer-cli: " << written.error().message << "\n";
        return exit_io_error;
    }
    std::cerr << "the render is in " << render_path << ", the differences in " << heat_map_path
              << "\n";
    return exit_outside_tolerance;
}

}  // namespace jt::cli
