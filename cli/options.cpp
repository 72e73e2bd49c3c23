#include "options.hpp"

#include "jtracer/frontend/existing_output.hpp"
#include "jtracer/frontend/frame_file_name.hpp"
#include "jtracer/image_file.hpp"
#include "jtracer/scene_file.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <iostream>

namespace jt::cli {

std::optional<std::string> file_clash(const Options& o, const std::string& output) {
    using frontend::same_file;
    const std::string named =
        (o.output ? "-o/--output '" : "the scene's filename '") + output + "'";
    // An empty output is not known yet: only the --junit file is checked.
    if (!output.empty() && same_file(output, o.scene_path))
        return named + " is the scene file itself: the image would replace it";
    // A render sent to a device gets no heat map (check_expected).
    const std::string heat_map = o.expect && !output.empty() && !frontend::is_stream(output)
                                     ? heat_map_path_for(output)
                                     : std::string();
    if (!heat_map.empty()) {
        if (same_file(output, *o.expect))
            return named +
                   " is the reference given to --expect: the render would replace it "
                   "before the comparison; write the render elsewhere";
        if (same_file(heat_map, *o.expect))
            return "--expect '" + *o.expect + "' is where the heat map of " + named + " goes (" +
                   heat_map + "): a render outside the tolerance would replace it";
    }
    if (o.junit) {
        if (!output.empty() && (o.output_is_stdout || frontend::is_standard_output(output)) &&
            frontend::is_standard_output(*o.junit))
            return "--junit '" + *o.junit +
                   "' is standard output, which already carries the image (-o -): name a file "
                   "for the report";
        for (const auto& [what, path] :
             {std::pair<const char*, std::string>{"the scene file", o.scene_path},
              {"the image", output},
              {"the reference given to --expect", o.expect.value_or("")},
              {"where the heat map of a render outside the tolerance goes", heat_map}})
            if (!path.empty() && same_file(*o.junit, path))
                return "--junit '" + *o.junit + "' is " + what + ": the report would replace it";
    }
    return std::nullopt;
}

ParsedOptions parse_options(int argc, char** argv) {
    ParsedOptions parsed;
    Options& o = parsed.options;
    CLI::App app{"jtracer-cli: renders a JTracer scene (.jts) to a BMP or PNG image."};
    app.footer(
        "Examples:\n"
        "  jtracer-cli scenes/showcase.jts                  writes the scene's filename (BMP)\n"
        "  jtracer-cli scenes/showcase.jts -o shot.png --width 1920 --height 1080 --samples 16\n"
        "  jtracer-cli --check scenes/showcase.jts          only checks the scene\n"
        "  jtracer-cli scenes/showcase.jts --region 0,0,960,540 --region-output -o part.bmp\n"
        "  jtracer-cli scenes/showcase.jts -o shot.png --expect ref.png --threshold 2\n"
        "  jtracer-cli scenes/showcase.jts -o shot.png --expect ref.png --update\n"
        "                                                   rewrites ref.png if they differ\n"
        "  jtracer-cli diff ref.png shot.png -o diff.png     compares two images (see diff "
        "--help)\n"
        "  jtracer-cli scenes/orbit.jts --frames 48 -o orbit-%04d.png\n"
        "                                                   48 frames, clock 0 to 1\n"
        "  jtracer-cli scenes/orbit.jts --frames 48 --frame-range 0..11 -o orbit-%04d.png\n"
        "                                                   the first 12 of them\n"
        "\n"
        "Exit codes: 0 ok, 1 errors in the scene (or, with --expect, a render outside the\n"
        "tolerance), 2 bad command line, 3 file I/O error or not enough memory, 130\n"
        "interrupted (Ctrl-C), 143 stopped (SIGTERM).\n");
    frontend::add_version_flag(app, "jtracer-cli");
    frontend::add_render_flags(app, o);
    frontend::add_region_flags(app, o);
    app.add_flag("--check", o.check_only, "Only parse and validate the scene; write nothing");
    app.add_flag("--skip-existing", o.skip_existing,
                 "Keep an image already there and complete instead of rendering it again (with "
                 "--frames, frame by frame): for rerunning a frame range or a region after a "
                 "failure. Complete: every byte there, the frame's size, and for a region file "
                 "this region of this render; anything else is rendered again");
    app.add_option("--expect", o.expect,
                   "After writing the render, compare it with this reference image (BMP or "
                   "PNG); outside the tolerance, write the differences beside the render "
                   "(out.png -> out.diff.png) and exit 1")
        ->type_name("REFERENCE");
    add_tolerance_flags(app, o.tolerance);
    app.add_flag("--update", o.update,
                 "With --expect: when the render differs from the reference (or it is missing), "
                 "write the render over it, say so and exit 0; never after a failed render");
    app.add_option("--junit", o.junit,
                   "With --expect: also write the comparison as a JUnit XML test case to this "
                   "file, failed outside the tolerance with the figures as its message")
        ->type_name("FILE");
    // For the shell completions; not a user's option.
    app.add_flag("--list-cameras", o.list_cameras)->group("");
    app.add_flag("--list-defines", o.list_defines)->group("");
    // Rules between options, reported like CLI11's own errors.
    auto checks = [&] {
        // An empty name would fail only after the render, as a write error
        // ("cannot write an image to an empty file name", even for --junit).
        for (const auto& [flag, name] :
             {std::pair<const char*, const std::optional<std::string>*>{"-o/--output", &o.output},
              {"--expect", &o.expect},
              {"--junit", &o.junit}})
            if (*name && (*name)->empty())
                throw CLI::ValidationError(flag, "needs a file name, not an empty string");
        if (o.output)
            if (std::optional<std::string> refused = frontend::output_refusal(*o.output))
                throw CLI::ValidationError("-o/--output", *refused);
        frontend::check_region_flags(o, o.output);
        if (o.expect && (o.region || o.check_only))
            throw CLI::ValidationError("--expect",
                                       "compares a whole render: not with --region "
                                       "or --check");
        const bool tolerance_given = app.count("--threshold") + app.count("--max-pixels") > 0;
        if (tolerance_given && !o.expect)
            throw CLI::ValidationError("--threshold/--max-pixels", "need --expect REFERENCE");
        if ((o.update || o.junit) && !o.expect)
            throw CLI::ValidationError(o.update ? "--update" : "--junit",
                                       "needs --expect REFERENCE");
        if (o.skip_existing) {
            auto refuse = [](const std::string& why) {
                throw CLI::ValidationError("--skip-existing", why);
            };
            if (o.check_only) refuse("not with --check, which writes nothing");
            if (o.expect) refuse("not with --expect, which compares a render it has just made");
            if (std::optional<std::string> why = frontend::region_skip_existing_refusal(o))
                refuse(*why);
            if (std::optional<std::string> why = frontend::skip_existing_refusal(o)) refuse(*why);
        }
        if (o.expect && o.frames)
            throw CLI::ValidationError("--expect", "compares one image: not with --frames");
        frontend::check_sequence_flags(o);
        // An -o with a frame field names a file a frame (the sequence checks
        // each frame's, sequence_command.cpp); the scene's filename is known
        // only once the scene is read (main.cpp checks it then).
        const bool one_image = !o.frames && !o.check_only;
        if (std::optional<std::string> clash =
                file_clash(o, one_image ? o.output.value_or("") : std::string()))
            throw CLI::ValidationError(*clash);
    };
    if (std::optional<int> code =
            frontend::parse_command_line(app, argc, argv, "jtracer-cli", checks))
        parsed.exit_code = *code;
    return parsed;
}

}  // namespace jt::cli
