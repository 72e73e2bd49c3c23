#include "render/triangle_geometry.hpp"

#include "geometry/bounds.hpp"
#include "jtracer/model_cache.hpp"
#include "jtracer/texture.hpp"
#include "render/embree_device.hpp"
#include "render/far_ray.hpp"
#include "render/triangle_queries.hpp"
#include "render/user_geometry.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace jt {

TriangleModel::~TriangleModel() {
    if (scene) rtcReleaseScene(scene);
    for (const auto& [exponent, copy] : shrunk) rtcReleaseScene(copy);
}

TriangleGeometry::~TriangleGeometry() {
    if (scene) rtcReleaseScene(scene);
}

namespace {

// Past this many triangles, a faster build pays off more than a better tree.
constexpr std::size_t fast_build_triangles = 4000000;

RTCGeometry new_triangle_geometry(std::size_t vertices, std::size_t triangles) {
    RTCGeometry g = rtcNewGeometry(embree_device(), RTC_GEOMETRY_TYPE_TRIANGLE);
    // Embree reads vertices 16 bytes at a time: its own buffer is padded.
    rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                            vertices);
    rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                            3 * sizeof(std::uint32_t), triangles);
    rtcSetGeometryIntersectFilterFunction(g, triangle_intersect_filter);
    rtcSetGeometryOccludedFilterFunction(g, triangle_occluded_filter);
    return g;
}

RTCScene new_robust_scene(std::size_t triangles) {
    RTCScene scene = rtcNewScene(embree_device());
    // Robust traversal: a ray through a shared edge or vertex never slips
    // between the triangles that share it.
    rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(
        scene, triangles > fast_build_triangles ? RTC_BUILD_QUALITY_LOW : RTC_BUILD_QUALITY_MEDIUM);
    return scene;
}

// The BVH of `model`'s triangles with every corner coordinate times 2^-e
// (exact in float unless it underflows).
RTCScene corner_scene(const Model& model, int e) {
    RTCScene scene = new_robust_scene(model.triangles.size());
    RTCGeometry g = new_triangle_geometry(model.positions.size(), model.triangles.size());
    auto* v = static_cast<float*>(rtcGetGeometryBufferData(g, RTC_BUFFER_TYPE_VERTEX, 0));
    for (const glm::vec3& p : model.positions) {
        *v++ = std::ldexp(p.x, -e);
        *v++ = std::ldexp(p.y, -e);
        *v++ = std::ldexp(p.z, -e);
    }
    auto* i = static_cast<std::uint32_t*>(rtcGetGeometryBufferData(g, RTC_BUFFER_TYPE_INDEX, 0));
    for (const auto& t : model.triangles) {
        *i++ = t[0];
        *i++ = t[1];
        *i++ = t[2];
    }
    rtcCommitGeometry(g);
    rtcAttachGeometry(scene, g);
    rtcReleaseGeometry(g);
    rtcCommitScene(scene);
    return scene;
}

std::unique_ptr<TriangleModel> model_scene(std::shared_ptr<const Model> model) {
    auto m = std::make_unique<TriangleModel>();
    m->scene = corner_scene(*model, 0);
    if (!model->positions.empty()) m->lower = m->upper = Vec3(model->positions[0]);
    for (const glm::vec3& p : model->positions) {
        m->extent = std::max(
            {m->extent, double(std::abs(p.x)), double(std::abs(p.y)), double(std::abs(p.z))});
        m->lower = glm::min(m->lower, Vec3(p));
        m->upper = glm::max(m->upper, Vec3(p));
    }
    m->model = std::move(model);
    return m;
}

// Embree moves a ray into a mesh's space by the inverse of the float map it
// is given, and Debian's build aborts (assertion `ray.valid()`) when a
// component of the moved origin or direction passes 1.8e18. A mesh shrunk by
// 1e-10 seen from 1e9 away, or by 1e-20 from anywhere, got there. So a map
// whose inverse has a row sum above kMaxPlainInverse (a shrink past about
// 6e-8) goes to Embree as M * 2^e with the model's corners times 2^-e, e
// chosen so that the inverse's row sums fall below 1: the same world
// triangles, and moved rays no longer than the world's. Below it, rays that
// start within 1e11 of the mesh stay in range. Powers of two scale floats
// exactly, and hits are worked out again in double precision from the model
// itself; meshes shrunk less keep the shared BVH and their images' bytes.
constexpr double kMaxPlainInverse = 1 << 24;

