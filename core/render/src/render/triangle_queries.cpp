#include "render/triangle_queries.hpp"

#include "geometry/intersect.hpp"
#include "render/far_ray.hpp"
#include "render/float_ray.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

namespace jt {

namespace {

// Embree hands the filters the context pointer we passed in; the query starts
// with it so that it can be found again.
struct TriangleQuery {
    RTCIntersectContext context;
    const TriangleGeometry* geometry;
    Vec3 origin, direction;
    double t_min, t_max;
    Departure from;
    double lift;  // |origin - from.point|
    // The instance whose corners Embree walks on their own (a FarInstance):
    // its hits name no instance.
    std::uint32_t far_instance = TriangleId::no_instance;
    // How the ray Embree walks in the scene of all the triangles maps to
    // this one (embree_ray), and the exact distance of the nearest boxed
    // instance's hit found so far.
    FarRay embree;
    double nearest_boxed = no_hit;
};

Vec3 corner(const Model& m, std::uint32_t triangle, int k) {
    return Vec3(m.positions[m.triangles[triangle][k]]);
}

// The double-precision point of the ray on triangle `id`'s plane.
bool exact_point(const TriangleGeometry& g, TriangleId id, const Vec3& origin,
                 const Vec3& direction, TrianglePoint& out) {
    if (id.instance == TriangleId::no_instance) {
        const auto& c = g.loose[id.triangle].corners;
        return triangle_plane_point(origin, direction, c[0], c[1], c[2], out);
    }
    const MeshInstance& instance = g.instances[id.instance];
    const Model& m = *g.models[instance.model]->model;
    return triangle_plane_point(
        apply_point(instance.to_object, origin), apply_vector(instance.to_object, direction),
        corner(m, id.triangle, 0), corner(m, id.triangle, 1), corner(m, id.triangle, 2), out);
}

// The corners of triangle `id` in the space its hits are computed in: a
// loose triangle's in world space, a mesh triangle's in its model's.
std::array<Vec3, 3> corners_of(const TriangleGeometry& g, TriangleId id) {
    if (id.instance == TriangleId::no_instance) return g.loose[id.triangle].corners;
    const Model& m = *g.models[g.instances[id.instance].model]->model;
    return {corner(m, id.triangle, 0), corner(m, id.triangle, 1), corner(m, id.triangle, 2)};
}

// Whether triangles a and b of one mesh instance (or both loose) share a corner.
bool neighbours(const TriangleGeometry& g, TriangleId a, TriangleId b) {
    if (a.instance != b.instance) return false;
    const std::array<Vec3, 3> ca = corners_of(g, a), cb = corners_of(g, b);
    for (const Vec3& p : ca)
        if (std::find(cb.begin(), cb.end(), p) != cb.end()) return true;
    return false;
}

TriangleId id_of(const RTCFilterFunctionNArguments* args) {
    const unsigned instance = RTCHitN_instID(args->hit, args->N, 0, 0);
    return {instance == RTC_INVALID_GEOMETRY_ID ? TriangleId::no_instance : instance,
            RTCHitN_primID(args->hit, args->N, 0)};
}

// Whether the candidate the filter sees lies in the query's range, exactly.
// A ray that leaves a triangle starts at a point P of it lifted by ε, and P at
// a shared vertex or edge lies on every triangle around it, which therefore
// never shadows or reflects it (docs/language.md §13.5). The lift cannot tell:
// along the normal facing the ray it carries P just behind the plane of a face
// across the vertex (Embree's single-precision test then reports that face,
// though the ray passes outside it), and at a back face met on a silhouette it
// carries P into the solid, where the ray toward a light outside crosses a
// neighbour on its way out (the vertex, lit, came out black). So a triangle
// that shares a corner with the one the ray leaves is met only where the ray
// from P itself, in double precision, passes inside it farther than ε from P.
// Other triangles keep Embree's watertight answer, so that no ray slips
// between two of them.
bool keep(const TriangleQuery& q, TriangleId id) {
    if (id == q.from.triangle) return false;
    TrianglePoint p;
    if (!exact_point(*q.geometry, id, q.origin, q.direction, p) || !(p.t > q.t_min) ||
        !(p.t < q.t_max))
        return false;
    if (q.from.triangle == TriangleId{} || !neighbours(*q.geometry, id, q.from.triangle))
        return true;
    TrianglePoint from_p;
    return exact_point(*q.geometry, id, q.from.point, q.direction, from_p) && from_p.t > q.lift &&
           from_p.u >= 0.0 && from_p.v >= 0.0 && from_p.u + from_p.v <= 1.0;
}

bool keep(const RTCFilterFunctionNArguments* args) {
    const auto& q = *reinterpret_cast<const TriangleQuery*>(args->context);
    TriangleId id = id_of(args);
    if (q.far_instance != TriangleId::no_instance) id.instance = q.far_instance;
    return keep(q, id);
}

bool position_less(const glm::vec3& a, const glm::vec3& b) {
    return a.x < b.x || (a.x == b.x && (a.y < b.y || (a.y == b.y && a.z < b.z)));
}

// The model's corners sorted by position (TriangleModel::corners_by_position).
const std::vector<std::uint32_t>& corners_by_position(const TriangleModel& tm) {
    std::call_once(tm.corners_sorted, [&tm] {
        const Model& m = *tm.model;
        auto at = [&m](std::uint32_t k) { return m.positions[m.triangles[k / 3][k % 3]]; };
        std::vector<std::uint32_t>& sorted = tm.corners_by_position;
        sorted.resize(3 * m.triangles.size());
        std::iota(sorted.begin(), sorted.end(), 0u);
        std::sort(sorted.begin(), sorted.end(), [&](std::uint32_t a, std::uint32_t b) {
            return position_less(at(a), at(b)) || (at(a) == at(b) && a < b);
        });
    });
    return tm.corners_by_position;
}

// Tests triangle `id` exactly: true when the ray passes inside it nearer than
// `best`, and the query keeps it; `best` and `nearest` are then that hit.
bool offer_exactly(const TriangleQuery& q, TriangleId id, double& best, TriangleId& nearest) {
    TrianglePoint p;
    if (!exact_point(*q.geometry, id, q.origin, q.direction, p) || !(p.u >= 0.0) || !(p.v >= 0.0) ||
        !(p.u + p.v <= 1.0) || !(p.t < best) || !keep(q, id))
        return false;
    best = p.t;
    nearest = id;
    return true;
}

// A ray leaving a mesh triangle at P within this barycentric weight of one of
// its edges has its start within Embree's single-precision rounding of that
// edge for any triangle larger than about 1e-4 of the coordinates around it.
constexpr double near_edge_weight = 1e-3;

// The triangles around the one a ray leaves, tested exactly, after Embree's
// answer (`found`, at `nearest`): the nearest kept one of them all ends in
// `nearest`. Leaving P near an edge into the fold between its triangle and a
// neighbour (a ray reflected inside a mesh's crease, closer to the edge at
// each bounce), the ray meets that neighbour within rounding of the shared
// edge, where Embree's float test may put it just outside; its watertight
// partner across the edge is the triangle the ray leaves, which it never
// meets, so the ray would slip out through the closed fold.
bool nearest_around_departure(const TriangleQuery& q, TriangleId& nearest, bool found) {
    const TriangleId from = q.from.triangle;
    if (from.instance == TriangleId::no_instance || from.triangle == TriangleId{}.triangle)
        return found;
    const TriangleGeometry& g = *q.geometry;
    TrianglePoint p;
    if (!exact_point(g, from, q.from.point, q.direction, p) ||
        !(std::min({p.u, p.v, 1.0 - p.u - p.v}) < near_edge_weight))
        return found;
    double best = no_hit;
    TrianglePoint h;
    if (found && exact_point(g, nearest, q.origin, q.direction, h)) best = h.t;
    const TriangleModel& tm = *g.models[g.instances[from.instance].model];
    const Model& m = *tm.model;
    const std::vector<std::uint32_t>& sorted = corners_by_position(tm);
    auto at = [&m](std::uint32_t k) { return m.positions[m.triangles[k / 3][k % 3]]; };
    for (const std::uint32_t corner : m.triangles[from.triangle]) {
        const glm::vec3 position = m.positions[corner];
        auto k = std::lower_bound(
            sorted.begin(), sorted.end(), position,
            [&](std::uint32_t c, const glm::vec3& x) { return position_less(at(c), x); });
        for (; k != sorted.end() && at(*k) == position; ++k) {
            const TriangleId id{from.instance, *k / 3};
            if (id != from) found = offer_exactly(q, id, best, nearest) || found;
        }
    }
    return found;
}

// The walk for a ray out of Embree's reach even when moved (render/far_ray.hpp):
// every triangle, in double precision, the nearest kept one first (the lowest
// id of equally near ones). `first` stops at any kept one.
bool nearest_by_testing_all(const TriangleQuery& q, TriangleId& nearest, bool first) {
    const TriangleGeometry& g = *q.geometry;
    double best = no_hit;
    auto offer = [&](TriangleId id) { return offer_exactly(q, id, best, nearest) && first; };
    for (std::uint32_t i = 0; i < g.loose.size(); ++i)
        if (offer({TriangleId::no_instance, i})) return true;
    for (std::uint32_t k = 0; k < g.instances.size(); ++k) {
        const Model& m = *g.models[g.instances[k].model]->model;
        for (std::uint32_t i = 0; i < m.triangles.size(); ++i)
            if (offer({k, i})) return true;
    }
    return best < no_hit;
}

// The float ray Embree walks for the query's ray; false when no triangle can
// be met (out of reach: `walk` says to test them all). A ray from outside
// the triangles' box starts where it enters the box, moved along itself in
// double precision: Embree's single-precision test rounds its edge values at
// the size of the ray's start, and a ray from hundreds of model sizes away
// through a mesh's vertex came out on one side of all four edges there and
// met none of the faces around it (language.md §13.5 says it meets one).
bool embree_ray(TriangleQuery& q, RTCRay& ray, bool& walk) {
    walk = false;
    q.embree = FarRay{};
    q.embree.fit = FarRay::Fit::as_is;
    if (!embree_takes(q.origin, q.direction)) {
        q.embree = fit_embree_ray(q.geometry->scene, q.origin, q.direction, q.t_min, q.t_max, ray);
        walk = q.embree.fit == FarRay::Fit::out_of_reach;
        return q.embree.fit == FarRay::Fit::moved;
    }
    set_float_ray(ray, q.origin, q.direction, q.t_min, q.t_max);
    // fit_far_ray looks ahead of the start only; inside the box the rounding
    // is the box's own.
    const RTCBounds& box = q.geometry->bounds;
    const bool inside = q.origin.x >= box.lower_x && q.origin.x <= box.upper_x &&
                        q.origin.y >= box.lower_y && q.origin.y <= box.upper_y &&
                        q.origin.z >= box.lower_z && q.origin.z <= box.upper_z;
    if (inside || !(q.t_min >= 0.0)) return true;
    const FarRay near = fit_far_ray(q.origin, q.direction, q.t_min, q.t_max, q.geometry->bounds);
    if (near.fit == FarRay::Fit::misses) return false;
    // The direction is within Embree's reach, so it keeps its length (exponent 0).
    if (near.fit == FarRay::Fit::moved && near.shift > q.t_min) {
        set_far_ray(ray, near, q.t_min, q.t_max);
        q.embree = near;
    }
    return true;
}

// The distance along the query's ray of distance `t` along Embree's.
double query_t(const FarRay& embree, float t) {
    return times_two_to(static_cast<double>(t), -embree.exponent) + embree.shift;
}

Vec3 times_power_of_two(const Vec3& v, int exponent) {
    return Vec3(times_two_to(v.x, exponent), times_two_to(v.y, exponent),
                times_two_to(v.z, exponent));
}

// Whether the ray's stretch from t_min to t_max misses the box.
bool misses_box(const Vec3& lower, const Vec3& upper, const Vec3& origin, const Vec3& direction,
                double t_min, double t_max) {
    double enter = t_min, leave = t_max;
    for (int a = 0; a < 3; ++a) {
        if (direction[a] == 0.0) {
            if (origin[a] < lower[a] || origin[a] > upper[a]) return true;
            continue;
        }
        double t0 = (lower[a] - origin[a]) / direction[a],
               t1 = (upper[a] - origin[a]) / direction[a];
        if (t0 > t1) std::swap(t0, t1);
        enter = std::max(enter, t0);
        leave = std::min(leave, t1);
    }
    return enter > leave;
}

// The walk of one mesh on its own (FarInstance), for a ray that may cross its
// world box: the ray moved into its model's space in double precision, times
// 2^-exponent, against the model's own BVH.
// Its direction is scaled to a length near 1 by another power of two (and its
// distances the other way): Embree's float test multiplies coordinates by the
// direction, and a shrunk mesh's map lengthens it past what a float holds.
// Its start is moved along it to where it enters the model's box
// (fit_far_ray), always: a float origin rounds at its own size, and one
// hundreds of model sizes away (an ill-conditioned mesh's map stretches the
// world's distances so) put a shadow ray that crosses a ridge of the mesh
// 1e-5 inside it outside both faces there.
// The filter decides each hit on the ray as it is. The nearest kept triangle
// nearer than q.t_max goes to `nearest`; `first` stops at any kept one.
bool nearest_in_walked_mesh(TriangleQuery& q, const FarInstance& far, TriangleId& nearest,
                            bool first) {
    const MeshInstance& instance = q.geometry->instances[far.instance];
    const Vec3 origin =
        times_power_of_two(apply_point(instance.to_object, q.origin), -far.exponent);
    Vec3 direction = apply_vector(instance.to_object, q.direction);
    const double longest =
        std::max({std::abs(direction.x), std::abs(direction.y), std::abs(direction.z)});
    if (!(longest > 0.0) || !std::isfinite(longest)) return false;
    const int k = std::ilogb(longest);
    direction = times_power_of_two(direction, -k);
    RTCRayHit rayhit;
    const double t_min = times_two_to(q.t_min, k - far.exponent),
                 t_max = times_two_to(q.t_max, k - far.exponent);
    const FarRay fit = fit_far_ray(origin, direction, t_min, t_max, far.corners_bounds);
    if (fit.fit == FarRay::Fit::moved) set_far_ray(rayhit.ray, fit, t_min, t_max);
    if (fit.fit == FarRay::Fit::misses) return false;
    if (fit.fit == FarRay::Fit::out_of_reach) {
        const Model& m = *q.geometry->models[instance.model]->model;
        double best = q.t_max;
        bool found = false;
        for (std::uint32_t i = 0; i < m.triangles.size(); ++i)
            if (offer_exactly(q, {far.instance, i}, best, nearest)) {
                found = true;
                if (first) break;
            }
        return found;
    }
    q.far_instance = far.instance;
    bool found = false;
    if (first) {
        rtcOccluded1(far.corners, &q.context, &rayhit.ray);
        found = rayhit.ray.tfar < 0.0f;
    } else {
        clear_hit(rayhit.hit);
        rtcIntersect1(far.corners, &q.context, &rayhit);
        found = rayhit.hit.geomID != RTC_INVALID_GEOMETRY_ID;
        if (found) nearest = {far.instance, rayhit.hit.primID};
    }
    q.far_instance = TriangleId::no_instance;
    return found;
}

// The triangles Embree's BVH leaves out (TriangleGeometry::far_loose and
// far_instances), offered after what it found (`found`, at `nearest`): the
// nearest kept one of them all ends in `nearest`. `first` stops at any kept one.
bool nearest_beyond_bvh(TriangleQuery& q, TriangleId& nearest, bool found, bool first) {
    const TriangleGeometry& g = *q.geometry;
    const double t_max = q.t_max;
    double best = no_hit;
    TrianglePoint p;
    if (found && exact_point(g, nearest, q.origin, q.direction, p)) best = p.t;
    for (const std::uint32_t k : g.far_loose) {
        if (found && first) return true;
        found = offer_exactly(q, {TriangleId::no_instance, k}, best, nearest) || found;
    }
    for (const FarInstance& far : g.far_instances) {
        if (found && first) return true;
        q.t_max = std::min(t_max, best);
        if (misses_box(far.lower, far.upper, q.origin, q.direction, q.t_min, q.t_max)) continue;
        TriangleId id;
        if (nearest_in_walked_mesh(q, far, id, first) &&
            (first || (exact_point(g, id, q.origin, q.direction, p) && p.t < best))) {
            best = first ? best : p.t;
            nearest = id;
            found = true;
        }
    }
    q.t_max = t_max;
    return found;
}

TriangleQuery query(const TriangleGeometry& g, const Vec3& origin, const Vec3& direction,
                    double t_min, double t_max, const Departure& from) {
    TriangleQuery q;
    rtcInitIntersectContext(&q.context);
    q.geometry = &g;
    q.origin = origin;
    q.direction = direction;
    q.t_min = t_min;
    q.t_max = t_max;
    q.from = from;
    q.lift = glm::length(origin - from.point);
    return q;
}

}  // namespace

// Nothing farther than what Embree holds already (tfar, whose rounding is up)
// nor, of equally near meshes, any but the first.
void boxed_instance_intersect(const RTCIntersectFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto& q = *reinterpret_cast<TriangleQuery*>(args->context);
    RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, args->N);
    const double t_max = q.t_max;
    q.t_max = std::min({t_max, q.nearest_boxed, query_t(q.embree, RTCRayN_tfar(ray, args->N, 0))});
    TriangleId id;
    const bool found =
        nearest_in_walked_mesh(q, q.geometry->boxed_instances[args->primID], id, false);
    q.t_max = t_max;
    TrianglePoint p;
    if (!found || !exact_point(*q.geometry, id, q.origin, q.direction, p)) return;
    q.nearest_boxed = p.t;
    RTCHitN* hit = RTCRayHitN_HitN(args->rayhit, args->N);
    RTCRayN_tfar(ray, args->N, 0) = far_t_up(q.embree, p.t);
    RTCHitN_geomID(hit, args->N, 0) = args->geomID;
    RTCHitN_primID(hit, args->N, 0) = id.triangle;
    RTCHitN_instID(hit, args->N, 0, 0) = id.instance;
}

