// kernel-limit: how fast Embree's own native geometry traces the rays JTracer
// traces for a scene, with no shading: the limit of the ray kernel on this
// machine, against which bench/kernel_limit.py sets JTracer's rays per second.
//
// The scene is read with the core's parser; spheres become float
// RTC_GEOMETRY_TYPE_SPHERE_POINT, cylinders RTC_GEOMETRY_TYPE_ROUND_LINEAR_CURVE
// segments (Embree's nearest native shape; round instead of flat ends), planes
// two large triangles each. The rays are JTracer's (docs/language.md §7, §8):
// one primary ray through every pixel centre, at every hit one shadow ray to
// each light in front of the surface with a non-zero intensity, and a mirror
// ray while the material reflects and the depth is below recurse_depth. Rays
// are counted as the CLI counts them. Modes: one ray at a time (rtcIntersect1,
// rtcOccluded1) and packets of 8 and 16 (the primary rays of 4x2 and 4x4 pixel
// blocks; the shadow and mirror rays of the same lanes).
//
// usage: kernel-limit SCENE.jts [--threads N] [--runs N]
// prints, per mode, the median over the runs: rays, seconds, Mrays/s.

#include "converter_cli.hpp"
#include "jtracer/validate.hpp"
#include "render/camera_rays.hpp"
#include "render/embree_device.hpp"
#include "world_shapes.hpp"

#include <embree3/rtcore.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

namespace {

using jt::Vec3;

constexpr int tile_size = 16;  // pixels a side; threads take tiles in turn

// What the rays need: the BVH, each hit's reflection, the lights, the camera.
struct KernelScene {
    RTCScene bvh = nullptr;
    std::vector<std::vector<double>> reflection;  // [geometry id][primitive id]
    std::vector<Vec3> lights;                     // those with a non-zero intensity
    jt::CameraFrame camera;
    int depth_limit = 0;
};

double max_abs(const Vec3& v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

unsigned attach(RTCScene bvh, RTCGeometry g) {
    rtcCommitGeometry(g);
    unsigned id = rtcAttachGeometry(bvh, g);
    rtcReleaseGeometry(g);
    return id;
}

void set_reflection(KernelScene& k, unsigned id, std::vector<double> values) {
    if (k.reflection.size() <= id) k.reflection.resize(id + 1);
    k.reflection[id] = std::move(values);
}

KernelScene build(RTCDevice device, const jt::Scene& scene) {
    const jt::bench::WorldShapes shapes = jt::bench::world_shapes(scene);
    KernelScene k;
    k.bvh = rtcNewScene(device);
    auto reflection_of = [&](std::size_t primitive) {
        return scene.primitives[primitive].material.finish->reflection;
    };
    double extent = 1.0;
    if (!shapes.spheres.empty()) {
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0,
                                                              RTC_FORMAT_FLOAT4, 4 * sizeof(float),
                                                              shapes.spheres.size()));
        std::vector<double> reflections;
        for (const jt::bench::WorldSphere& s : shapes.spheres) {
            *v++ = float(s.center.x), *v++ = float(s.center.y), *v++ = float(s.center.z);
            *v++ = float(s.radius);
            reflections.push_back(reflection_of(s.primitive));
            extent = std::max(extent, max_abs(s.center) + s.radius);
        }
        set_reflection(k, attach(k.bvh, g), std::move(reflections));
    }
    if (!shapes.cylinders.empty()) {
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_ROUND_LINEAR_CURVE);
        const std::size_t n = shapes.cylinders.size();
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), 2 * n));
        auto* index = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT, sizeof(unsigned), n));
        std::vector<double> reflections;
        for (std::size_t i = 0; i < n; ++i) {
            const jt::bench::WorldCylinder& c = shapes.cylinders[i];
            for (const Vec3& end : {c.base, c.apex}) {
                *v++ = float(end.x), *v++ = float(end.y), *v++ = float(end.z);
                *v++ = float(c.radius);
                extent = std::max(extent, max_abs(end) + c.radius);
            }
            index[i] = unsigned(2 * i);
            reflections.push_back(reflection_of(c.primitive));
        }
        set_reflection(k, attach(k.bvh, g), std::move(reflections));
    }
    if (!shapes.planes.empty()) {
        // A square this much wider than the scene, about the point nearest the
        // origin, looks infinite from any camera inside the scene.
        const double half = 1000.0 * extent;
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        const std::size_t n = shapes.planes.size();
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 4 * n));
        auto* index = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), 2 * n));
        std::vector<double> reflections;
        for (std::size_t i = 0; i < n; ++i) {
            const jt::bench::WorldPlane& p = shapes.planes[i];
            const Vec3 helper = std::abs(p.normal.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
            const Vec3 u = glm::normalize(glm::cross(p.normal, helper)) * half;
            const Vec3 w = glm::cross(p.normal, u);
            for (const Vec3& corner :
                 {p.point - u - w, p.point + u - w, p.point + u + w, p.point - u + w}) {
                *v++ = float(corner.x), *v++ = float(corner.y), *v++ = float(corner.z);
            }
            const unsigned first = unsigned(4 * i);
            for (unsigned corner : {0u, 1u, 2u, 0u, 2u, 3u}) *index++ = first + corner;
            reflections.push_back(reflection_of(p.primitive));
            reflections.push_back(reflection_of(p.primitive));
        }
        set_reflection(k, attach(k.bvh, g), std::move(reflections));
    }
    rtcCommitScene(k.bvh);
    for (const jt::PointLight& light : scene.lights)
        if (light.intensity != jt::Colour(0.0)) k.lights.push_back(light.position);
    const int camera_index = jt::active_camera_index(scene);
    if (camera_index >= 0)
        k.camera =
            jt::camera_frame(scene.cameras[std::size_t(camera_index)],
                             std::max(scene.settings.width, 1), std::max(scene.settings.height, 1));
    k.depth_limit = std::clamp(scene.settings.recurse_depth, 0, 256);
    return k;
}

