#include "diff_command.hpp"

#include "comparison_report.hpp"

#include "jtracer/atomic_file.hpp"
#include "jtracer/frontend/render_flags.hpp"
#include "jtracer/image_diff.hpp"
#include "jtracer/image_file.hpp"

#include <CLI/CLI.hpp>

#include <chrono>
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

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The report of a comparison of `expected` with `actual`, whose heat map is
// left in `diff.image`; `report.diff` keeps the figures only.
ComparisonReport compared(ComparisonReport r, const Image8& expected, const Image8& actual,
                          ImageDiff& diff, const Tolerance& tolerance) {
    r.expected_size = ImageSize{expected.width, expected.height};
    r.actual_size = ImageSize{actual.width, actual.height};
    r.threshold = tolerance.threshold;
    r.max_percent = tolerance.max_percent;
    r.verdict = within(diff, tolerance) ? Verdict::within : Verdict::outside;
    r.text = diff.same_size ? report(diff, tolerance) : "the sizes differ\n";
    Image8 heat_map = std::move(diff.image);  // not copied into the report
    r.diff = diff;
    diff.image = std::move(heat_map);
    return r;
}

// Writes --junit's file when asked; on failure says why and returns false.
bool junit_written(const std::optional<std::string>& junit, const ComparisonReport& r,
                   const std::string& suite, const std::string& program) {
    if (!junit) return true;
    if (const Expected<void> written = write_junit(*junit, r, suite); !written) {
        std::cerr << program << ": --junit: " << written.error().message << "\n";
        return false;
    }
    return true;
}

constexpr const char* kDiffSuite = "jtracer-cli diff";
constexpr const char* kExpectSuite = "jtracer-cli --expect";

}  // namespace

void add_tolerance_flags(CLI::App& app, Tolerance& tolerance) {
    app.add_option("--threshold", tolerance.threshold,
                   "Largest difference of a channel (0-255) still counted as equal (default 0)")
        ->check(CLI::Range(0, 255))
        ->type_name("N");
    app.add_option("--max-pixels", tolerance.max_percent,
                   "Percentage of the pixels allowed over the threshold, 0..100 (default 0)")
        ->check(CLI::Range(0.0, 100.0))
        ->type_name("P");
}

