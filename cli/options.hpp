#pragma once
// jtracer-cli's command line, parsed into a plain struct.

#include "diff_command.hpp"

#include "jtracer/frontend/render_flags.hpp"

#include "jtracer/frontend/region_flags.hpp"

#include <optional>
#include <string>
#include <vector>

namespace jt::cli {

struct Options : frontend::RenderFlags, frontend::RegionFlags {
    bool check_only = false;
    // Keep an output already there and complete instead of rendering it again
    // (existing_output.hpp).
    bool skip_existing = false;
    // Compare the written render with this reference image (diff_command.hpp).
    std::optional<std::string> expect;
    Tolerance tolerance;
    bool update = false;               // --update: a render that differs replaces the reference
    std::optional<std::string> junit;  // --junit FILE: the comparison as a JUnit test case
    bool list_cameras = false;         // print the scene's camera names only (list_names.hpp)
    bool list_defines = false;         // print the names the scene defines only (list_names.hpp)
};

struct ParsedOptions {
    Options options;
    // Set when the program should stop now with this code: after --help or
    // --version (0), or a usage error (2, message already printed).
    std::optional<int> exit_code;
};

ParsedOptions parse_options(int argc, char** argv);

// Why the files of one run cannot be as named, or nothing: the image
// (`output`, from -o or the scene's filename) would replace the scene file or
// --expect's reference, its heat map (OUT.diff.png) the reference, or the
// --junit file one of them. Each would destroy an input or make the
// comparison meaningless (a render compared with itself always matches).
// An empty `output` (not known yet) checks the --junit file alone.
std::optional<std::string> file_clash(const Options& o, const std::string& output);

// frontend::format_warning, as jtracer-cli says it.
inline std::string format_warning(const Options& o, const std::string& output) {
    return frontend::format_warning("jtracer-cli", o, output);
}

// frontend::region_output_refusal, as jtracer-cli says it.
inline std::optional<std::string> region_output_refusal(const Options& o,
                                                        const std::string& output) {
    return frontend::region_output_refusal("jtracer-cli", o, o, output);
}

}  // namespace jt::cli
