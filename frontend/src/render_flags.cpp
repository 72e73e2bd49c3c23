#include "jtracer/frontend/render_flags.hpp"

#include "jtracer/limits.hpp"

#include <CLI/CLI.hpp>

#include <map>
#include <string>

namespace jt::frontend {

void add_render_flags(CLI::App& app, RenderFlags& o) {
    app.add_option("scene", o.scene_path, "The scene file to render (.jts)")->required();
    app.add_option("-o,--output", o.output,
                   "Write the image here instead of the scene's filename; a name ending in .png "
                   "gives a PNG, anything else a BMP")
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
                   "on a terminal, nothing otherwise; log: a plain line per 10%, for log files")
        ->transform(CLI::CheckedTransformer(modes))
        ->type_name("MODE");
}

void name_setting_flags(std::vector<Diagnostic>& diagnostics) {
    for (Diagnostic& d : diagnostics) {
        if (d.setting == "width" || d.setting == "height" || d.setting == "samples") {
            d.message.append(" or pass --").append(d.setting);
        }
    }
}

}  // namespace jt::frontend
