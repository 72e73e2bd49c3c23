#pragma once
// The render-ready scene (the private side of render_job.hpp's PreparedScene).
//
// Geometry is split by how it is intersected, into flat arrays with no virtual
// dispatch: spheres that stay spheres in world space, shapes that need their
// inverse transform, and infinite planes (outside the BVH). Every entry keeps
// `source`, the index of the Scene primitive it came from, for its material.

#include "geometry/bounds.hpp"
#include "jtracer/affine.hpp"
#include "jtracer/file_stamp.hpp"
#include "jtracer/render_job.hpp"
#include "jtracer/scene.hpp"
#include "jtracer/texture.hpp"
#include "render/direction_table.hpp"
#include "render/triangle_geometry.hpp"

#include <embree3/rtcore.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace jt {

struct WorldSphere {
    Vec3 center{0.0};
    double radius = 1.0;
    std::uint32_t source = 0;
};

// A sphere or cylinder defined in object space (sphere: center and radius;
// cylinder: radius and height) and seen through a non-trivial transform.
struct TransformedShape {
    enum class Kind : std::uint8_t { sphere, cylinder };
    // A sphere's maps to its object space moved to its centre (add_sphere
    // says why), where its centre is the origin.
    Affine to_object;
    glm::dmat3 normal_matrix{1.0};  // inverse transpose of the object-to-world map
    Vec3 center{0.0};
    double radius = 1.0;
    double height = 1.0;
    Kind kind = Kind::sphere;
    std::uint32_t source = 0;
    RTCBounds bounds{};
    // A sphere around the padded box, for rejecting rays cheaply when no BVH
    // walk does it (a few shapes, a direction table's list).
    Vec3 bounding_center{0.0};
    double bounding_radius_sq = 0.0;
};

struct WorldPlane {
    Vec3 normal{0.0, 1.0, 0.0};  // unit
    double distance = 0.0;
    std::uint32_t source = 0;
};

// The BVH of hard shadow rays, native float spheres that cull for the exact
// test (render/shadow_spheres.hpp); its scene is null when there is none.
struct ShadowSpheres {
    RTCScene bvh = nullptr;
    double reach = 0.0;  // the largest coordinate of an origin it takes
    double tail = 0.0;   // how far past their end its float rays run
};

struct PatternSpace {
    Affine to_object;
    Shape shape;
};

// Spheres decided at once by render/sphere_batch.hpp's early answers: two
// SSE2 registers a value, or one AVX register.
inline constexpr std::size_t sphere_batch = 4;

// Four spheres' centres and radii, a value's four lanes side by side: read as
// whole registers, where a batch of listed spheres gathers each value.
struct alignas(32) SphereLanes {
    double x[sphere_batch], y[sphere_batch], z[sphere_batch], r[sphere_batch];
};

// The bounded shapes of a small scene in groups of sphere_batch, for the rays
// without a list (render/shape_groups.hpp).
struct ShapeGroups {
    // Group g's lanes: a sphere's own centre and radius, or a transformed
    // shape's bounding sphere; what lane k is, as listed_shapes.hpp lists it,
    // at listed[sphere_batch * g + k]. Unused lanes repeat the group's first.
    std::vector<SphereLanes> members;
    std::vector<std::uint32_t> listed;
    // Of each group: the bits of its used lanes, and of its sphere lanes.
    std::vector<std::uint8_t> used;
    std::vector<std::uint8_t> spheres;
    // The groups' spheres, sphere_batch groups an entry (unused lanes repeat
    // the last group's and are never read).
    std::vector<SphereLanes> bounds;
    // The largest coordinate of an origin the groups take.
    double reach = 0.0;
    std::size_t count() const { return members.size(); }
    bool empty() const { return members.empty(); }
};

struct GeometryDigest {
    std::uint64_t a = 0, b = 0;
    std::size_t primitives = 0;
    bool operator==(const GeometryDigest&) const = default;
};

// Of the scene's primitives and the stamps of the model files they name.
GeometryDigest digest_geometry(const Scene& scene);

