#pragma once
// The points at which a light of some radius is tested for shadow
// (docs/language.md §14.1): a sunflower spiral on the disk through the
// light's centre that faces the shading point, turned by the pixel's angle.

#include "jtracer/scene.hpp"
#include "render/pixel_hash.hpp"

#include <glm/geometric.hpp>

#include <cmath>

namespace jt {

struct LightDisk {
    Vec3 centre{0.0};
    double radius = 0.0;
    Vec3 e1{1.0, 0.0, 0.0};  // unit, across the direction to the light
    Vec3 e2{0.0, 1.0, 0.0};  // unit, across both
};

// The disk of a light at `centre` seen along the unit direction `l` toward it.
inline LightDisk light_disk(const Vec3& centre, double radius, const Vec3& l) {
    Vec3 across = glm::cross(l, Vec3(0.0, 1.0, 0.0));
    // Straight up or down: any other axis does.
    if (across.x == 0.0 && across.y == 0.0 && across.z == 0.0)
        across = glm::cross(l, Vec3(1.0, 0.0, 0.0));
    LightDisk disk;
    disk.centre = centre;
    disk.radius = radius;
    disk.e1 = glm::normalize(across);
    disk.e2 = glm::cross(l, disk.e1);
    return disk;
}

// Point m of `count` on the disk: equal areas between successive radii, so
// the points are spread evenly whatever `count` is.
inline Vec3 disk_point(const LightDisk& disk, int m, int count, double turn) {
    const double rho = disk.radius * std::sqrt((m + 0.5) / count);
    const double theta = m * kGoldenAngle + turn;
    return disk.centre + rho * (std::cos(theta) * disk.e1 + std::sin(theta) * disk.e2);
}

}  // namespace jt
