#pragma once
// Comparing images from the command line, for users' CI: `jtracer-cli diff
// EXPECTED ACTUAL` and `jtracer-cli scene.jts --expect REFERENCE`, both on
// core's diff_images and both with the same tolerance flags.

#include "jtracer/image.hpp"

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

// `jtracer-cli diff ...`: argv[0] is "diff". Prints the comparison on stdout.
// Exit codes: 0 within the tolerance, 1 outside it (or sizes differ), 2 bad
// command line, 3 an image that cannot be read or a heat map not written.
int run_diff_command(int argc, char** argv);

// --expect: compares the render written to `render_path` with `reference`
// and reports on stderr. Outside the tolerance it writes the heat map beside
// the render (out.png -> out.diff.png) and returns 1; 3 when the reference
// cannot be read or the heat map not written; 0 within the tolerance.
int check_expected(const Image8& render, const std::string& render_path,
                   const std::string& reference, const Tolerance& tolerance, bool quiet);

}  // namespace jt::cli
