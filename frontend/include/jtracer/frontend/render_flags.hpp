#pragma once
// The command line every JTracer renderer shares (jtracer-cli, jtracer-mpi):
// the options and their declaration, written once so that
// both read a render the same way.

#include "jtracer/diagnostics.hpp"
#include "jtracer/frontend/argument_names.hpp"
#include "jtracer/frontend/command_line.hpp"
#include "jtracer/frontend/frame_numbering.hpp"
#include "jtracer/frontend/progress.hpp"
#include "jtracer/parser.hpp"

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace CLI {
class App;
}

namespace jt::frontend {

struct RenderFlags {
    std::string scene_path;
    std::optional<std::string> output;  // wins over the scene's filename
    // -o - (standard output, output_name): `output` is /dev/stdout, which the
    // messages about -o do not name, as the user never wrote it.
    bool output_is_stdout = false;
    std::optional<std::string> camera;
    std::optional<int> width;
    std::optional<int> height;
    std::optional<int> samples;
    int threads = 0;  // 0: every core
    bool quiet = false;
    ProgressMode progress = ProgressMode::automatic;
    // --define NAME=VALUE, each checked by parse_define, in command-line
    // order; --clock V (docs/language.md §15.2, §15.4).
    std::vector<std::string> defines;
    std::optional<double> clock;
    // --frames N and --frame-range A..B: a sequence at clocks 0..1 (§15.4).
    std::optional<int> frames;
    std::optional<FrameRange> frame_range;
    // How the messages about these name them.
    ArgumentNames names = {};
};

// The options the scene is parsed with: --define and --clock, named as
// flags.names says.
ParseOptions parse_options_for(const RenderFlags& flags);
// The same from add_scene_value_flags' two values (already checked by it),
// with the source map on, named as the command line names them.
ParseOptions scene_value_options(const std::vector<std::string>& defines,
                                 std::optional<double> clock);

// Declares the scene argument and -o, --camera, --width, --height, --samples,
// --threads, --progress, -q, --define, --clock, --frames and --frame-range.
void add_render_flags(CLI::App& app, RenderFlags& flags);

// A warning line, "PROGRAM: warning: ...", or nothing, when the image's name
// promises a format it will not have: the scene's filename always gives a
// BMP, even `shot.png`, and -o gives a BMP for any name but .png, even
// `shot.jpg`. Image viewers, browsers and upload forms trust the name and
// refuse such a file. Also when -o holds a frame number field without
// --frames: one image is written under that very name.
std::string format_warning(std::string_view program, const RenderFlags& flags,
                           const std::string& output);

// The rules between the sequence flags, for the programs' checks: a --define
// that fails at every clock rendered (check_defines_at_their_clocks), --clock
// not with --frames, --frame-range only with --frames and within it, -o a
// pattern with one frame number field. Throws CLI::ValidationError naming
// the option.
void check_sequence_flags(const RenderFlags& flags);

// A --define of the clock that fails at every clock the command renders (at
// `clock` for one image, at each frame's clock of a whole sequence of `frames`)
// is a bad value, as one that fails at any clock: throws CLI::ValidationError
// naming --define, before anything is read. One that fails at some frames only
// is those frames' error, the one a frame range of them gets too
// (docs/language.md §15.2). check_sequence_flags calls it.
void check_defines_at_their_clocks(const std::vector<std::string>& defines,
                                   std::optional<double> clock, std::optional<int> frames);

// --define (repeatable) and --clock alone, for a front end with its own
// other flags (jtracer-view).
void add_scene_value_flags(CLI::App& app, std::vector<std::string>& defines,
                           std::optional<double>& clock);

// Adds to each diagnostic that asks for a render setting what sets it, as
// `names` names it: "... set 'width' in render_settings or pass --width".
// A setting in `passed` (given already, as --samples 1 is) gets nothing: the
// value the diagnostic is about is the one passed.
void name_setting_flags(std::vector<Diagnostic>& diagnostics, const ArgumentNames& names = {},
                        std::span<const std::string_view> passed = {});

}  // namespace jt::frontend