// The largest row sum of |m|: the norm that bounds how much m can lengthen a vector.
double largest_row_sum(const glm::dmat3& m) {
    double largest_row = 0.0;
    for (int r = 0; r < 3; ++r) {
        double row = 0.0;
        for (int c = 0; c < 3; ++c) row += std::abs(m[c][r]);
        largest_row = std::max(largest_row, row);
    }
    return largest_row;
}

int shrink_exponent(const ObjectTransform& transform) {
    const double largest_row = largest_row_sum(transform.to_object.linear);
    if (!(largest_row > kMaxPlainInverse)) return 0;
    return std::ilogb(largest_row) + 1;
}

// Embree moves a ray into an instance's space in single precision by the
// float inverse of its map, and the rounding grows with the map's condition
// number: a tetrahedron stretched 600 times more along one axis than another
// (a random scene's) moved a reflected ray by 3e-5 of its size, and the ray,
// which passes 3e-6 inside a corner of the solid, missed both faces there.
// Past this condition number (the product of the map's and its inverse's
// largest row sums), a mesh is walked on its own, its rays moved into its
// space in double precision (FarInstance), where the float rounding is that
// of the model's own coordinates. Each such mesh costs every ray a box test
// and, when it passes, a walk of its own; below the limit (a plank scaled
// 20 times longer than it is thick) meshes keep Embree's instancing, and the
// rounding it adds stays within about 64 float steps.
constexpr double kMaxInstanceCondition = 64.0;

bool ill_conditioned(const ObjectTransform& transform) {
    return !(largest_row_sum(transform.to_world.linear) *
                 largest_row_sum(transform.to_object.linear) <=
             kMaxInstanceCondition);
}

// The BVH of the model's corners times 2^-e, made once.
RTCScene scaled_corners(TriangleModel& model, int e) {
    if (e == 0) return model.scene;
    auto known = model.shrunk.find(e);
    if (known == model.shrunk.end())
        known = model.shrunk.emplace(e, corner_scene(*model.model, e)).first;
    return known->second;
}

// The exponent e that brings the model's corners times 2^-e below 2^50, well
// within Embree's reach; 0 when they are within it already.
int reach_exponent(const TriangleModel& model) {
    return model.extent > embree_reach ? std::ilogb(model.extent) - 49 : 0;
}

// Whether some corner of the mesh may lie past Embree's reach, in the corners
// its instance names (the model's times 2^-shrink) or in the world: each
// world coordinate is bounded by the translation's plus the map's row of
// magnitudes times the model's extent.
bool beyond_reach(const TriangleModel& model, const ObjectTransform& transform, int shrink) {
    if (!(std::ldexp(model.extent, -shrink) <= embree_reach)) return true;
    for (int r = 0; r < 3; ++r) {
        double reach = std::abs(transform.to_world.translation[r]);
        for (int c = 0; c < 3; ++c)
            reach += std::abs(transform.to_world.linear[c][r]) * model.extent;
        if (!(reach <= embree_reach)) return true;
    }
    return false;
}

// The box FarInstance::lower and upper describe: the model's box through the
// map, padded as render/listed_shapes.hpp pads bounds; unbounded when any of
// it is not finite.
void bound_far_instance(FarInstance& far, const TriangleModel& model,
                        const ObjectTransform& transform) {
    Vec3 lower(std::numeric_limits<double>::infinity()), upper(-lower);
    for (int k = 0; k < 8; ++k) {
        const Vec3 corner((k & 1) ? model.upper.x : model.lower.x,
                          (k & 2) ? model.upper.y : model.lower.y,
                          (k & 4) ? model.upper.z : model.lower.z);
        const Vec3 p = apply_point(transform.to_world, corner);
        lower = glm::min(lower, p);
        upper = glm::max(upper, p);
    }
    if (!all_finite(lower) || !all_finite(upper)) return;
    const double largest = std::max({std::abs(lower.x), std::abs(lower.y), std::abs(lower.z),
                                     std::abs(upper.x), std::abs(upper.y), std::abs(upper.z)});
    const Vec3 pad = 1e-6 * (upper - lower) + Vec3(1e-7 * largest);
    far.lower = lower - pad;
    far.upper = upper + pad;
}

