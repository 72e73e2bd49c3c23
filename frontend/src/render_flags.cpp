#include "jtracer/frontend/render_flags.hpp"

#include "jtracer/frontend/command_line.hpp"
#include "jtracer/frontend/frame_file_name.hpp"
#include "jtracer/frontend/frame_numbering.hpp"

#include "jtracer/limits.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <string>

namespace jt::frontend {

void add_render_flags(CLI::App& app, RenderFlags& o) {
    app.add_option("scene", o.scene_path, "The scene file to render (.jts)")->required();
    app.add_option_function<std::string>(
           "-o,--output",
           [&o](const std::string& name) {
               o.output = output_name(name);
               o.output_is_stdout = name == "-";
           },
           "Write the image here instead of the scene's filename; a name ending in .png "
           "gives a PNG, anything else a BMP; - is standard output (a BMP)")
        ->type_name("FILE");
    app.add_option("--camera", o.camera, "Render from the camera with this name")
        ->type_name("NAME");
    const std::string sides = std::to_string(kMaxImageSide);
    app.add_option("--width", o.width,
                   "Image width in pixels, 1.." + sides + " (overrides the scene)")
        ->check(CLI::Range(1, kMaxImageSide))
        ->type_name("N");
    app.add_option("--height", o.height,
                   "Image height in pixels, 1.." + sides + " (overrides the scene)")
        ->check(CLI::Range(1, kMaxImageSide))
        ->type_name("N");
    app.add_option("--samples", o.samples,
                   "Rays per pixel, " + std::to_string(kMinSamples) + ".." +
                       std::to_string(kMaxSamples) + " (overrides the scene)")
        ->check(CLI::Range(kMinSamples, kMaxSamples))
        ->type_name("N");
    app.add_option("--threads", o.threads,
                   "Worker threads, 0..4096; 0 (the default) uses every core")
        ->check(CLI::Range(0, 4096))
        ->type_name("N");
    app.add_flag("-q,--quiet", o.quiet, "No progress bar, summary or warnings; errors still show");
    const std::map<std::string, ProgressMode> modes{{"auto", ProgressMode::automatic},
                                                    {"bar", ProgressMode::bar},
                                                    {"log", ProgressMode::log},
                                                    {"none", ProgressMode::none}};
    app.add_option("--progress", o.progress,
                   "How progress shows on stderr: auto|bar|log|none. auto (the default): a bar "
                   "on a terminal, nothing otherwise; log: a plain line at each multiple of 10% "
                   "passed (10%, 20%, ...) and at least one a minute, for log files")
        ->transform(CLI::CheckedTransformer(modes))
        ->type_name("MODE");
    add_scene_value_flags(app, o.defines, o.clock);
    app.add_option("--frames", o.frames,
                   "Render a sequence of N images, frame f at clock f / (N - 1) (0 when N is "
                   "1), 1.." +
                       std::to_string(kMaxFrames) +
                       "; -o then names them with a frame number field: -o shot-%04d.png")
        ->check(CLI::Range(1, kMaxFrames))
        ->type_name("N");
    app.add_option_function<std::string>(
           "--frame-range",
           [&o](const std::string& text) {
               Expected<FrameRange> range = parse_frame_range(text);
               if (!range) throw CLI::ValidationError("--frame-range", range.error().message);
               o.frame_range = *range;
           },
           "With --frames: render only the frames A to B, counted from 0, both included (for "
           "job arrays and farms)")
        ->type_name("A..B");
}

std::string format_warning(std::string_view program, const RenderFlags& o,
                           const std::string& output) {
    std::string ext = std::filesystem::path(output).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    static constexpr std::string_view other_images[] = {".jpg",  ".jpeg", ".tif",  ".tiff", ".gif",
                                                        ".webp", ".exr",  ".tga",  ".ppm",  ".hdr",
                                                        ".avif", ".jxl",  ".heic", ".ico"};
    const bool other =
        std::find(std::begin(other_images), std::end(other_images), ext) != std::end(other_images);
    if (!o.output && (ext == ".png" || other))
        return std::string(program) + ": warning: the scene's filename '" + output +
               "' is written as a BMP, as the scene's filename always is" +
               (ext != ".png" ? ""
                : o.frames    ? "; an -o name ending in .png writes PNGs"
                              : "; -o " + output + " writes a PNG") +
               "\n";
    if (o.output && other)
        return std::string(program) + ": warning: -o/--output '" + output +
               "' is written as a BMP: JTracer writes a PNG for a name ending in .png and a BMP "
               "for any other\n";
    // 'shot-%04d.png' without --frames is one image under that very name: the
    // field says a sequence was meant.
    if (o.output && !o.frames && parse_frame_name_pattern(output))
        return std::string(program) + ": warning: -o/--output '" + output +
               "' has a frame number field, but without --frames N one image is written under "
               "that very name\n";
    return {};
}

void check_defines_at_their_clocks(const std::vector<std::string>& defines,
                                   std::optional<double> clock, std::optional<int> frames) {
    const int count = frames.value_or(1);
    for (const std::string& argument : defines) {
        Expected<Define> define = parse_define(argument);
        // Others were evaluated by parse_define: at every clock the same.
        if (!define || define->value.find("clock") == std::string::npos) continue;
        std::optional<std::string> first;
        for (int frame = 0; frame < count; ++frame) {
            std::optional<std::string> error =
                define_error_at(*define, frames ? frame_clock(frame, count) : clock.value_or(0.0));
            if (!error) {
                first.reset();
                break;
            }
            if (!first) first = std::move(error);
        }
        if (!first) continue;
        const std::string where =
            !frames
                ? "at clock " + shortest_decimal(clock.value_or(0.0)) + ", the clock of this render"
            : count == 1 ? std::string("at clock 0, the clock of the one frame")
                         : "at clock 0, and it fails at the clock of every one of the " +
                               std::to_string(count) + " frames";
        throw CLI::ValidationError(
            "--define", "the value of " + define->name + ": " + *first + " (" + where + ")");
    }
}

void check_sequence_flags(const RenderFlags& o) {
    check_defines_at_their_clocks(o.defines, o.clock, o.frames);
    if (o.frame_range && !o.frames) throw CLI::ValidationError("--frame-range", "needs --frames N");
    if (!o.frames) return;
    if (o.clock)
        throw CLI::ValidationError("--clock",
                                   "cannot be given with --frames (each frame has its own clock)");
    if (o.frame_range)
        if (Expected<void> inside = check_frame_range(*o.frame_range, *o.frames); !inside)
            throw CLI::ValidationError("--frame-range", inside.error().message);
    // A sequence is a file a frame: standard output could only run them
    // together into one stream that no tool reads back as frames.
    if (o.output_is_stdout)
        throw CLI::ValidationError("-o/--output",
                                   "- (standard output) takes one image, but --frames writes a "
                                   "file a frame: name them with a frame number field, such as "
                                   "-o shot-%04d.png");
    if (o.output)
        if (Expected<FrameNamePattern> pattern = parse_frame_name_pattern(*o.output); !pattern)
            throw CLI::ValidationError("-o/--output", pattern.error().message);
}

void add_scene_value_flags(CLI::App& app, std::vector<std::string>& defines,
                           std::optional<double>& clock) {
    app.add_option("--define", defines,
                   "Set a name the scene defines, as a file would write its value: r=2, "
                   "'c=<1, 0, 0>', 's=\"out.png\"' (repeatable; the file's own definition is "
                   "then ignored)")
        ->check(CLI::Validator(
            [](std::string& argument) -> std::string {
                Expected<Define> define = parse_define(argument, ArgumentNames{}.values);
                return define ? std::string() : define.error().message;
            },
            "NAME=VALUE"))
        ->type_name("NAME=VALUE")
        ->take_all()
        ->allow_extra_args(false);
    app.add_option("--clock", clock, "The value of clock in the scene (default 0)")
        ->check(CLI::Validator(
            [](std::string& text) -> std::string {
                double value = 0.0;
                auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
                if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
                    return "expected a finite number, got '" + text + "'";
                return {};
            },
            "V"))
        ->type_name("V");
}

ParseOptions parse_options_for(const RenderFlags& flags) {
    ParseOptions options = scene_value_options(flags.defines, flags.clock);
    options.value_names = flags.names.values;
    options.source_map = false;
    options.threads = static_cast<unsigned>(flags.threads);
    return options;
}

ParseOptions scene_value_options(const std::vector<std::string>& defines,
                                 std::optional<double> clock) {
    ParseOptions options;
    for (const std::string& argument : defines)
        if (Expected<Define> define = parse_define(argument)) options.defines.push_back(*define);
    options.clock = clock.value_or(0.0);
    options.value_names = ArgumentNames{}.values;
    return options;
}

void name_setting_flags(std::vector<Diagnostic>& diagnostics, const ArgumentNames& names,
                        std::span<const std::string_view> passed) {
    // The settings a renderer's user can set beside the file.
    for (Diagnostic& d : diagnostics)
        if ((d.setting == "width" || d.setting == "height" || d.setting == "samples") &&
            std::find(passed.begin(), passed.end(), d.setting) == passed.end())
            d.message.append(" or pass ").append(names.name(d.setting)).append(names.after_pass);
}

}  // namespace jt::frontend
