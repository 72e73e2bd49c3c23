#include "jtracer/frontend/region_flags.hpp"

#include "jtracer/image_file.hpp"
#include "jtracer/scene_file.hpp"

#include <CLI/CLI.hpp>

namespace jt::frontend {

namespace {

// Why --region-output takes no other name than a BMP's, for both ways of
// naming its file.
constexpr std::string_view kRegionFileIsBmp =
    "writes a BMP (its placement record lives in the BMP)";

}  // namespace

void add_region_flags(CLI::App& app, RegionFlags& flags) {
    app.add_option_function<std::string>(
           "--region",
           [&flags](const std::string& text) {
               Expected<FrameRegion> region = parse_frame_region(text);
               if (!region) throw CLI::ValidationError("--region", region.error().message);
               flags.region = *region;
           },
           "Render only the pixels X0 <= x < X1, Y0 <= y < Y1, counted from the top-left "
           "corner as image viewers show them; the rest of the image stays black")
        ->type_name("X0,Y0,X1,Y1");
    app.add_flag("--region-output", flags.region_output,
                 "With --region: write only the region, as a BMP that records where it belongs "
                 "and what it was rendered from (jtracer-merge assembles such parts)");
}

void check_region_flags(const RegionFlags& flags, const std::optional<std::string>& output) {
    if (flags.region_output && !flags.region)
        throw CLI::ValidationError("--region-output", "needs --region X0,Y0,X1,Y1");
    if (flags.region_output && output && format_from_extension(*output) != ImageFormat::bmp)
        throw CLI::ValidationError("--region-output",
                                   std::string(kRegionFileIsBmp) + "; name the output .bmp");
}

std::optional<std::string> region_skip_existing_refusal(const RegionFlags& flags) {
    if (!flags.region || flags.region_output) return std::nullopt;
    return "with --region, needs --region-output: a whole-frame image does not record which "
           "region it holds, a region file does";
}

std::optional<std::string> region_output_refusal(std::string_view program,
                                                 const RenderFlags& render,
                                                 const RegionFlags& flags,
                                                 const std::string& output) {
    if (!flags.region_output || render.output || format_from_extension(output) == ImageFormat::bmp)
        return std::nullopt;
    const std::string message = "--region-output " + std::string(kRegionFileIsBmp) +
                                ": name the scene's filename .bmp, or the output with -o";
    // The scene was read without its source map: read again to say where.
    ParseOptions options = parse_options_for(render);
    options.source_map = true;
    const Expected<LoadedScene> loaded = load_scene_file(render.scene_path, options);
    if (!loaded) return std::string(program) + ": " + message + "\n";
    SourcePos at;
    if (const std::optional<BlockSource>& block = loaded->parsed.source.render_settings)
        for (const PropertySource& p : properties_of(loaded->parsed.source, *block))
            if (p.name == "filename") at = p.value_span.pos;  // the last one is in effect
    return format_diagnostics({Diagnostic{Severity::error, at, message}}, *loaded);
}

RegionPlacement region_placement(const RegionFlags& flags, const RenderOptions& render,
                                 const std::optional<RenderFingerprint>& fingerprint) {
    return {render.width, render.height, *flags.region, fingerprint};
}

}  // namespace jt::frontend
