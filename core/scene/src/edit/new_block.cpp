#include "jtracer/new_block.hpp"

#include "jtracer/camera_edit.hpp"
#include "jtracer/primitive_bounds.hpp"
#include "jtracer/schema.hpp"
#include "jtracer/validate.hpp"
#include "jtracer/value_text.hpp"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace jt {

namespace {

// Where the active camera looks, and how big things look there.
struct View {
    Vec3 eye{0.0};
    Vec3 forward{0.0, 0.0, -1.0};
    Vec3 up{0.0, 1.0, 0.0};   // at right angles to forward
    Vec3 sky{0.0, 1.0, 0.0};  // the camera's own up, of unit length: the scene's vertical
    double distance = 5.0;    // to the look_at point
    double fov = 45.0;
    // Half the height the view spans at `at` from the eye.
    double half_height(double at) const { return at * std::tan(glm::radians(fov) / 2.0); }
};

View active_view(const Scene& scene) {
    View view;
    const int index = active_camera_index(scene);
    if (index < 0) return view;
    const Camera& camera = scene.cameras[static_cast<std::size_t>(index)];
    const Vec3 to = camera.look_at - camera.position;
    const double distance = glm::length(to);
    view.eye = camera.position;
    if (std::isfinite(distance) && distance > 0.0) {
        view.forward = to / distance;
        view.distance = distance;
    }
    if (camera.fov > 0.0 && camera.fov < 180.0) view.fov = camera.fov;
    const Vec3 right = glm::cross(view.forward, camera.up);
    const double right_length = glm::length(right);
    if (std::isfinite(right_length) && right_length > 1e-12) {
        view.up = glm::cross(right / right_length, view.forward);
        view.sky = glm::normalize(camera.up);
    }
    return view;
}

}  // namespace

std::string_view keyword_of(ShapeKind kind) {
    switch (kind) {
        case ShapeKind::sphere:
            return schema_of<Sphere>().keyword;
        case ShapeKind::plane:
            return schema_of<Plane>().keyword;
        case ShapeKind::cylinder:
            return schema_of<Cylinder>().keyword;
        case ShapeKind::triangle:
            return schema_of<Triangle>().keyword;
    }
    return schema_of<Sphere>().keyword;
}

Material new_material() {
    Finish finish;
    finish.ambient = Colour{0.2};
    finish.diffuse = Colour{0.8};
    finish.specular = Colour{0.3};
    finish.specular_k = 32.0;
    return Material{.pigment = Colour{0.8}, .finish = finish};
}

namespace {

// Where a new object goes, and how big it is: the point halfway along the
// view, and half the view's height there.
struct Placement {
    Vec3 at{0.0};
    double half = 1.0;
};

Placement placement(const View& view) {
    const double along = view.distance / 2.0;
    const double half = view.half_height(along);
    return {rounded_to_scale(view.eye + view.forward * along, half), half};
}

// Where a new plane lies along the unit `n`: the height of the view's floor,
// below the point the camera looks at by the camera's own height above it
// (new_scene's camera, 1 above that point, gets a floor at 0) but by no more
// than a third of the view's half-height there, so that the floor is seen; and
// under every object whose extent is known, so that they stand on it.
double floor_height(const Scene& scene, const View& view, const Vec3& n) {
    const Vec3 look_at = view.eye + view.forward * view.distance;
    const double centre = glm::dot(n, look_at), eye = glm::dot(n, view.eye);
    double drop = view.half_height(view.distance) / 3.0;
    if (eye > centre) drop = std::min(drop, eye - centre);
    double floor = centre - drop;
    for (const Primitive& p : scene.primitives)
        if (const std::optional<Bounds> box = primitive_bounds(p)) {
            double lowest = 0.0;
            for (int axis = 0; axis < 3; ++axis)
                lowest += std::min(n[axis] * box->lower[axis], n[axis] * box->upper[axis]);
            floor = std::min(floor, lowest);
        }
    return floor;
}

}  // namespace