// A mesh walked on its own (FarInstance) keeps its instance, disabled, so that
// instance ids stay the indices of TriangleGeometry::instances; rays meet it
// through TriangleGeometry::far_instances instead.
void attach_instance(RTCScene top, TriangleModel& model, const ObjectTransform& transform,
                     bool enabled) {
    RTCGeometry g = rtcNewGeometry(embree_device(), RTC_GEOMETRY_TYPE_INSTANCE);
    const int e = shrink_exponent(transform);
    rtcSetGeometryInstancedScene(g, scaled_corners(model, e));
    float xfm[12];  // 3x4, column-major: the linear part's columns, then the translation
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            xfm[3 * c + r] = static_cast<float>(std::ldexp(transform.to_world.linear[c][r], e));
    for (int r = 0; r < 3; ++r) xfm[9 + r] = static_cast<float>(transform.to_world.translation[r]);
    rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm);
    if (!enabled) rtcDisableGeometry(g);
    rtcCommitGeometry(g);
    rtcAttachGeometry(top, g);
    rtcReleaseGeometry(g);
}

// A mesh walked on its own (FarInstance), with the model's corners it walks.
FarInstance walked_instance(std::uint32_t instance, TriangleModel& model,
                            const ObjectTransform& transform) {
    FarInstance walked;
    walked.instance = instance;
    walked.exponent = reach_exponent(model);
    walked.corners = scaled_corners(model, walked.exponent);
    rtcGetSceneBounds(walked.corners, &walked.corners_bounds);
    bound_far_instance(walked, model, transform);
    return walked;
}

// Attaches every instance to t.scene, in order, so that its geometry id is
// its index; the ones walked on their own (far or boxed) disabled.
void attach_instances(TriangleGeometry& t, const std::vector<ObjectTransform>& transforms) {
    std::vector<bool> far(t.instances.size());
    std::size_t shared_bvh = 0;
    for (std::size_t k = 0; k < t.instances.size(); ++k) {
        const TriangleModel& model = *t.models[t.instances[k].model];
        far[k] = beyond_reach(model, transforms[k], shrink_exponent(transforms[k])) ||
                 ill_conditioned(transforms[k]);
        shared_bvh += far[k] ? 0 : 1;
    }
    const bool boxed = shared_bvh > 1 || (shared_bvh == 1 && !t.loose.empty());
    for (std::size_t k = 0; k < t.instances.size(); ++k) {
        TriangleModel& model = *t.models[t.instances[k].model];
        attach_instance(t.scene, model, transforms[k], !far[k] && !boxed);
        if (!far[k] && !boxed) continue;
        const FarInstance walked =
            walked_instance(static_cast<std::uint32_t>(k), model, transforms[k]);
        (far[k] ? t.far_instances : t.boxed_instances).push_back(walked);
    }
}

// The world box of boxed instance `primID` (TriangleGeometry::boxed_instances).
void boxed_instance_bounds(const RTCBoundsFunctionArguments* args) {
    const auto& t = *static_cast<const TriangleGeometry*>(args->geometryUserPtr);
    const FarInstance& mesh = t.boxed_instances[args->primID];
    *args->bounds_o = padded_float_bounds(Box{mesh.lower, mesh.upper}, 0.0);
}

void attach_loose(TriangleGeometry& t) {
    RTCGeometry g = new_triangle_geometry(3 * t.loose.size(), t.loose.size());
    auto* v = static_cast<float*>(rtcGetGeometryBufferData(g, RTC_BUFFER_TYPE_VERTEX, 0));
    auto* i = static_cast<std::uint32_t*>(rtcGetGeometryBufferData(g, RTC_BUFFER_TYPE_INDEX, 0));
    std::uint32_t next = 0;
    for (std::uint32_t k = 0; k < t.loose.size(); ++k) {
        const LooseTriangle& triangle = t.loose[k];
        const bool far = !within_reach(triangle.corners[0]) || !within_reach(triangle.corners[1]) ||
                         !within_reach(triangle.corners[2]);
        // Embree's BVH leaves such a triangle out; it stands here as a point,
        // which Embree's test never meets, and is tested exactly instead.
        if (far) t.far_loose.push_back(k);
        for (const Vec3& corner : triangle.corners) {
            const Vec3 p = far ? Vec3(0.0) : corner;
            *v++ = static_cast<float>(p.x);
            *v++ = static_cast<float>(p.y);
            *v++ = static_cast<float>(p.z);
            *i++ = next++;
        }
    }
    rtcCommitGeometry(g);
    rtcAttachGeometry(t.scene, g);
    rtcReleaseGeometry(g);
}