int run_diff_command(int argc, char** argv) {
    std::string expected_path, actual_path;
    std::string heat_map_path;
    std::optional<std::string> junit;
    Tolerance tolerance;
    bool quiet = false, json = false;
    CLI::App app{"jtracer-cli diff: compares two images (BMP or PNG, any mix) pixel by pixel.",
                 "jtracer-cli diff"};
    app.footer(
        "Prints both sizes, the largest channel difference, the pixels over the threshold\n"
        "(count and percentage), the mean absolute error and the PSNR.\n"
        "\n"
        "Examples:\n"
        "  jtracer-cli diff reference.png render.png                    exact match\n"
        "  jtracer-cli diff reference.png render.bmp --threshold 2 --max-pixels 0.1 -o diff.png\n"
        "  jtracer-cli diff reference.png render.png --json --junit report.xml   for CI\n"
        "\n"
        "Exit codes: 0 within the tolerance, 1 outside it (or the sizes differ), 2 bad\n"
        "command line, 3 an image that cannot be read or a heat map or report that cannot\n"
        "be written.\n");
    app.add_option("expected", expected_path, "The reference image (BMP or PNG)")->required();
    app.add_option("actual", actual_path, "The image to check against it (BMP or PNG)")->required();
    app.add_option("-o,--output", heat_map_path,
                   "Write a heat map of the differences here (PNG, or BMP for a .bmp name): "
                   "pixels over the threshold from red to white, the rest dim grey; - is "
                   "standard output (a PNG; the report then goes to stderr)")
        ->type_name("FILE");
    add_tolerance_flags(app, tolerance);
    app.add_flag("--json", json,
                 "Print the comparison as one JSON object instead: both paths and sizes, the "
                 "tolerance, the figures, the verdict and the heat map's path");
    app.add_option("--junit", junit,
                   "Also write the comparison as a JUnit XML test case to this file, failed "
                   "outside the tolerance with the figures as its message")
        ->type_name("FILE");
    app.add_flag("-q,--quiet", quiet, "Print nothing but errors; the exit code tells the result");
    // Neither file written may be an image compared (a heat map over the
    // reference would pass every later comparison), nor the other.
    auto checks = [&] {
        if (app.count("--output") && heat_map_path.empty())
            throw CLI::ValidationError("-o/--output", "needs a file name, not an empty string");
        heat_map_path = output_name(heat_map_path);
        if (heat_map_path == "/dev/stdout" && json)
            throw CLI::ValidationError("-o/--output",
                                       "standard output cannot hold both the heat map and "
                                       "--json's object: name a file for the heat map");
        if (!heat_map_path.empty())
            if (std::optional<std::string> refused = output_refusal(heat_map_path))
                throw CLI::ValidationError("-o/--output", *refused);
        if (junit && junit->empty())
            throw CLI::ValidationError("--junit", "needs a file name, not an empty string");
        for (const auto& [flag, written] :
             {std::pair<const char*, std::string>{"-o/--output", heat_map_path},
              {"--junit", junit.value_or("")}}) {
            if (written.empty()) continue;
            for (const auto& [what, path] :
                 {std::pair<const char*, std::string>{"EXPECTED", expected_path},
                  {"ACTUAL", actual_path}})
                if (same_file(written, path))
                    throw CLI::ValidationError(
                        flag, "'" + written + "' is the " + what + " image: it would be replaced");
        }
        // Two documents on one stream cannot be parted again by what reads it.
        if (junit && is_standard_output(*junit) && (heat_map_path == "/dev/stdout" || json))
            throw CLI::ValidationError(
                "--junit", "'" + *junit + "' is standard output, which already carries " +
                               (json ? "--json's object" : "the heat map (-o -)") +
                               ": name a file for the report");
        if (junit && !heat_map_path.empty() && same_file(*junit, heat_map_path))
            throw CLI::ValidationError(
                "--junit", "'" + *junit + "' is also the heat map (-o): it would be replaced");
    };
    if (std::optional<int> code = parse_command_line(app, argc, argv, "jtracer-cli diff", checks))
        return *code;

    const std::string program = "jtracer-cli diff";
    const auto start = std::chrono::steady_clock::now();
    ComparisonReport r;
    r.name = actual_path;
    r.expected_path = expected_path;
    r.actual_path = actual_path;
    r.threshold = tolerance.threshold;
    r.max_percent = tolerance.max_percent;
    // Prints the JSON and writes the JUnit file, whatever the verdict.
    auto finish = [&](int code) -> int {
        r.seconds = seconds_since(start);
        if (json) std::cout << comparison_json(r) << "\n";
        // The report printed comes before a --junit file on the same stream.
        std::cout.flush();
        if (!junit_written(junit, r, kDiffSuite, program)) return exit_io_error;
        return code;
    };
    try {
        Expected<Image8> expected = read_image(expected_path);
        Expected<Image8> actual = expected ? read_image(actual_path) : Expected<Image8>(Image8{});
        for (const Expected<Image8>* image : {&expected, &actual})
            if (!*image) {
                std::cerr << program << ": " << image->error().message << "\n";
                r.error = image->error().message;
                if (expected) r.expected_size = ImageSize{expected->width, expected->height};
                return finish(exit_io_error);
            }
        ImageDiff d = diff_images(*expected, *actual, tolerance.threshold);
        r = compared(std::move(r), *expected, *actual, d, tolerance);
        // With the heat map on standard output (-o -), the report goes to
        // stderr, as jtracer-cli's messages do when -o - carries the image.
        std::ostream& report_out = heat_map_path == "/dev/stdout" ? std::cerr : std::cout;
        if (!quiet && !json) {
            report_out << expected_path << ": " << size_text(*expected) << "\n"
                       << actual_path << ": " << size_text(*actual) << "\n"
                       << r.text
                       << (r.verdict == Verdict::within ? "within the tolerance\n"
                                                        : "OUTSIDE the tolerance\n");
        }
        if (!heat_map_path.empty()) {
            if (!d.same_size) {
                std::cerr << program << ": the sizes differ, so no heat map was written\n";
            } else if (const Expected<void> written =
                           write_image(heat_map_path, d.image, heat_map_format(heat_map_path));
                       !written) {
                std::cerr << program << ": " << shown_write_error(written.error().message) << "\n";
                return finish(exit_io_error);
            } else {
                r.heat_map_path = shown_output(heat_map_path);
            }
        }
        return finish(r.verdict == Verdict::within ? exit_ok : exit_outside_tolerance);
    } catch (const std::bad_alloc&) {
        std::cerr << program << ": out of memory\n";
        return exit_io_error;
    }
}

ImageFormat heat_map_format(const std::string& path) {
    return format_named_by(path).value_or(ImageFormat::png);
}

std::string heat_map_path_for(const std::string& render_path) {
    // Beside the file a link names: `-o /dev/stdout > out.png` writes out.png
    // (through /proc/self/fd/1), whose heat map belongs beside it, not in /dev.
    return file_behind_links(render_path).replace_extension(".diff.png").string();
}