// Shapes, transforms and the BVH: the part worth reusing when only materials,
// lights, cameras or settings change.
struct Geometry {
    std::vector<WorldSphere> spheres;
    std::vector<TransformedShape> shapes;
    std::vector<WorldPlane> planes;
    double bounds_slack = 0.0;  // world-space margin added to every box
    // Null when there are so few bounded shapes that testing each one beats a
    // BVH walk (Embree's per-ray overhead dominates a handful of shapes).
    RTCScene bvh = nullptr;
    unsigned sphere_geometry_id = RTC_INVALID_GEOMETRY_ID;
    unsigned shape_geometry_id = RTC_INVALID_GEOMETRY_ID;
    // With a BVH: the spheres and shapes (listed as in listed_shapes.hpp)
    // whose boxes reach past what Embree's BVH holds (render/far_ray.hpp).
    // The BVH leaves them out, so every query tests them exactly, as it does
    // the planes. Empty in any scene whose numbers stay near unit size.
    std::vector<std::uint32_t> beyond_bvh;
    ShadowSpheres shadow;
    // With a BVH of at most max_grouped_shapes shapes, none beyond it: the
    // shapes in groups of four, which rays without a list test instead of
    // walking the BVH (render/shape_groups.hpp).
    ShapeGroups groups;
    // Whether the spheres overlap heavily (render/shadow_spheres.hpp); only
    // then is there a shadow BVH, and hard shadow rays walk longer cell lists.
    bool crowded = false;
    // Triangles and meshes, in Embree's own geometry; null when there are none.
    std::unique_ptr<TriangleGeometry> triangles;

    // A 128-bit digest of what the geometry was built from (shapes and
    // transforms in order), to recognise it again without keeping a copy.
    GeometryDigest digest;

    Geometry() = default;
    Geometry(const Geometry&) = delete;
    Geometry& operator=(const Geometry&) = delete;
    ~Geometry();
};

// Sphere `i`'s box as the BVH holds it: grown by bounds_slack and rounded
// outward to floats. Worked out whenever the builder asks, never kept: the
// spheres are sorted in the order the Morton builder asks for them, where
// working a box out costs about what reading a kept one does, and a million
// kept boxes would take 24 MB at the peak of the build.
inline RTCBounds padded_sphere_bounds(const Geometry& g, std::size_t i) {
    return padded_float_bounds(sphere_box(g.spheres[i].center, g.spheres[i].radius),
                               g.bounds_slack);
}

struct PreparedScene {
    std::shared_ptr<const Geometry> geometry;
    // The scene itself, when its caller shares it unchanging
    // (prepare_scene(std::shared_ptr<const Scene>)), no material has a pattern
    // and a copy would be large: each primitive's material is then read where
    // the scene holds it, and `materials` and `material_of` stay empty. A scene
    // handed over (prepare_scene(Scene&&)) is never kept: its materials are
    // moved into `materials` and its primitives freed, 96 bytes a primitive,
    // before the BVH is built.
    std::shared_ptr<const Scene> scene;
    // Runs of primitives with equal materials share one entry.
    std::vector<Material> materials;
    // Each Scene primitive's entry of `materials`; empty with `materials` not
    // when every primitive has an entry of its own, the one at its index (a
    // scene handed over with no two neighbours alike): shading then reads one
    // array where it would read two at random places.
    std::vector<std::uint32_t> material_of;
    // Each Scene primitive's shape and world-to-object map, for patterns;
    // empty when no material has one.
    std::vector<PatternSpace> pattern_space;
    // The picture of each material's image_map (null for none), parallel to
    // `materials` when any material has a pattern, else empty; a file named by
    // several materials is loaded once.
    std::vector<std::shared_ptr<const Texture>> textures;
    // Where each picture of `textures` was read from and its stamp then, one
    // entry a material with an image_map: a million plain materials need none.
    struct TextureSource {
        std::size_t material = 0;
        std::filesystem::path file;
        FileStamp stamp;
    };
    std::vector<TextureSource> texture_sources;
    // The picture of render_settings' background_map (null for none), where it
    // was read from and its stamp then, as for `textures`.
    std::shared_ptr<const Texture> background_map;
    std::filesystem::path background_map_file;
    FileStamp background_map_stamp;
    // Whether any material transmits: only then do shadow rays look past the
    // first surface they meet (docs/language.md §13.2).
    bool has_transmission = false;
    std::vector<PointLight> lights;
    // Shadow-ray candidates, one table a light (none when no table pays);
    // shared with the previous PreparedScene when geometry and lights are.
    std::shared_ptr<const std::vector<DirectionTable>> light_tables;
    std::vector<Camera> cameras;
    RenderSettings settings;
    // How many primitives' materials this preparation gathered: every one for
    // prepare_scene, only those an edit changed for prepare_scene_edit (how a
    // test tells that the whole scene was not prepared again).
    std::size_t materials_gathered = 0;
};

// The entry of `materials` (and of `textures`) of Scene primitive `source`,
// when the materials are not read in place.
inline std::uint32_t material_entry(const PreparedScene& prepared, std::uint32_t source) {
    return prepared.material_of.empty() ? source : prepared.material_of[source];
}

// The material of Scene primitive `source`.
inline const Material& primitive_material(const PreparedScene& prepared, std::uint32_t source) {
    return prepared.scene ? prepared.scene->primitives[source].material
                          : prepared.materials[material_entry(prepared, source)];
}

}  // namespace jt
