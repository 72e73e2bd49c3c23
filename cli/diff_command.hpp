#pragma once
// Comparing images from the command line, for users' CI: `jtracer-cli diff
// EXPECTED ACTUAL` and `jtracer-cli scene.jts --expect REFERENCE`, both on
// core's diff_images and both with the same tolerance flags, and both able to
// leave a JUnit XML file of the comparison (comparison_report.hpp).

#include "jtracer/image.hpp"
#include "jtracer/image_file.hpp"

#include <optional>
#include <string>

namespace CLI {
class App;
}

namespace jt::cli {

// A comparison outside its tolerance: the exit code of a scene with errors, as
// both mean that the picture is not what it should be.
inline constexpr int exit_outside_tolerance = 1;

struct Tolerance {
    int threshold = 0;         // largest channel difference (0..255) counted as equal
    double max_percent = 0.0;  // of the pixels, allowed over the threshold
};

// Declares --threshold and --max-pixels.
void add_tolerance_flags(CLI::App& app, Tolerance& tolerance);

// `jtracer-cli diff ...`: argv[0] is "diff". Prints the comparison on stdout
// (with --json as one JSON object). Exit codes: 0 within the tolerance, 1
// outside it (or sizes differ), 2 bad command line, 3 an image that cannot be
// read or a heat map or JUnit file not written.
int run_diff_command(int argc, char** argv);

// What --expect does besides comparing.
struct ExpectOptions {
    std::string reference;
    Tolerance tolerance;
    bool update = false;               // --update: a render that differs replaces the reference
    std::optional<std::string> junit;  // --junit FILE
    std::string scene_path;            // the JUnit test case's name
    bool quiet = false;
};

// The format of diff's heat map (-o): a PNG but for a name ending in .bmp,
// as its help says (format_from_extension would make any other name a BMP).
ImageFormat heat_map_format(const std::string& path);

// Where --expect puts the heat map of a render outside the tolerance:
// out.png -> out.diff.png, beside the file when out.png is a link to it.
std::string heat_map_path_for(const std::string& render_path);

// --expect: compares the render written to `render_path` with the reference
// and reports on stderr. Outside the tolerance it writes the heat map beside
// the render (out.png -> out.diff.png) and returns 1, or with `update` writes
// the render over the reference and returns 0; 3 when the reference cannot be
// read (without `update`) or a file not written; 0 within the tolerance.
// `seconds`: the render's time, for the JUnit file.
int check_expected(const Image8& render, const std::string& render_path,
                   const ExpectOptions& expect, double seconds);

// --expect --junit when the render failed before any comparison (exit code
// `code`): the test case in error, its message naming the first error in
// `messages` (what the run printed on stderr), which the report keeps whole;
// `seconds`: the time the run spent until it failed, for the JUnit file (a CI
// page sorts and charts by it: a render that failed after an hour is no 0 s).
// Returns `code`, or 3 when the file could not be written.
int record_failed_render(const ExpectOptions& expect, int code, const std::string& messages,
                         double seconds);

}  // namespace jt::cli
