#pragma once
// Patterns: the pigment a material shows at a point (docs/language.md §13.3, §13.4).

#include "jtracer/scene.hpp"
#include "jtracer/texture.hpp"

namespace jt {

// Whether the material's pigment depends on where it is hit.
bool has_pattern(const Material& m);

// Texture coordinates of an object-space point on each shape, before wrapping.
struct Uv {
    double u = 0.0, v = 0.0;
};
Uv sphere_uv(const Sphere& sphere, const Vec3& p);
Uv cylinder_uv(const Cylinder& cylinder, const Vec3& p);
Uv plane_uv(const Plane& plane, double map_size, const Vec3& p);
// Triangles and meshes take theirs from the hit (`surface`), blended from
// their corners'.
Uv shape_uv(const Shape& shape, double map_size, const Vec3& p, Uv surface = {});

// The bilinear blend of the four texel centres nearest (u, v), wrapping
// around both edges; (0, 0) is the bottom-left corner of the picture.
Colour sample_bilinear(const Texture& texture, Uv uv);

// The same blend wrapping around the left and right edges only: v = 0 and
// below is the bottom row, v = 1 and above the top row, each row a blend of
// its own texels (docs/language.md §14.3). uv.v must be a number.
Colour sample_bilinear_rows_clamped(const Texture& texture, Uv uv);

// The pigment at `object_point`, a point in the primitive's object space
// (before its transform): the image's texel when the material has one
// (`image`, loaded from its image_map), else the checker's colour on odd
// cubes, else `pigment`.
Colour pattern_pigment(const Material& m, const Texture* image, const Shape& shape,
                       const Vec3& object_point, Uv surface = {});

}  // namespace jt
