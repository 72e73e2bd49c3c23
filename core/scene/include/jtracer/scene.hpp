#pragma once
// The scene model: what a .jts file means, as plain values.
//
// A Scene is a value: copy it, compare it with ==, serialise it (serializer.hpp).
// It holds no source positions; where each part came from lives beside it in a
// SceneSource (source_map.hpp), so that two files that mean the same scene
// compare equal. Every default below is the one docs/language.md §4 gives;
// schema.hpp lists each property with its kind and range.

#include <glm/vec3.hpp>

#include "jtracer/boxed.hpp"
#include "jtracer/shared.hpp"

#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace jt {

using Vec3 = glm::dvec3;
using Colour = glm::dvec3;  // linear RGB, each channel in [0, 1] after parsing

// Whether every component is a number (neither NaN nor infinite).
inline bool all_finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

struct RenderSettings {
    int width = 0;
    int height = 0;
    int recurse_depth = 0;
    std::string filename = "jtracer.bmp";
    std::string active_camera;  // empty: the first camera
    Colour background{0.0};
    Colour ambient_light{0.0};
    int samples = 1;  // extension: rays per pixel, kMinSamples..kMaxSamples (limits.hpp)
    // Extension (docs/language.md §14.3): an equirectangular image every ray
    // that meets nothing returns; "": the background colour.
    std::string background_map;

    bool operator==(const RenderSettings&) const = default;
};

struct Camera {
    std::string name;
    Vec3 position{0.0};
    Vec3 look_at{0.0, 0.0, -1.0};  // a point, not a direction
    Vec3 up{0.0, 1.0, 0.0};
    double aspect = 1.0;
    double fov = 45.0;  // vertical, degrees
    // Extensions (docs/language.md §14.2): a lens of this radius, focused at
    // this distance along the view direction; unset: |look_at - position|.
    double aperture = 0.0;
    std::optional<double> focus_distance;

    bool operator==(const Camera&) const = default;
};

// Everything a material says but its base colour. The split follows what
// scenes vary: a pigment differs from object to object, while the finish
// (how light meets the surface, and the patterns laid on it) is most often
// the same for thousands of objects. So a material holds its pigment inline
// and its finish shared (shared.hpp): a million spheres of one finish hold
// it once, and a primitive stays small.
struct Finish {
    Colour ambient{0.0};
    Colour diffuse{0.0};
    Colour specular{0.0};
    double diffuse_k = 1.0;
    double specular_k = 64.0;
    double reflection = 0.0;
    // Extensions (docs/language.md §13): refraction and patterns.
    double transmission = 0.0;
    double ior = 1.0;               // index of refraction of the inside
    std::optional<Colour> checker;  // the second colour of a solid checker; none: no checker
    double checker_size = 1.0;      // edge of one checker cube, object units
    std::string image_map;          // PNG, JPEG or BMP, relative to Scene::asset_folder; "": none
    double map_size = 1.0;          // size of one tile of a planar map

    bool operator==(const Finish&) const = default;
};

// Read a finish property with material.finish->ambient; set one with
// material.finish.edit().ambient = ..., which copies a shared finish first.
struct Material {
    Colour pigment{0.0};
    Shared<Finish> finish;

    bool operator==(const Material&) const = default;
};

enum class TransformKind { translate, scale, xrotate, yrotate, zrotate };

// One operation of a transform block. translate/scale use `vector`,
// the rotations use `degrees`.
struct TransformOp {
    TransformKind kind = TransformKind::translate;
    Vec3 vector{0.0};
    double degrees = 0.0;

    bool operator==(const TransformOp&) const = default;
};

struct Sphere {
    Vec3 center{0.0};
    double radius = 1.0;
    bool operator==(const Sphere&) const = default;
};

// The plane { p : p . normalize(normal) = distance }.
struct Plane {
    Vec3 normal{0.0, 1.0, 0.0};
    double distance = 0.0;
    bool operator==(const Plane&) const = default;
};

// Solid cylinder x^2 + z^2 <= radius^2, 0 <= y <= height, closed by both caps.
struct Cylinder {
    double radius = 0.5;
    double height = 1.0;
    bool operator==(const Cylinder&) const = default;
};

// Extensions (docs/language.md §13.5): a triangle, counter-clockwise seen
// from the front, and every triangle of a model file.
struct Triangle {
    Vec3 a{0.0, 0.0, 0.0};
    Vec3 b{1.0, 0.0, 0.0};
    Vec3 c{0.0, 1.0, 0.0};
    // Texture coordinates of the corners (x and y used, z ignored).
    Vec3 uv_a{0.0, 0.0, 0.0};
    Vec3 uv_b{1.0, 0.0, 0.0};
    Vec3 uv_c{0.0, 1.0, 0.0};
    bool operator==(const Triangle&) const = default;
};

