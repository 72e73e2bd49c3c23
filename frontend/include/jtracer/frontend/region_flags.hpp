#pragma once
// --region and --region-output, for the renderers that split a frame among
// machines (jtracer-cli, jtracer-mpi): declared, checked and refused alike, so
// that a farm script passes the same flags to either.

#include "jtracer/frontend/render_flags.hpp"
#include "jtracer/region.hpp"
#include "jtracer/region_file.hpp"

#include <optional>
#include <string>
#include <string_view>

namespace CLI {
class App;
}

namespace jt::frontend {

struct RegionFlags {
    // Render only this window (top-left origin, region.hpp); the rest stays black.
    std::optional<FrameRegion> region;
    bool region_output = false;  // write the region alone, as a region file (region_file.hpp)
};

// Declares --region X0,Y0,X1,Y1 and --region-output.
void add_region_flags(CLI::App& app, RegionFlags& flags);

// The rules between them and -o, for the programs' checks: --region-output
// needs --region, and a BMP name for -o. Throws CLI::ValidationError.
void check_region_flags(const RegionFlags& flags, const std::optional<std::string>& output);

// Why --skip-existing cannot go with these flags (nothing when it can): a
// --region render kept must be a region file, which records its region.
std::optional<std::string> region_skip_existing_refusal(const RegionFlags& flags);

// The error (or nothing) for a region file (--region-output, always a BMP)
// under the scene's filename `output` when that names another format: refused
// as `-o part.png --region-output` is (check_region_flags), and located at
// the scene's filename, which the user must change.
std::optional<std::string> region_output_refusal(std::string_view program,
                                                 const RenderFlags& render,
                                                 const RegionFlags& flags,
                                                 const std::string& output);

// The record a region file of this frame carries: the frame's size, the
// region, what it was rendered from.
RegionPlacement region_placement(const RegionFlags& flags, const RenderOptions& render,
                                 const std::optional<RenderFingerprint>& fingerprint);

}  // namespace jt::frontend
