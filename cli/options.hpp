#pragma once
// jtracer-cli's command line, parsed into a plain struct.

#include "jtracer/region.hpp"

#include <optional>
#include <string>
#include <vector>

namespace jt::cli {

// Exit codes, as the README documents them.
enum ExitCode : int { exit_ok = 0, exit_scene_error = 1, exit_usage = 2, exit_io_error = 3 };

struct Options {
    std::string scene_path;
    std::optional<std::string> output;  // wins over the scene's filename
    std::optional<std::string> camera;
    std::optional<int> width;
    std::optional<int> height;
    std::optional<int> samples;
    int threads = 0;  // 0: every core
    // Render only this window (top-left origin, region.hpp); the rest stays black.
    std::optional<jt::FrameRegion> region;
    bool region_output = false;  // write the region alone, as a region file (region_file.hpp)
    bool check_only = false;
    bool quiet = false;
};

struct ParsedOptions {
    Options options;
    // Set when the program should stop now with this code: after --help or
    // --version (0), or a usage error (2, message already printed).
    std::optional<int> exit_code;
};

ParsedOptions parse_options(int argc, char** argv);

}  // namespace jt::cli
