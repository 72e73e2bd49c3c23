#pragma once
// The command line every JTracer renderer shares (jtracer-cli, jtracer-mpi):
// the options and their declaration, written once so that
// both read a render the same way.

#include "jtracer/diagnostics.hpp"
#include "jtracer/frontend/command_line.hpp"
#include "jtracer/frontend/progress.hpp"

#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace jt::frontend {

struct RenderFlags {
    std::string scene_path;
    std::optional<std::string> output;  // wins over the scene's filename
    std::optional<std::string> camera;
    std::optional<int> width;
    std::optional<int> height;
    std::optional<int> samples;
    int threads = 0;  // 0: every core
    bool quiet = false;
    ProgressMode progress = ProgressMode::automatic;
};

// Declares the scene argument and -o, --camera, --width, --height, --samples,
// --threads, --progress and -q.
void add_render_flags(CLI::App& app, RenderFlags& flags);

// Adds to each diagnostic that asks for a render setting the flag that sets
// it: "... set 'width' in render_settings or pass --width".
void name_setting_flags(std::vector<Diagnostic>& diagnostics);

}  // namespace jt::frontend
