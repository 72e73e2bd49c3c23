#pragma once
// Closest-hit and any-hit queries against the triangles (triangle_geometry.hpp).
// Embree's watertight single-precision test decides which triangle a ray
// meets; our filter callbacks then put the hit on that triangle in double
// precision and drop it unless it lies in the query's (t_min, t_max), so a ray
// leaving a surface never meets it again however Embree's float rounds.

#include "render/triangle_geometry.hpp"

#include <glm/vec2.hpp>

namespace jt {

struct TriangleHit {
    double t = 0.0;
    double u = 0.0, v = 0.0;  // barycentric weights of the second and third corner
    TriangleId id;
    std::uint32_t source = 0;
};

// Where a secondary ray leaves a triangle: which one, and the point P on it
// that the ray's origin is P lifted from (docs/language.md §8.5). A primary
// ray leaves none.
struct Departure {
    TriangleId triangle;
    Vec3 point{0.0};
};

// The nearest triangle along origin + t * direction with t in (t_min, t_max).
// A ray that leaves a triangle never meets it, and meets a triangle that
// shares a corner with it only where the ray from P itself passes inside that
// triangle farther than the lift from P (docs/language.md §13.5).
bool closest_triangle(const TriangleGeometry& g, const Vec3& origin, const Vec3& direction,
                      double t_min, double t_max, TriangleHit& hit, const Departure& from = {});

// Whether a triangle lies at some t in (t_min, t_max), as closest_triangle meets them.
bool triangle_blocks(const TriangleGeometry& g, const Vec3& origin, const Vec3& direction,
                     double t_min, double t_max, const Departure& from = {});

// What shading needs at a hit: the outward geometric normal
// cross(b - a, c - a) in world space (not unit length); the smooth shading
// normal in world space, or zero when the triangle has none (docs/language.md
// §13.5); the texture coordinates, (0, 0) when the file has none.
struct TriangleSurface {
    Vec3 geometric{0.0};
    Vec3 shading{0.0};
    glm::dvec2 uv{0.0};
};
TriangleSurface triangle_surface(const TriangleGeometry& g, const TriangleHit& hit);

// Embree filter callbacks; build_triangle_geometry registers them.
void triangle_intersect_filter(const RTCFilterFunctionNArguments* args);
void triangle_occluded_filter(const RTCFilterFunctionNArguments* args);

// The user geometry callbacks of TriangleGeometry::boxed_instances: each
// walks the mesh whose box Embree found.
void boxed_instance_intersect(const RTCIntersectFunctionNArguments* args);
void boxed_instance_occluded(const RTCOccludedFunctionNArguments* args);

}  // namespace jt