void boxed_instance_occluded(const RTCOccludedFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto& q = *reinterpret_cast<TriangleQuery*>(args->context);
    TriangleId any;
    if (nearest_in_walked_mesh(q, q.geometry->boxed_instances[args->primID], any, true))
        RTCRayN_tfar(args->ray, args->N, 0) = -float_infinity;
}

void triangle_intersect_filter(const RTCFilterFunctionNArguments* args) {
    if (args->valid[0] && !keep(args)) args->valid[0] = 0;
}

void triangle_occluded_filter(const RTCFilterFunctionNArguments* args) {
    if (args->valid[0] && !keep(args)) args->valid[0] = 0;
}

bool closest_triangle(const TriangleGeometry& g, const Vec3& origin, const Vec3& direction,
                      double t_min, double t_max, TriangleHit& hit, const Departure& from) {
    TriangleQuery q = query(g, origin, direction, t_min, t_max, from);
    RTCRayHit rayhit;
    bool walk = false;
    bool found = false;
    if (!embree_ray(q, rayhit.ray, walk)) {
        found = walk && nearest_by_testing_all(q, hit.id, false);
    } else {
        clear_hit(rayhit.hit);
        rtcIntersect1(g.scene, &q.context, &rayhit);
        found = rayhit.hit.geomID != RTC_INVALID_GEOMETRY_ID;
        const unsigned instance = rayhit.hit.instID[0];
        if (found)
            hit.id = {instance == RTC_INVALID_GEOMETRY_ID ? TriangleId::no_instance : instance,
                      rayhit.hit.primID};
    }
    if (!g.far_loose.empty() || !g.far_instances.empty())
        found = nearest_beyond_bvh(q, hit.id, found, false);
    found = nearest_around_departure(q, hit.id, found);
    if (!found) return false;
    TrianglePoint p;
    if (!exact_point(g, hit.id, origin, direction, p)) return false;
    hit.t = p.t;
    hit.u = p.u;
    hit.v = p.v;
    hit.source = hit.id.instance == TriangleId::no_instance ? g.loose[hit.id.triangle].source
                                                            : g.instances[hit.id.instance].source;
    return true;
}

