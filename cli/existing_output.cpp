#include "existing_output.hpp"

namespace jt::cli {

WantedOutput wanted_output(const Options& o, const RenderOptions& render, ImageFormat format,
                           const std::optional<RenderFingerprint>& fingerprint) {
    WantedOutput wanted{render.width, render.height, format, std::nullopt};
    if (o.region_output) wanted.placement = frontend::region_placement(o, render, fingerprint);
    return wanted;
}

bool keep_existing_output(const Options& o, const std::string& path, const WantedOutput& wanted,
                          const std::string& what) {
    return frontend::keep_existing_output("jtracer-cli", o.quiet, path, wanted, what);
}

}  // namespace jt::cli
