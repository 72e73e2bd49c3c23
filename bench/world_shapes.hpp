#pragma once
// A scene's primitives placed in world space as plain spheres, capped cylinders
// and planes: what jts-to-tachyon writes and what kernel-limit hands to
// Embree's native geometry. Placement follows the renderer's rules
// (jtracer/affine.hpp): left-out primitives are skipped, and a sphere or
// cylinder stays one only under a rotation and a uniform scale.

#include "jtracer/affine.hpp"
#include "jtracer/scene.hpp"

#include <cstddef>
#include <optional>
#include <vector>

namespace jt::bench {

struct WorldSphere {
    Vec3 center{0.0};
    double radius = 0.0;
    std::size_t primitive = 0;  // index into Scene::primitives
};

struct WorldCylinder {
    Vec3 base{0.0}, apex{0.0};  // the centres of the two caps
    double radius = 0.0;
    std::size_t primitive = 0;
};

struct WorldPlane {
    Vec3 point{0.0};   // a point of the plane
    Vec3 normal{0.0};  // unit
    std::size_t primitive = 0;
};

struct WorldShapes {
    std::vector<WorldSphere> spheres;
    std::vector<WorldCylinder> cylinders;
    std::vector<WorldPlane> planes;
    // The first primitive that is neither left out nor a plain shape in world
    // space (an ellipsoid, an elliptic cylinder, a triangle or mesh), if any; it is
    // not in the lists.
    std::optional<std::size_t> first_unplaceable;
};

inline WorldShapes world_shapes(const Scene& scene) {
    WorldShapes shapes;
    for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
        const Primitive& p = scene.primitives[i];
        const auto placed = object_transform(p.transforms);
        if (std::holds_alternative<LeftOut>(placed)) continue;
        const ObjectTransform& transform = std::get<ObjectTransform>(placed);
        const Affine& world = transform.to_world;
        if (const auto* plane = shape_if<Plane>(&p.shape)) {
            auto n = unit_length(plane->normal);
            auto world_normal = n ? unit_length(transform.normal_matrix * *n) : std::nullopt;
            if (world_normal)
                shapes.planes.push_back(
                    {apply_point(world, *n * plane->distance), *world_normal, i});
            continue;
        }
        auto scale = similarity_scale(world.linear);
        // Triangles and meshes are not among the shapes these tools compare.
        const bool triangles = shape_is<Triangle>(p.shape) || shape_is<Mesh>(p.shape);
        if (!scale || triangles) {
            if (!shapes.first_unplaceable) shapes.first_unplaceable = i;
            continue;
        }
        if (const auto* sphere = shape_if<Sphere>(&p.shape)) {
            shapes.spheres.push_back(
                {apply_point(world, sphere->center), *scale * sphere->radius, i});
        } else if (const auto* cylinder = shape_if<Cylinder>(&p.shape)) {
            shapes.cylinders.push_back({apply_point(world, Vec3(0.0)),
                                        apply_point(world, Vec3(0.0, cylinder->height, 0.0)),
                                        *scale * cylinder->radius, i});
        }
    }
    return shapes;
}

}  // namespace jt::bench