// The lifted origin of a secondary ray: as JTracer's surface_offset, but in
// float, whose rounding is 1e-7 of the magnitudes rather than 1e-16.
float offset(const Vec3& origin, const Vec3& point, double t) {
    return float(std::max({max_abs(origin), max_abs(point), t}) * 1e-4);
}

// One ray at a time.
std::uint64_t trace_scalar(const KernelScene& k, Vec3 o, Vec3 d) {
    std::uint64_t rays = 0;
    RTCIntersectContext context;
    for (int depth = 0;; ++depth) {
        rtcInitIntersectContext(&context);
        RTCRayHit rh{};
        rh.ray.org_x = float(o.x), rh.ray.org_y = float(o.y), rh.ray.org_z = float(o.z);
        rh.ray.dir_x = float(d.x), rh.ray.dir_y = float(d.y), rh.ray.dir_z = float(d.z);
        rh.ray.tnear = 0.0f;
        rh.ray.tfar = std::numeric_limits<float>::infinity();
        rh.ray.mask = ~0u;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        ++rays;
        rtcIntersect1(k.bvh, &context, &rh);
        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) break;
        Vec3 point = o + double(rh.ray.tfar) * d;
        Vec3 normal = glm::normalize(Vec3(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z));
        if (glm::dot(normal, d) > 0.0) normal = -normal;
        const float lift = offset(o, point, rh.ray.tfar);
        const Vec3 lifted = point + double(lift) * normal;
        for (const Vec3& light : k.lights) {
            Vec3 to_light = light - lifted;
            double distance = glm::length(to_light);
            if (!(glm::dot(normal, to_light) > 0.0) || !(distance > 0.0)) continue;
            Vec3 l = to_light / distance;
            RTCRay shadow{};
            shadow.org_x = float(lifted.x), shadow.org_y = float(lifted.y);
            shadow.org_z = float(lifted.z);
            shadow.dir_x = float(l.x), shadow.dir_y = float(l.y), shadow.dir_z = float(l.z);
            shadow.tnear = 0.0f;
            shadow.tfar = float(distance);
            shadow.mask = ~0u;
            ++rays;
            rtcInitIntersectContext(&context);
            rtcOccluded1(k.bvh, &context, &shadow);
        }
        const double reflection = k.reflection[rh.hit.geomID][rh.hit.primID];
        if (depth >= k.depth_limit || !(reflection > 0.0)) break;
        d = glm::normalize(d - 2.0 * glm::dot(d, normal) * normal);
        o = lifted;
    }
    return rays;
}

// Embree's packet types and calls for 8 and 16 lanes.
template <int N>
struct Packet;
template <>
struct Packet<8> {
    using RayHit = RTCRayHit8;
    using Ray = RTCRay8;
    static constexpr int columns = 4;
    static void intersect(const int* valid, RTCScene s, RTCIntersectContext* c, RayHit* r) {
        rtcIntersect8(valid, s, c, r);
    }
    static void occluded(const int* valid, RTCScene s, RTCIntersectContext* c, Ray* r) {
        rtcOccluded8(valid, s, c, r);
    }
};
template <>
struct Packet<16> {
    using RayHit = RTCRayHit16;
    using Ray = RTCRay16;
    static constexpr int columns = 4;
    static void intersect(const int* valid, RTCScene s, RTCIntersectContext* c, RayHit* r) {
        rtcIntersect16(valid, s, c, r);
    }
    static void occluded(const int* valid, RTCScene s, RTCIntersectContext* c, Ray* r) {
        rtcOccluded16(valid, s, c, r);
    }
};

