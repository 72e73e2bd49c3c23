#pragma once
// jtracer-mpi's command line: the shared render flags (frontend/) plus the distribution's
// own. Every rank parses the same argv, so every rank reaches the same verdict.

#include "jtracer/frontend/region_flags.hpp"
#include "jtracer/frontend/render_flags.hpp"

#include <optional>

namespace jt::mpi {

using frontend::exit_io_error;
using frontend::exit_ok;
using frontend::exit_scene_error;
using frontend::exit_usage;

// --region and --region-output as jtracer-cli's: the ranks share the window's
// tiles alone.
struct Options : frontend::RenderFlags, frontend::RegionFlags {  // threads: per rank
    int tile_size = 128;         // the unit of work handed out, in pixels a side
    bool stats = false;          // timings of the coordinator and of every rank
    double rank_timeout = 10.0;  // seconds of silence after which a rank is lost
    // Keep an image already there and complete instead of rendering it again
    // (jtracer/frontend/existing_output.hpp); rank 0 decides, on its machine.
    bool skip_existing = false;
    // Only parse and validate the scene (every frame of --frames), on rank 0
    // alone: nothing is rendered, so no rank need read the scene.
    bool check_only = false;
};

struct ParsedOptions {
    Options options;
    std::optional<int> exit_code;  // stop now with this code (help, version, usage error)
};

// Only a rank that `speaks` prints help or errors (rank 0).
ParsedOptions parse_options(int argc, char** argv, bool speaks);

}  // namespace jt::mpi
