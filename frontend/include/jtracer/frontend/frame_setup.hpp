#pragma once
// What a renderer does with its command line before it renders: read the
// scene file, apply the flags that override the scene's values, check the
// result (parse and validation diagnostics), and work out the frame to render:
// size, camera, samples, region, and the image file to write.
//
// The overrides come before validation, so that the checks see what will
// render (validate.hpp).

#include "jtracer/frontend/render_flags.hpp"

#include "jtracer/image_file.hpp"
#include "jtracer/region.hpp"
#include "jtracer/render_job.hpp"
#include "jtracer/scene.hpp"
#include "jtracer/scene_file.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace jt::frontend {

struct FrameSetup {
    int exit_code = exit_ok;  // non-zero: stop with it; `message` says why
    // To print on stderr whatever the verdict: the diagnostics (warnings only
    // when not quiet), or the error, each line ending in '\n'.
    std::string message;
    std::vector<Diagnostic> diagnostics;  // what `message` lists, for a caller that wants them
    Scene scene;                          // with the overrides applied; free of errors
    RenderOptions render;                 // size, samples, camera, threads, region; previews off
    std::string output;                   // the image file to write
    ImageFormat format = ImageFormat::bmp;
};

// `program` ("jtracer-cli") starts the messages that are not diagnostics;
// they name the flags as flags.names does. `region` (top-left origin,
// region.hpp) outside the frame is a usage error (exit_usage, "--region: ...").
FrameSetup set_up_frame(std::string_view program, const RenderFlags& flags,
                        const std::optional<FrameRegion>& region = std::nullopt);

// Whether a loaded scene's primitives are exactly as the parser made them
// (ValidateOptions::primitives_as_parsed): then the parser's range checks are
// not made again. A scene edited or built in code is `changed`.
enum class LoadedPrimitives { as_parsed, changed };

// The same for a scene already read (flags.scene_path is not used): what a
// program that holds scenes in memory (the Python module) renders, set up
// exactly as the command line sets up a file.
FrameSetup set_up_frame(std::string_view program, const RenderFlags& flags, LoadedScene loaded,
                        LoadedPrimitives primitives,
                        const std::optional<FrameRegion>& region = std::nullopt);

// The scene's camera names, quoted, for messages: "\"front\", \"top\"", with
// "and 2 without a name" for the unnamed ones, or
// "none".
std::string camera_names(const Scene& scene);

}  // namespace jt::frontend
