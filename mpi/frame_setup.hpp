#pragma once
// What every rank does alone before rendering: read the scene file, apply the
// command line's overrides, validate, and work out the render options.

#include "mpi_options.hpp"

#include "jtracer/render_job.hpp"
#include "jtracer/scene.hpp"

#include <string>

namespace jt::mpi {

struct FrameSetup {
    int exit_code = exit_ok;  // non-zero: `message` says why
    std::string message;      // diagnostics (warnings too, unless quiet) or the error
    Scene scene;
    RenderOptions render;  // width, height, samples, camera, threads; previews off
    std::string output;    // the image file rank 0 writes
};

FrameSetup set_up_frame(const Options& options);

}  // namespace jt::mpi
