#pragma once
// jtracer-mpi's command line: the CLI's render options plus the distribution's
// own. Every rank parses the same argv, so every rank reaches the same verdict.

#include <optional>
#include <string>

namespace jt::mpi {

enum ExitCode : int { exit_ok = 0, exit_scene_error = 1, exit_usage = 2, exit_io_error = 3 };

struct Options {
    std::string scene_path;
    std::optional<std::string> output;  // wins over the scene's filename
    std::optional<std::string> camera;
    std::optional<int> width;
    std::optional<int> height;
    std::optional<int> samples;
    int threads = 0;      // per rank; 0: every core of the rank's machine
    int tile_size = 128;  // the unit of work handed out, in pixels a side
    bool quiet = false;
    bool stats = false;  // timings of the coordinator and of every rank
};

struct ParsedOptions {
    Options options;
    std::optional<int> exit_code;  // stop now with this code (help, version, usage error)
};

// Only a rank that `speaks` prints help or errors (rank 0).
ParsedOptions parse_options(int argc, char** argv, bool speaks);

}  // namespace jt::mpi