// The rays of one block of N pixels, lane by lane as trace_scalar, N at a time.
template <int N>
std::uint64_t trace_packet(const KernelScene& k, const Vec3 (&origin)[N], const Vec3 (&dir)[N],
                           const int (&active)[N]) {
    using P = Packet<N>;
    std::uint64_t rays = 0;
    Vec3 o[N], d[N];
    alignas(64) int valid[N];
    for (int i = 0; i < N; ++i) o[i] = origin[i], d[i] = dir[i], valid[i] = active[i];
    RTCIntersectContext context;
    for (int depth = 0;; ++depth) {
        alignas(64) typename P::RayHit rh;
        bool any = false;
        for (int i = 0; i < N; ++i) {
            rh.ray.org_x[i] = float(o[i].x), rh.ray.org_y[i] = float(o[i].y);
            rh.ray.org_z[i] = float(o[i].z);
            rh.ray.dir_x[i] = float(d[i].x), rh.ray.dir_y[i] = float(d[i].y);
            rh.ray.dir_z[i] = float(d[i].z);
            rh.ray.tnear[i] = 0.0f;
            rh.ray.tfar[i] = std::numeric_limits<float>::infinity();
            rh.ray.mask[i] = ~0u;
            rh.ray.time[i] = 0.0f;
            rh.ray.flags[i] = 0;
            rh.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
            if (valid[i]) ++rays, any = true;
        }
        if (!any) break;
        rtcInitIntersectContext(&context);
        context.flags = depth == 0 ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT
                                   : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
        P::intersect(valid, k.bvh, &context, &rh);
        Vec3 normal[N], lifted[N];
        for (int i = 0; i < N; ++i) {
            if (valid[i] && rh.hit.geomID[i] == RTC_INVALID_GEOMETRY_ID) valid[i] = 0;
            if (!valid[i]) continue;
            Vec3 point = o[i] + double(rh.ray.tfar[i]) * d[i];
            normal[i] = glm::normalize(Vec3(rh.hit.Ng_x[i], rh.hit.Ng_y[i], rh.hit.Ng_z[i]));
            if (glm::dot(normal[i], d[i]) > 0.0) normal[i] = -normal[i];
            lifted[i] = point + double(offset(o[i], point, rh.ray.tfar[i])) * normal[i];
        }
        for (const Vec3& light : k.lights) {
            alignas(64) typename P::Ray shadow;
            alignas(64) int shadow_valid[N];
            bool any_shadow = false;
            for (int i = 0; i < N; ++i) {
                // Embree may look at idle lanes too: they get an empty ray.
                shadow.org_x[i] = shadow.org_y[i] = shadow.org_z[i] = 0.0f;
                shadow.dir_x[i] = shadow.dir_y[i] = 0.0f;
                shadow.dir_z[i] = 1.0f;
                shadow.tnear[i] = shadow.tfar[i] = shadow.time[i] = 0.0f;
                shadow.mask[i] = ~0u;
                shadow.flags[i] = 0;
                shadow_valid[i] = 0;
                if (!valid[i]) continue;
                Vec3 to_light = light - lifted[i];
                double distance = glm::length(to_light);
                if (!(glm::dot(normal[i], to_light) > 0.0) || !(distance > 0.0)) continue;
                Vec3 l = to_light / distance;
                shadow.org_x[i] = float(lifted[i].x), shadow.org_y[i] = float(lifted[i].y);
                shadow.org_z[i] = float(lifted[i].z);
                shadow.dir_x[i] = float(l.x), shadow.dir_y[i] = float(l.y);
                shadow.dir_z[i] = float(l.z);
                shadow.tfar[i] = float(distance);
                shadow_valid[i] = -1;
                any_shadow = true;
                ++rays;
            }
            if (!any_shadow) continue;
            rtcInitIntersectContext(&context);
            P::occluded(shadow_valid, k.bvh, &context, &shadow);
        }
        for (int i = 0; i < N; ++i) {
            if (!valid[i]) continue;
            const double reflection = k.reflection[rh.hit.geomID[i]][rh.hit.primID[i]];
            if (depth >= k.depth_limit || !(reflection > 0.0)) {
                valid[i] = 0;
                continue;
            }
            d[i] = glm::normalize(d[i] - 2.0 * glm::dot(d[i], normal[i]) * normal[i]);
            o[i] = lifted[i];
        }
    }
    return rays;
}

