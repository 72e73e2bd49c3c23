#pragma once
// Triangles (docs/language.md §13.5) as Embree's own triangle geometry: one
// RTCScene per distinct model file, instanced once per mesh that uses it (100
// copies cost one model's memory), and the scene's `triangle` blocks in one
// world-space geometry. Embree finds the hit in single precision with its
// watertight (robust) test; every hit is then refined in double precision on
// the triangle found, so secondary rays never meet their own surface again.
//
// A scene with no triangle has no TriangleGeometry at all and pays nothing.

#include "jtracer/affine.hpp"
#include "jtracer/error.hpp"
#include "jtracer/model_file.hpp"
#include "jtracer/scene.hpp"
#include "jtracer/smooth_normals.hpp"

#include <embree3/rtcore.h>

#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

namespace jt {

// A model in its own Embree scene, shared by all its instances, and the
// corner normals generated for it, one set for each smooth_angle its smooth
// meshes name (docs/language.md §14.4).
struct TriangleModel {
    std::shared_ptr<const Model> model;
    RTCScene scene = nullptr;
    // The model's corners times 2^-e, by e: for meshes whose map shrinks them
    // past what Embree's float instance transform holds (attach_instance).
    std::map<int, RTCScene> shrunk;
    std::map<double, std::shared_ptr<const CornerNormals>> generated;
    // Every corner of every triangle (3 * triangle + corner), sorted by its
    // position: the triangles around a point (corners_by_position in
    // triangle_queries.cpp). Built on first use, by whichever render thread
    // needs it: most scenes never do.
    mutable std::once_flag corners_sorted;
    mutable std::vector<std::uint32_t> corners_by_position;
    // The largest magnitude of any corner coordinate, and the corners' box.
    double extent = 0.0;
    Vec3 lower{0.0}, upper{0.0};

    TriangleModel() = default;
    TriangleModel(const TriangleModel&) = delete;
    TriangleModel& operator=(const TriangleModel&) = delete;
    ~TriangleModel();
};

// One mesh primitive: a model placed by its transform.
struct MeshInstance {
    std::uint32_t model = 0;  // index into TriangleGeometry::models
    Affine to_object;
    glm::dmat3 normal_matrix{1.0};  // inverse transpose of the object-to-world map
    bool smooth = true;             // shading: "smooth"
    // With smooth_angle, when the file lacks a normal at some corner: every
    // corner's normal (in TriangleModel::generated). Null: the file's normals
    // alone, as in language 1.1.
    const CornerNormals* corner_normals = nullptr;
    // materials: "file": the model's parts give the pigment (render/file_pigment.hpp).
    bool file_materials = false;
    std::uint32_t source = 0;
};

// One triangle block, moved to world space: corners in double precision, its
// texture coordinates, and the Scene primitive it came from. Under a mirroring
// transform the world-space corners wind the other way round the outward
// normal M^-T cross(b - a, c - a) (docs/language.md §13.5): `mirrored` says so.
struct LooseTriangle {
    std::array<Vec3, 3> corners;
    std::array<glm::dvec2, 3> uvs;
    std::uint32_t source = 0;
    bool mirrored = false;
};

// A mesh walked on its own: each ray is moved into the model's space in
// double precision, times 2^-exponent, to where it enters the model's box,
// and walks `corners` (its model's corners times 2^-exponent) on its own.
// Far instances are those whose triangles reach past what Embree's BVH holds
// (1.8e18, see render/far_ray.hpp), in the world or in its file, which
// Embree's top BVH leaves out without a word, or whose map is so
// ill-conditioned that Embree's float move into its space misses faces
// (triangle_geometry.cpp); boxed instances are all the others, in a scene
// with more than one mesh, or a mesh and triangle blocks.
struct FarInstance {
    std::uint32_t instance = 0;  // index into TriangleGeometry::instances
    RTCScene corners = nullptr;  // owned by the model
    RTCBounds corners_bounds{};  // of `corners`, once committed
    int exponent = 0;
    // A world-space box around the mesh, padded far beyond rounding: a ray
    // that misses it is not walked.
    Vec3 lower{-std::numeric_limits<double>::infinity()};
    Vec3 upper{std::numeric_limits<double>::infinity()};
};

struct TriangleGeometry {
    std::vector<std::unique_ptr<TriangleModel>> models;
    std::vector<MeshInstance> instances;  // index = instance geometry id in `scene`
    std::vector<FarInstance> far_instances;
    // Embree's float test rounds its edge values at the size of the ray's
    // start in the mesh's space: from hundreds of model sizes away, a ray
    // exactly through a vertex came out on one side of every edge there and
    // met none of the faces around it. A ray from outside the box of all the
    // triangles starts where it enters that box, which is the mesh's own
    // when it is the only one; with more, the meshes are found by their
    // world boxes (one user geometry) and each ray
    // walks each mesh it may meet from where it enters that mesh's box.
    std::vector<FarInstance> boxed_instances;
    std::vector<LooseTriangle> loose;
    // Loose triangles with a corner past Embree's reach (indices into
    // `loose`): its BVH leaves them out, so each query tests them exactly.
    std::vector<std::uint32_t> far_loose;
    bool file_materials = false;  // some instance has materials: "file"
    RTCScene scene = nullptr;     // the instances and the loose triangles
    RTCBounds bounds{};           // of `scene`, once committed

    TriangleGeometry() = default;
    TriangleGeometry(const TriangleGeometry&) = delete;
    TriangleGeometry& operator=(const TriangleGeometry&) = delete;
    ~TriangleGeometry();
};

// Which triangle: the instance (or no_instance for a loose triangle) and the
// triangle's index in its model (or in `loose`).
struct TriangleId {
    static constexpr std::uint32_t no_instance = std::numeric_limits<std::uint32_t>::max();
    std::uint32_t instance = no_instance;
    std::uint32_t triangle = std::numeric_limits<std::uint32_t>::max();
    bool operator==(const TriangleId&) const = default;
};

// The triangles of a scene's triangle and mesh primitives, or null when it has
// none. A mesh whose file cannot be read is an error; one with no triangle is
// left out (the validator warned). Each file is read once (model_cache.hpp).
Expected<std::unique_ptr<TriangleGeometry>> build_triangle_geometry(const Scene& scene);

}  // namespace jt
