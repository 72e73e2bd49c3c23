#include "jtracer/frontend/frame_setup.hpp"

#include "jtracer/frontend/pipe_wait_notice.hpp"
#include "jtracer/parallel_chunks.hpp"
#include "jtracer/scene_file.hpp"
#include "jtracer/validate.hpp"

#include <string_view>
#include <vector>

namespace jt::frontend {

namespace {

Expected<void> apply_overrides(const RenderFlags& flags, Scene& scene) {
    if (flags.width) scene.settings.width = *flags.width;
    if (flags.height) scene.settings.height = *flags.height;
    if (flags.samples) scene.settings.samples = *flags.samples;
    if (flags.camera) {
        if (find_camera(scene, *flags.camera) < 0)
            return Error{flags.names.name("camera") + ": the scene has no camera named \"" +
                         *flags.camera + "\" (its cameras: " + camera_names(scene) + ")"};
        scene.settings.active_camera = *flags.camera;
    }
    return {};
}

// `as_parsed`: the primitives are as the parser made them, which only a set-up
// that read the file itself can say (the overrides change settings alone).
FrameSetup set_up_loaded(std::string_view program, const RenderFlags& flags, LoadedScene loaded,
                         const std::optional<FrameRegion>& region, bool as_parsed);

}  // namespace

std::string camera_names(const Scene& scene) {
    std::string names;
    std::size_t unnamed = 0;
    for (const Camera& c : scene.cameras) {
        // An unnamed camera cannot be chosen by name: listing it as "" would
        // read as a camera whose name is empty quotes.
        if (c.name.empty()) {
            ++unnamed;
            continue;
        }
        names += (names.empty() ? "\"" : ", \"") + c.name + "\"";
    }
    if (unnamed > 0)
        names += (names.empty() ? "" : " and ") + std::to_string(unnamed) + " without a name";
    return names.empty() ? "none" : names;
}

FrameSetup set_up_frame(std::string_view program, const RenderFlags& flags,
                        const std::optional<FrameRegion>& region) {
    // Without the source map: check_scene builds it only if there is something to
    // locate. A render needs the scene, not the text: a large one is given back.
    Expected<LoadedScene> read = [&] {
        const PipeWaitNotice notice(program, flags.scene_path);
        return load_scene_file(flags.scene_path, parse_options_for(flags),
                               TextKeeping::given_back_when_large);
    }();
    if (!read) {
        FrameSetup setup;
        setup.exit_code = exit_io_error;
        setup.message = std::string(program) + ": " + read.error().message + "\n";
        return setup;
    }
    return set_up_loaded(program, flags, std::move(*read), region, true);
}

FrameSetup set_up_frame(std::string_view program, const RenderFlags& flags, LoadedScene loaded,
                        LoadedPrimitives primitives, const std::optional<FrameRegion>& region) {
    return set_up_loaded(program, flags, std::move(loaded), region,
                         primitives == LoadedPrimitives::as_parsed);
}

namespace {

FrameSetup set_up_loaded(std::string_view program, const RenderFlags& flags, LoadedScene loaded,
                         const std::optional<FrameRegion>& region, bool as_parsed) {
    FrameSetup setup;
    const std::string prefix = std::string(program) + ": ";
    auto fail = [&](int code, const std::string& message) {
        setup.exit_code = code;
        setup.message += prefix + message + "\n";
        return std::move(setup);
    };
    if (Expected<void> applied = apply_overrides(flags, loaded.parsed.scene); !applied)
        return fail(exit_usage, applied.error().message);
    // The BMP limit is the scene's rule (docs/language.md §4.9), but a size
    // from the command line is the command line's error: located in the
    // file, it would point at a width or height the flag replaced.
    if (const RenderSettings& s = loaded.parsed.scene.settings; (flags.width || flags.height) &&
                                                                s.width > 0 && s.height > 0 &&
                                                                !fits_in_bmp(s.width, s.height)) {
        // "--width", "--height" or "--width/--height": what was given.
        std::string flag = flags.width ? flags.names.name("width") : "";
        if (flags.width && flags.height) flag += '/';
        if (flags.height) flag += flags.names.name("height");
        return fail(exit_usage, flag + ": a " + std::to_string(s.width) + " x " +
                                    std::to_string(s.height) +
                                    " image does not fit in a BMP file (4 GiB at most), the "
                                    "largest image JTracer renders whatever the output format");
    }
    // Quiet drops warnings: locating them would only cost another parse.
    std::vector<Diagnostic> diagnostics =
        check_scene(loaded, {.locate_warnings = !flags.quiet,
                             .validation = {.run_chunks = parallel_chunks(flags.threads),
                                            .primitives_as_parsed = as_parsed}});
    std::vector<std::string_view> passed;
    if (flags.width) passed.push_back("width");
    if (flags.height) passed.push_back("height");
    if (flags.samples) passed.push_back("samples");
    name_setting_flags(diagnostics, flags.names, passed);
    const bool errors = has_errors(diagnostics);
    if (flags.quiet && !errors) diagnostics.clear();  // quiet drops warnings, never errors
    setup.message = format_diagnostics(diagnostics, loaded);
    setup.diagnostics = std::move(diagnostics);
    if (errors) {
        setup.exit_code = exit_scene_error;
        return setup;
    }
    setup.scene = std::move(loaded.parsed.scene);
    setup.render = render_options_for(setup.scene);
    setup.render.threads = flags.threads;
    setup.render.previews = false;
    if (region) {
        if (Expected<void> inside =
                check_region_in_frame(*region, setup.render.width, setup.render.height);
            !inside)
            return fail(exit_usage, flags.names.name("region") + ": " + inside.error().message);
        setup.render.region = to_image_rect(*region, setup.render.height);
    }
    // The manual's rule: the scene's filename always yields a BMP; only a name
    // typed on the command line may ask for PNG.
    setup.output = flags.output.value_or(setup.scene.settings.filename);
    setup.format = flags.output ? format_from_extension(setup.output) : ImageFormat::bmp;
    return setup;
}

}  // namespace

}  // namespace jt::frontend
