#pragma once
// Attaching a set of JTracer's own shapes to an Embree scene as one user
// geometry: Embree builds the BVH over the boxes `bounds` gives and calls
// `intersect` / `occluded` for each candidate, which decide it exactly.

#include <embree3/rtcore.h>

#include <cstddef>

namespace jt {

// Embree builds a user geometry's tree at the geometry's own quality: the
// scene's quality alone still gets the SAH build. Returns the geometry's id.
unsigned attach_user_geometry(RTCScene scene, void* user_data, std::size_t count,
                              RTCBuildQuality quality, RTCBoundsFunction bounds,
                              RTCIntersectFunctionN intersect, RTCOccludedFunctionN occluded);

// The bounds callbacks of the spheres' and the shapes' user geometries,
// whose user data is the Geometry: each sphere's box padded as the BVH needs
// it, each shape's padded box.
void sphere_bounds(const RTCBoundsFunctionArguments* args);
void shape_bounds(const RTCBoundsFunctionArguments* args);

}  // namespace jt