bool triangle_blocks(const TriangleGeometry& g, const Vec3& origin, const Vec3& direction,
                     double t_min, double t_max, const Departure& from) {
    TriangleQuery q = query(g, origin, direction, t_min, t_max, from);
    RTCRay ray;
    bool walk = false;
    TriangleId any;
    bool blocked = false;
    if (!embree_ray(q, ray, walk)) {
        blocked = walk && nearest_by_testing_all(q, any, true);
    } else {
        rtcOccluded1(g.scene, &q.context, &ray);
        blocked = ray.tfar < 0.0f;
    }
    if (!blocked && (!g.far_loose.empty() || !g.far_instances.empty()))
        blocked = nearest_beyond_bvh(q, any, false, true);
    // Leaving near an edge into a fold, a shadow ray slips out of it as a
    // reflected one would (nearest_around_departure).
    if (!blocked) blocked = nearest_around_departure(q, any, false);
    return blocked;
}

TriangleSurface triangle_surface(const TriangleGeometry& g, const TriangleHit& hit) {
    TriangleSurface s;
    const double w = 1.0 - hit.u - hit.v;
    if (hit.id.instance == TriangleId::no_instance) {
        const LooseTriangle& t = g.loose[hit.id.triangle];
        s.geometric = glm::cross(t.corners[1] - t.corners[0], t.corners[2] - t.corners[0]);
        if (t.mirrored) s.geometric = -s.geometric;
        s.uv = w * t.uvs[0] + hit.u * t.uvs[1] + hit.v * t.uvs[2];
        return s;
    }
    const MeshInstance& instance = g.instances[hit.id.instance];
    const Model& m = *g.models[instance.model]->model;
    const auto& corners = m.triangles[hit.id.triangle];
    const Vec3 a = corner(m, hit.id.triangle, 0);
    s.geometric = instance.normal_matrix *
                  glm::cross(corner(m, hit.id.triangle, 1) - a, corner(m, hit.id.triangle, 2) - a);
    if (instance.smooth && instance.corner_normals) {
        const auto& n = (*instance.corner_normals)[hit.id.triangle];
        s.shading = instance.normal_matrix * (w * n[0] + hit.u * n[1] + hit.v * n[2]);
    } else if (instance.smooth && !m.normals.empty()) {
        const Vec3 na(m.normals[corners[0]]), nb(m.normals[corners[1]]), nc(m.normals[corners[2]]);
        if (na != Vec3(0.0) && nb != Vec3(0.0) && nc != Vec3(0.0))
            s.shading = instance.normal_matrix * (w * na + hit.u * nb + hit.v * nc);
    }
    if (!m.uvs.empty())
        s.uv = w * glm::dvec2(m.uvs[corners[0]]) + hit.u * glm::dvec2(m.uvs[corners[1]]) +
               hit.v * glm::dvec2(m.uvs[corners[2]]);
    return s;
}

}  // namespace jt