int check_expected(const Image8& render, const std::string& render_path,
                   const ExpectOptions& expect, double seconds) {
    const std::string& reference = expect.reference;
    const std::string heat_map_path = heat_map_path_for(render_path);
    // A heat map left beside the render by an earlier run that failed would
    // say this one failed too (to a person, or to CI keeping out/ as an
    // artifact): only a render outside the tolerance keeps one.
    auto remove_stale_heat_map = [&] {
        std::error_code error;
        if (std::filesystem::is_regular_file(heat_map_path, error) &&
            std::filesystem::remove(heat_map_path, error) && !expect.quiet)
            std::cerr << "removed " << heat_map_path << ", the heat map of an earlier run\n";
    };
    ComparisonReport r;
    r.name = expect.scene_path;
    r.expected_path = reference;
    r.actual_path = shown_output(render_path);
    r.threshold = expect.tolerance.threshold;
    r.max_percent = expect.tolerance.max_percent;
    r.actual_size = ImageSize{render.width, render.height};
    r.seconds = seconds;
    auto finish = [&](int code) -> int {
        return junit_written(expect.junit, r, kExpectSuite, "jtracer-cli") ? code : exit_io_error;
    };
    // --update: the render replaces the reference, in the format its name asks for.
    auto update = [&](const std::string& why) -> int {
        if (const Expected<void> written =
                write_image(reference, render, format_from_extension(reference));
            !written) {
            std::cerr << "jtracer-cli: --update: " << written.error().message << "\n";
            r.verdict = Verdict::error;
            r.error = written.error().message;
            return finish(exit_io_error);
        }
        std::cerr << "updated " << reference << " with the render (" << why << ")\n";
        remove_stale_heat_map();
        r.verdict = Verdict::updated;
        return finish(exit_ok);
    };

    const Expected<Image8> expected = read_image(reference);
    if (!expected) {
        if (expect.update) return update("it could not be read: " + expected.error().message);
        std::cerr << "jtracer-cli: --expect: " << expected.error().message << "\n";
        r.verdict = Verdict::error;
        r.error = expected.error().message;
        return finish(exit_io_error);
    }
    ImageDiff d = diff_images(*expected, render, expect.tolerance.threshold);
    r = compared(std::move(r), *expected, render, d, expect.tolerance);
    if (r.verdict == Verdict::within) {
        if (!expect.quiet) std::cerr << "matches " << reference << "\n";
        remove_stale_heat_map();
        return finish(exit_ok);
    }
    if (!d.same_size) {
        const std::string sizes =
            "the render is " + size_text(render) + ", the reference " + size_text(*expected);
        if (expect.update) return update(sizes);
        std::cerr << "jtracer-cli: the render (" << size_text(render) << ", in "
                  << shown_output(render_path) << ") is not the size of " << reference << " ("
                  << size_text(*expected) << ")\n";
        remove_stale_heat_map();  // none is drawn for images of different sizes
        return finish(exit_outside_tolerance);
    }
    if (expect.update) {
        char why[96];
        std::snprintf(why, sizeof why, "it differed: max channel difference %d, %zu pixels over",
                      d.max_channel_difference, d.pixels_over);
        return update(why);
    }
    std::cerr << "jtracer-cli: the render differs from " << reference << ":\n" << r.text;
    if (frontend::is_stream(render_path)) {
        std::cerr << "the render went to " << shown_output(render_path)
                  << ", which has no folder to keep a heat map beside it: none was written\n";
        return finish(exit_outside_tolerance);
    }
    if (const Expected<void> written = write_image(heat_map_path, d.image, ImageFormat::png);
        !written) {
        std::cerr << "jtracer-cli: " << written.error().message << "\n";
        return finish(exit_io_error);
    }
    r.heat_map_path = heat_map_path;
    std::cerr << "the render is in " << shown_output(render_path) << ", the differences in "
              << heat_map_path << "\n";
    return finish(exit_outside_tolerance);
}

namespace {

// The line of `messages` a CI page should show for a failed render: the
// first error, else the last line printed.
std::string first_error(const std::string& messages) {
    std::string last;
    std::size_t start = 0;
    while (start < messages.size()) {
        std::size_t end = messages.find('\n', start);
        if (end == std::string::npos) end = messages.size();
        const std::string line = messages.substr(start, end - start);
        if (line.find(": error: ") != std::string::npos || line.rfind("jtracer-cli: ", 0) == 0)
            return line;
        if (!line.empty()) last = line;
        start = end + 1;
    }
    return last;
}

}  // namespace

int record_failed_render(const ExpectOptions& expect, int code, const std::string& messages,
                         double seconds) {
    if (!expect.junit) return code;
    ComparisonReport r;
    r.name = expect.scene_path;
    r.seconds = seconds;
    r.expected_path = expect.reference;
    r.threshold = expect.tolerance.threshold;
    r.max_percent = expect.tolerance.max_percent;
    r.verdict = Verdict::error;
    r.error = "the render failed (jtracer-cli exit code " + std::to_string(code) +
              "), so it was not compared";
    if (const std::string line = first_error(messages); !line.empty()) r.error += ": " + line;
    r.log = messages;
    return junit_written(expect.junit, r, kExpectSuite, "jtracer-cli") ? code : exit_io_error;
}

}  // namespace jt::cli
