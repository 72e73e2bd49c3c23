#pragma once
// The command line every JTracer renderer shares (jtracer-cli, jtracer-mpi):
// the options, their exit codes, and their declaration, written once so that
// both read a render the same way.

#include "jtracer/diagnostics.hpp"

#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace jt::frontend {

// Exit codes, as the README documents them.
enum ExitCode : int { exit_ok = 0, exit_scene_error = 1, exit_usage = 2, exit_io_error = 3 };

struct RenderFlags {
    std::string scene_path;
    std::optional<std::string> output;  // wins over the scene's filename
    std::optional<std::string> camera;
    std::optional<int> width;
    std::optional<int> height;
    std::optional<int> samples;
    int threads = 0;  // 0: every core
    bool quiet = false;
};

// Declares the scene argument and -o, --camera, --width, --height, --samples,
// --threads and -q.
void add_render_flags(CLI::App& app, RenderFlags& flags);

// Adds to each diagnostic that asks for a render setting the flag that sets
// it: "... set 'width' in render_settings or pass --width".
void name_setting_flags(std::vector<Diagnostic>& diagnostics);

}  // namespace jt::frontend