// The corner normals of `model` at smooth_angle `degrees`, made once for all
// the meshes that use them; null when the file gives every corner a normal,
// so those meshes keep language 1.1's path.
Expected<const CornerNormals*> generated_normals(TriangleModel& model, double degrees) {
    if (corners_without_normals(*model.model) == 0) return nullptr;
    auto known = model.generated.find(degrees);
    if (known == model.generated.end()) {
        auto normals = shared_corner_normals(model.model, degrees);
        if (!normals) return normals.error();
        known = model.generated.emplace(degrees, std::move(*normals)).first;
    }
    return known->second.get();
}

}  // namespace

Expected<std::unique_ptr<TriangleGeometry>> build_triangle_geometry(const Scene& scene) {
    std::unique_ptr<TriangleGeometry> t;
    // A file read with its materials is another model than the file without.
    std::map<std::pair<std::string, bool>, std::uint32_t> model_of_file;
    std::vector<ObjectTransform> transforms;  // of each instance
    for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
        const Primitive& p = scene.primitives[i];
        const auto* triangle = shape_if<Triangle>(&p.shape);
        const auto* mesh = shape_if<Mesh>(&p.shape);
        if (!triangle && !mesh) continue;
        ObjectTransform transform;
        if (!p.transforms.empty()) {
            auto placed = object_transform(p.transforms);
            if (std::holds_alternative<LeftOut>(placed)) continue;
            transform = std::get<ObjectTransform>(placed);
        }
        if (!t) {
            t = std::make_unique<TriangleGeometry>();
            t->scene = new_robust_scene(0);
        }
        const auto source = static_cast<std::uint32_t>(i);
        if (triangle) {
            LooseTriangle loose;
            loose.corners = {apply_point(transform.to_world, triangle->a),
                             apply_point(transform.to_world, triangle->b),
                             apply_point(transform.to_world, triangle->c)};
            loose.uvs = {glm::dvec2(triangle->uv_a), glm::dvec2(triangle->uv_b),
                         glm::dvec2(triangle->uv_c)};
            loose.source = source;
            loose.mirrored = transform.mirrors;
            const auto& c = loose.corners;
            // Zero area in its own space or in the world's: left out (the validator warned).
            if (glm::cross(triangle->b - triangle->a, triangle->c - triangle->a) == Vec3(0.0) ||
                !all_finite(c[0]) || !all_finite(c[1]) || !all_finite(c[2]) ||
                glm::cross(c[1] - c[0], c[2] - c[0]) == Vec3(0.0))
                continue;
            t->loose.push_back(loose);
            continue;
        }
        const std::string path = asset_path(scene, mesh->file).string();
        const bool file_materials = mesh->materials == kFileMaterials;
        auto known = model_of_file.find({path, file_materials});
        if (known == model_of_file.end()) {
            auto model = shared_model(path, scene.asset_folder, file_materials);
            if (!model) return Error{"mesh: " + model.error().message};
            if ((*model)->triangles.empty()) continue;
            t->models.push_back(model_scene(*model));
            known =
                model_of_file.emplace(std::pair(path, file_materials), t->models.size() - 1).first;
        }
        MeshInstance instance;
        instance.model = known->second;
        if (mesh->smooth_angle && mesh->shading == kSmoothShading) {
            auto normals = generated_normals(*t->models[known->second], *mesh->smooth_angle);
            if (!normals) return Error{"mesh: '" + mesh->file + "': " + normals.error().message};
            instance.corner_normals = *normals;
        }
        instance.to_object = transform.to_object;
        instance.normal_matrix = transform.normal_matrix;
        instance.smooth = mesh->shading == kSmoothShading;
        instance.file_materials = file_materials;
        t->file_materials = t->file_materials || file_materials;
        instance.source = source;
        t->instances.push_back(instance);
        transforms.push_back(transform);
    }
    if (!t) return std::unique_ptr<TriangleGeometry>();
    attach_instances(*t, transforms);
    if (!t->loose.empty()) attach_loose(*t);
    if (!t->boxed_instances.empty())
        attach_user_geometry(t->scene, t.get(), t->boxed_instances.size(), RTC_BUILD_QUALITY_MEDIUM,
                             boxed_instance_bounds, boxed_instance_intersect,
                             boxed_instance_occluded);
    rtcCommitScene(t->scene);
    rtcGetSceneBounds(t->scene, &t->bounds);
    return t;
}

}  // namespace jt
