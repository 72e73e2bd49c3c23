#pragma once
// The fingerprint a region file carries (region_file.hpp): what its pixels
// were rendered from, so that jtracer-merge refuses parts of different scenes,
// versions of one scene, clocks, sample counts or cameras.

#include "jtracer/region_file.hpp"
#include "jtracer/render_job.hpp"
#include "jtracer/scene.hpp"

namespace jt::frontend {

// `scene` as set up to render (defines, clock and flags applied). Its digest
// covers every value of the scene model (the canonical text of its settings,
// cameras and lights, serializer.hpp, and each primitive's values as the
// schema lists them), so that comments, layout and the way a value was
// written do not count but every value does, and the bytes of every file it
// names (models, image maps). Left out: what
// the fingerprint holds apart (samples, camera, clock), what the placement
// holds (the frame's size), and the output's name (each part has its own). The
// same on every machine: no path beyond the names the scene gives is read
// into it.
RenderFingerprint render_fingerprint(const Scene& scene, const RenderOptions& render, double clock);

}  // namespace jt::frontend
