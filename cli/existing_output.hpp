#pragma once
// --skip-existing in jtracer-cli: what a run of these options would write, for
// the shared check (jtracer/frontend/existing_output.hpp).

#include "options.hpp"

#include "jtracer/frontend/existing_output.hpp"
#include "jtracer/render_job.hpp"

#include <optional>
#include <string>

namespace jt::cli {

using frontend::WantedOutput;

// What a render of `render` writes as `format` under these options; a region
// file carries `fingerprint`.
WantedOutput wanted_output(const Options& o, const RenderOptions& render, ImageFormat format,
                           const std::optional<RenderFingerprint>& fingerprint);

// frontend::keep_existing_output, as jtracer-cli says it.
bool keep_existing_output(const Options& o, const std::string& path, const WantedOutput& wanted,
                          const std::string& what = "");

}  // namespace jt::cli