// Every tile of the image on `threads` threads; the mode is 1, 8 or 16 lanes.
std::uint64_t render(const KernelScene& k, int mode, int threads) {
    const jt::CameraFrame& c = k.camera;
    const int tiles_x = (c.width + tile_size - 1) / tile_size;
    const int tiles = tiles_x * ((c.height + tile_size - 1) / tile_size);
    std::atomic<int> next{0};
    std::atomic<std::uint64_t> total{0};
    auto work = [&] {
        std::uint64_t rays = 0;
        for (int tile; (tile = next++) < tiles;) {
            const int x0 = (tile % tiles_x) * tile_size, y0 = (tile / tiles_x) * tile_size;
            const int x1 = std::min(x0 + tile_size, c.width),
                      y1 = std::min(y0 + tile_size, c.height);
            auto block = [&]<int N>(std::integral_constant<int, N>) {
                constexpr int columns = Packet<N>::columns, rows = N / columns;
                for (int by = y0; by < y1; by += rows)
                    for (int bx = x0; bx < x1; bx += columns) {
                        Vec3 o[N], d[N];
                        int active[N];
                        for (int i = 0; i < N; ++i) {
                            const int x = bx + i % columns, y = by + i / columns;
                            active[i] = x < x1 && y < y1 ? -1 : 0;
                            o[i] = c.position;
                            d[i] = jt::camera_direction(c, x + 0.5, y + 0.5);
                        }
                        rays += trace_packet<N>(k, o, d, active);
                    }
            };
            if (mode == 8) {
                block(std::integral_constant<int, 8>{});
            } else if (mode == 16) {
                block(std::integral_constant<int, 16>{});
            } else {
                for (int y = y0; y < y1; ++y)
                    for (int x = x0; x < x1; ++x)
                        rays +=
                            trace_scalar(k, c.position, jt::camera_direction(c, x + 0.5, y + 0.5));
            }
        }
        total += rays;
    };
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t) pool.emplace_back(work);
    for (std::thread& t : pool) t.join();
    return total;
}

constexpr const char* program = "kernel-limit";

}  // namespace

int main(int argc, char** argv) {
    std::string scene_path;
    int threads = 2, runs = 3;
    for (int i = 1; i < argc; ++i) {
        std::string_view a = argv[i];
        if ((a == "--threads" || a == "--runs") && i + 1 < argc) {
            (a == "--threads" ? threads : runs) = std::max(1, std::atoi(argv[++i]));
        } else if (!a.starts_with("-") && scene_path.empty()) {
            scene_path = a;
        } else {
            scene_path.clear();
            break;
        }
    }
    if (scene_path.empty()) {
        std::fprintf(stderr,
                     "usage: kernel-limit SCENE.jts [--threads N] [--runs N]\n"
                     "Traces the scene's primary, shadow and mirror rays through Embree's "
                     "native geometry, unshaded.\n");
        return jt::bench::exit_usage;
    }
    int status = 0;
    auto loaded = jt::bench::load_checked_scene(program, scene_path.c_str(), status);
    if (!loaded) return status;
    const jt::Scene& scene = loaded->parsed.scene;
    if (jt::active_camera_index(scene) < 0) {
        std::fprintf(stderr, "%s: the scene has no camera\n", program);
        return jt::bench::exit_scene_errors;
    }
    // The same configuration as the renderer's device (embree_device.hpp).
    RTCDevice device = rtcNewDevice(std::getenv(jt::kEmbreeConfigVariable));
    if (!device) {
        std::fprintf(stderr, "%s: cannot start Embree\n", program);
        return jt::bench::exit_io;
    }
    auto start = std::chrono::steady_clock::now();
    KernelScene k = build(device, scene);
    const double build_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf(
        "scene %s: build %.3f s, %d threads, native ray16: %s\n", scene_path.c_str(), build_seconds,
        threads,
        rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED) ? "yes" : "no");
    for (int mode : {1, 8, 16}) {
        std::vector<double> seconds;
        std::uint64_t rays = 0;
        for (int run = 0; run < runs; ++run) {
            start = std::chrono::steady_clock::now();
            rays = render(k, mode, threads);
            seconds.push_back(
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        }
        std::sort(seconds.begin(), seconds.end());
        const double median = seconds[seconds.size() / 2];
        std::printf("mode %s: %llu rays, %.4f s, %.2f Mrays/s\n",
                    mode == 1 ? "ray1" : (mode == 8 ? "ray8" : "ray16"),
                    static_cast<unsigned long long>(rays), median, rays / median / 1e6);
    }
    rtcReleaseScene(k.bvh);
    rtcReleaseDevice(device);
    return 0;
}