inline constexpr std::string_view kSmoothShading = "smooth";
inline constexpr std::string_view kFlatShading = "flat";

inline constexpr std::string_view kSceneMaterials = "scene";
inline constexpr std::string_view kFileMaterials = "file";

struct Mesh {
    std::string file;  // relative to Scene::asset_folder; required
    std::string shading{kSmoothShading};
    // Extensions (docs/language.md §14.4, §14.5): corners without a normal in
    // the file get one from the faces around them within this angle (degrees);
    // "file" takes each part's colour and texture from the model file.
    std::optional<double> smooth_angle;
    std::string materials{kSceneMaterials};
    bool operator==(const Mesh&) const = default;
};

// Triangles and meshes are boxed so that a shape takes 40 bytes, not the 152
// a triangle's corners and texture coordinates would give every sphere.
using Shape = std::variant<Sphere, Plane, Cylinder, Boxed<Triangle>, Boxed<Mesh>>;

namespace shape_detail {
template <class T>
struct Stored {
    using type = T;
};
template <>
struct Stored<Triangle> {
    using type = Boxed<Triangle>;
};
template <>
struct Stored<Mesh> {
    using type = Boxed<Mesh>;
};
template <class T>
struct Unboxed {
    using type = T;
};
template <class T>
struct Unboxed<Boxed<T>> {
    using type = T;
};
template <class T>
constexpr const T& unbox(const T& shape) {
    return shape;
}
template <class T>
constexpr T& unbox(T& shape) {
    return shape;
}
template <class T>
constexpr const T& unbox(const Boxed<T>& shape) {
    return *shape;
}
template <class T>
constexpr T& unbox(Boxed<T>& shape) {
    return *shape;
}
}  // namespace shape_detail

// The I-th kind of shape, as callers name it (Triangle, not Boxed<Triangle>).
template <std::size_t I>
using ShapeAlternative = typename shape_detail::Unboxed<std::variant_alternative_t<I, Shape>>::type;

// std::get_if, std::get, std::holds_alternative and std::visit for a Shape,
// seeing through the boxes: callers name Triangle, never Boxed<Triangle>.
template <class T>
const T* shape_if(const Shape* shape) {
    const auto* stored = std::get_if<typename shape_detail::Stored<T>::type>(shape);
    return stored != nullptr ? &shape_detail::unbox(*stored) : nullptr;
}
template <class T>
T* shape_if(Shape* shape) {
    auto* stored = std::get_if<typename shape_detail::Stored<T>::type>(shape);
    return stored != nullptr ? &shape_detail::unbox(*stored) : nullptr;
}
template <class T>
const T& shape_as(const Shape& shape) {
    return shape_detail::unbox(std::get<typename shape_detail::Stored<T>::type>(shape));
}
template <class T>
T& shape_as(Shape& shape) {
    return shape_detail::unbox(std::get<typename shape_detail::Stored<T>::type>(shape));
}
template <class T>
bool shape_is(const Shape& shape) {
    return std::holds_alternative<typename shape_detail::Stored<T>::type>(shape);
}
template <class Visitor>
constexpr decltype(auto) visit_shape(Visitor&& visitor, const Shape& shape) {
    return std::visit(
        [&](const auto& s) -> decltype(auto) { return visitor(shape_detail::unbox(s)); }, shape);
}
template <class Visitor>
constexpr decltype(auto) visit_shape(Visitor&& visitor, Shape& shape) {
    return std::visit([&](auto& s) -> decltype(auto) { return visitor(shape_detail::unbox(s)); },
                      shape);
}

struct Primitive {
    Shape shape;
    Material material;
    // Applied in the order written: the first op acts on the shape first.
    std::vector<TransformOp> transforms;

    bool operator==(const Primitive&) const = default;
};

struct PointLight {
    Vec3 position{0.0};
    Colour intensity{0.0};
    // Extension (docs/language.md §14.1): a sphere of light of this radius
    // casting soft shadows, its visibility taken at shadow_samples points.
    double radius = 0.0;
    int shadow_samples = 16;
    bool operator==(const PointLight&) const = default;
};

struct Scene {
    RenderSettings settings;
    std::vector<Camera> cameras;
    std::vector<Primitive> primitives;
    std::vector<PointLight> lights;
    // Where the relative file names it holds (image_map, mesh files) are found: the folder
    // of the .jts file (load_scene_file sets it); empty: the current directory.
    std::string asset_folder;

    // What the scene means: two texts that say the same compare equal
    // wherever they lie, so asset_folder is left out.
    bool operator==(const Scene& other) const {
        return settings == other.settings && cameras == other.cameras &&
               primitives == other.primitives && lights == other.lights;
    }
};

}  // namespace jt
