#pragma once
// Sky maps (docs/language.md §14.3): what a ray that meets nothing shows.

#include "render/pattern.hpp"
#include "render/prepared_scene.hpp"

namespace jt {

// Where the unit direction d falls on an equirectangular map: u around the
// vertical axis, 0.5 straight down -z; v = 0 straight down, 1 straight up.
Uv sky_uv(const Vec3& d);

// The colour of `map` in the unit direction d (d's components finite).
Colour sky_colour(const Texture& map, const Vec3& d);

// What a camera, reflected or refracted ray along the unit direction d returns
// when it meets nothing: the background map's colour there, else `background`.
// A direction that is not a number (a camera that forms no frame) sees the
// background colour.
inline Colour miss_colour(const PreparedScene& scene, const Vec3& d) {
    if (!scene.background_map || !all_finite(d)) return scene.settings.background;
    return sky_colour(*scene.background_map, d);
}

}  // namespace jt