Primitive new_primitive(ShapeKind kind, const Scene& scene) {
    const View view = active_view(scene);
    const auto [at, half] = placement(view);
    Primitive p;
    p.material = new_material();
    switch (kind) {
        case ShapeKind::sphere:
            p.shape = Sphere{at, rounded_to_scale(half / 5.0, half)};
            break;
        case ShapeKind::plane: {
            // Level with the scene's vertical, not tilted with a camera that looks down.
            const Vec3 normal = rounded_to_scale(view.sky, 1.0);
            p.shape = Plane{
                normal, rounded_to_scale(floor_height(scene, view, glm::normalize(normal)), half)};
            break;
        }
        case ShapeKind::cylinder: {
            const Cylinder c{rounded_to_scale(half / 5.0, half),
                             rounded_to_scale(half / 2.0, half)};
            p.shape = c;
            p.transforms.push_back({TransformKind::translate,
                                    rounded_to_scale(at - Vec3{0.0, c.height / 2.0, 0.0}, half),
                                    0.0});
            break;
        }
        case ShapeKind::triangle: {
            const double r = half / 5.0;
            const Vec3 right = glm::cross(view.forward, view.up);
            Triangle t;
            t.a = rounded_to_scale(at - right * r - view.up * (r / 2.0), half);
            t.b = rounded_to_scale(at + right * r - view.up * (r / 2.0), half);
            t.c = rounded_to_scale(at + view.up * r, half);
            p.shape = t;
            break;
        }
    }
    return p;
}

Primitive new_mesh(const Scene& scene, const std::string& file, const Model& model) {
    const auto [at, half] = placement(active_view(scene));
    const ModelBox box = model_box(model);
    Primitive p;
    p.material = new_material();
    Mesh mesh;
    mesh.file = file;
    p.shape = mesh;
    if (box.empty()) return p;
    const Vec3 low = box.lower, high = box.upper;
    const Vec3 extent = high - low;
    const double largest = std::max({extent.x, extent.y, extent.z});
    const double diameter = 2.0 * half / 5.0;
    const double s = largest > 0.0 ? rounded_to_scale(diameter / largest, diameter / largest) : 1.0;
    if (s != 1.0) p.transforms.push_back({TransformKind::scale, Vec3(s), 0.0});
    p.transforms.push_back(
        {TransformKind::translate, rounded_to_scale(at - (low + high) * (s / 2.0), half), 0.0});
    return p;
}

PointLight new_light(const Scene& scene) {
    const View view = active_view(scene);
    const double half = view.half_height(view.distance);
    return {rounded_to_scale(view.eye + view.up * half, half), Colour{0.7}};
}

Camera new_camera(const Scene& scene) {
    const int index = active_camera_index(scene);
    Camera camera = index < 0 ? Camera{} : scene.cameras[static_cast<std::size_t>(index)];
    camera.name = unique_camera_name(scene, camera.name.empty() ? "camera" : camera.name);
    return camera;
}

Scene new_scene() {
    Scene scene;
    scene.settings.width = 640;
    scene.settings.height = 360;
    scene.settings.recurse_depth = 5;
    scene.settings.filename = "scene.bmp";
    scene.settings.background = Colour(0.05, 0.06, 0.09);
    scene.settings.ambient_light = Colour(0.2);
    Camera camera;
    camera.name = "main";
    camera.position = Vec3(0.0, 2.0, 8.0);
    camera.look_at = Vec3(0.0, 1.0, 0.0);
    camera.aspect = static_cast<double>(scene.settings.width) / scene.settings.height;
    scene.cameras.push_back(camera);
    PointLight light;
    light.position = Vec3(-4.0, 6.0, 6.0);
    light.intensity = Colour(1.0);
    scene.lights.push_back(light);
    return scene;
}

}  // namespace jt
