#pragma once
// An independent, deliberately plain renderer of docs/language.md sections 5-9
// and of the extensions of sections 13 and 14 that random scenes use (triangles
// and meshes, flat and smooth; refraction and transmitted shadows; image maps on
// triangles; the pixel hash, lights with a radius, the lens, sky maps,
// generated smooth normals and an OBJ's Kd per usemtl), for the differential
// test, written from the text of those sections alone: the R2 samples of each
// pixel (one at its centre by default), every ray tested against every
// primitive in that primitive's own object space, in double precision; no
// acceleration structure, no tables, no tiles, no code shared with the core
// (only the Scene values and glm's vector arithmetic). It reads no file: the
// generator hands it the triangles and texels it wrote (Files).
//
// Secondary rays start exactly on the surface: the root of the ray's own
// primitive at the start point is removed algebraically (the other root of a
// quadratic through a known root), not by an offset. A ray leaving a triangle
// of a mesh meets no triangle of that mesh whose plane holds its start (its
// own, and at an edge or vertex the ones that share it): a plane through the
// start is met only there. It meets a triangle that shares a corner with the
// one it leaves only farther than ε (§8.5) from its start, as §13.5 says.
//
// Besides its colour, each pixel says whether its bytes are numerically
// ambiguous: whether errors of the size any double-precision renderer makes
// could change them. A pixel is ambiguous when
// - its colour changes under a perturbation of the primary ray far above
//   rounding (1e-8 radians along each of the camera's right and up axes, both
//   ways: whatever edge passes within that of the ray, in any direction, lies
//   between two of the four rays), or when secondary rays start 1e-7 of the
//   scene's magnitude off the surface instead of on it (the offsets renderers
//   use lie between; off an ill-conditioned mesh, no farther than its faces
//   count as near the start, below);
// - a channel lies within 1e-6 of a rounding boundary of the 0..255 scale
//   (unless it is the exact mean of 2^k samples that each clamp to 0 or 1;
//   within 1e-9 when no sample took a light's, an image map's or a sky map's
//   term: sums of products of the scene's constants, exact to some ulps);
// - two surfaces lie within 1e-8 (relative) of each other along one of its
//   rays, or a secondary ray meets another surface within 1e-6 (relative) of
//   its start (another face of the ill-conditioned mesh it leaves: within
//   1e-6 of the model's size in its own space, or twice ε): coincident or
//   touching surfaces, where the nearest hit or the shadow is a matter of
//   rounding; two triangles within 1e-6 of each other, which a renderer
//   may order in single precision (§13.5 allows the core that; two faces of
//   one ill-conditioned mesh, within 1e-6 of the model's size in its own
//   space, where §13.5 orders them), and then the primary ray shaded as a
//   hit on each triangle within 1e-6 of its nearest joins the variants;
// - a point of a light's disk lies within rounding of the horizon of the
//   surface it lights, or the hit point within rounding of the light's sphere;
// - its ray passes within 1e-6 (barycentric) of an edge or a corner of a
//   triangle, where a single-precision test may put it on either side: then
//   the ray shaded as a hit on each triangle through that point, and a ray
//   aimed just inside each, join the variants (a renderer may take any of
//   them, and the four turned rays need not meet them all: at a corner, or at
//   a silhouette, perhaps none);
// - a shadow ray passes within 1e-6 (barycentric) of an edge of a triangle
//   before the light (passing outside a face that shares a corner with the
//   one it leaves does not count: §13.5 meets that face only where the ray,
//   in double precision, passes inside it): then the ray traced with each
//   such shadow ray turned just across the first such edge joins the
//   variants. Such a shadow ray flags nothing when an opaque surface blocks
//   it under any rounding (met farther than 1e-6 inside its edges, not near
//   the ray's start or end), or when its light's whole term there, times its
//   branch's weight in the pixel, summed over such rays, cannot move a byte
//   of the pixel;
// - a reflected or refracted ray passes within 1e-6 (barycentric) outside an
//   edge of a triangle: then the ray traced with every such ray meeting the
//   triangles it passes that close to joins the variants (a single-precision
//   test may meet them, and then whatever the rays it starts there meet);
// - a smooth normal lies within 1e-9 of its face's plane (a unit normal's dot
//   product with the unit geometric one), where the side §13.5 turns it to
//   is a matter of rounding: then the ray traced with each such normal
//   turned to the other side joins the variants, and the pixel is flagged
//   when that can move one of its bytes (or lies within rounding of one).
//   So does each variant above traced with its own such normals turned: a
//   ray through a vertex whose normal runs along an edge of the faces
//   around it, shaded as a hit on one of them, may light it either way.
// A light whose diffuse and specular terms at a point are zero, whatever
// reaches it, casts no shadow ray there, so flags nothing.
// With several samples a pixel, each sample's variants give it a least and a
// greatest clamped colour; the pixel's range is the byte of the mean of the
// least and of the greatest, and it is ambiguous when those differ or when
// any sample is flagged.

#include "jtracer/image.hpp"
#include "jtracer/scene.hpp"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

namespace jt::reference {

// p -> linear * p + translation
struct Map {
    glm::dmat3 linear{1.0};
    Vec3 translation{0.0};
};

// p -> second(first(p))
inline Map then(const Map& first, const Map& second) {
    return {second.linear * first.linear, second.linear * first.translation + second.translation};
}

inline glm::dmat3 rotation(TransformKind axis, double degrees) {
    const double a = degrees * std::numbers::pi / 180.0;
    const double c = std::cos(a), s = std::sin(a);
    glm::dmat3 m(1.0);  // m[column][row]
    int i = 0, j = 1;   // the plane turned: +i toward +j
    if (axis == TransformKind::xrotate) i = 1, j = 2;
    if (axis == TransformKind::yrotate) i = 2, j = 0;
    m[i][i] = c;
    m[i][j] = s;
    m[j][i] = -s;
    m[j][j] = c;
    return m;
}

inline Map op_map(const TransformOp& op) {
    Map m;
    if (op.kind == TransformKind::translate)
        m.translation = op.vector;
    else if (op.kind == TransformKind::scale)
        m.linear = glm::dmat3(glm::dvec3(op.vector.x, 0, 0), glm::dvec3(0, op.vector.y, 0),
                              glm::dvec3(0, 0, op.vector.z));
    else
        m.linear = rotation(op.kind, op.degrees);
    return m;
}

inline Map op_inverse(const TransformOp& op) {
    Map m;
    if (op.kind == TransformKind::translate)
        m.translation = -op.vector;
    else if (op.kind == TransformKind::scale)
        m.linear = glm::dmat3(glm::dvec3(1 / op.vector.x, 0, 0), glm::dvec3(0, 1 / op.vector.y, 0),
                              glm::dvec3(0, 0, 1 / op.vector.z));
    else
        m.linear = rotation(op.kind, -op.degrees);
    return m;
}

inline Map to_world(const std::vector<TransformOp>& ops) {
    Map m;
    for (const TransformOp& op : ops) m = then(m, op_map(op));
    return m;
}

inline Map to_object(const std::vector<TransformOp>& ops) {
    Map m;
    for (const TransformOp& op : ops) m = then(op_inverse(op), m);
    return m;
}

// docs/language.md §5.5: a scale with a zero component leaves the primitive out.
inline bool flattened(const std::vector<TransformOp>& ops) {
    for (const TransformOp& op : ops)
        if (op.kind == TransformKind::scale &&
            (op.vector.x == 0 || op.vector.y == 0 || op.vector.z == 0))
            return true;
    return false;
}

inline double max_abs(const Vec3& v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

// A model file's triangles as the generator wrote them (object space).
struct Model {
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;  // one a vertex, or none
    std::vector<std::array<int, 3>> faces;
    // With materials: "file" (§14.5): each face's part, an index into
    // part_colours (its Kd), or -1 for the mesh's own material.
    std::vector<int> face_part;
    std::vector<Colour> part_colours;
};

// A picture's texels, row 0 at the bottom, 3 bytes a texel.
struct Picture {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgb;
};

// The files a scene names, by the name it gives them.
struct Files {
    std::map<std::string, Model> models;
    std::map<std::string, Picture> pictures;
};

// The unit direction of the ray through image point (x, y), x from the left
// and y from the bottom in pixels (§7.1).
inline Vec3 sample_direction(const Camera& camera, int w, int h, double x, double y) {
    const Vec3 f = glm::normalize(camera.look_at - camera.position);
    const Vec3 r = glm::normalize(glm::cross(f, camera.up));
    const Vec3 u = glm::cross(r, f);
    const double t = std::tan(camera.fov / 2 * std::numbers::pi / 180);
    const double sx = (2 * x / w - 1) * t * camera.aspect;
    const double sy = (2 * y / h - 1) * t;
    return glm::normalize(f + sx * r + sy * u);
}

// The unit direction of the ray through pixel (i, j)'s centre (§7.1).
inline Vec3 pixel_direction(const Camera& camera, int w, int h, int i, int j) {
    return sample_direction(camera, w, h, i + 0.5, j + 0.5);
}

// Sample k's place in its pixel (§9.2): the R2 sequence from the centre.
inline double sample_offset(double step, int k) {
    const double x = 0.5 + step * static_cast<double>(k);
    return x - std::floor(x);
}
inline constexpr double kR2X = 0.7548776662466927, kR2Y = 0.5698402909980532;

// The angle docs/language.md §14.0 takes from pixel (i, j) and an integer s.
inline double pixel_angle(int i, int j, int s) {
    std::uint32_t h = (static_cast<std::uint32_t>(i) * 73856093u) ^
                      (static_cast<std::uint32_t>(j) * 19349663u) ^
                      (static_cast<std::uint32_t>(s) * 83492791u);
    h = h ^ (h >> 16);
    h = h * 0x45d9f3bu;
    h = h ^ (h >> 16);
    return 2 * std::numbers::pi * static_cast<double>(h) / 4294967296.0;
}

inline constexpr double kGoldenAngle = 2.399963229728653;

// The pixel hash's s for the lens (§14.2).
inline constexpr int kLensHash = 2048;

// A primary ray: where it starts and its unit direction.
struct Ray {
    Vec3 origin{0.0};
    Vec3 direction{0.0};
};

// Sample k (of n) of pixel (i, j) through the camera's lens (§14.2), d the
// pinhole direction of the sample.
inline Ray lens_ray(const Camera& camera, const Vec3& d, int i, int j, int k, int n) {
    const Vec3 e = camera.position;
    const double rho = camera.aperture * std::sqrt(static_cast<double>(k) / n);
    if (camera.aperture <= 0 || rho == 0) return {e, d};
    const Vec3 f = glm::normalize(camera.look_at - camera.position);
    const Vec3 r = glm::normalize(glm::cross(f, camera.up));
    const Vec3 u = glm::cross(r, f);
    const Vec3 look = camera.look_at - camera.position;
    const double focus = camera.focus_distance
                             ? *camera.focus_distance
                             : std::sqrt(look.x * look.x + look.y * look.y + look.z * look.z);
    const Vec3 in_focus = e + d * (focus / glm::dot(d, f));
    const double theta = k * kGoldenAngle + pixel_angle(i, j, kLensHash);
    const Vec3 from = e + rho * (std::cos(theta) * r + std::sin(theta) * u);
    return {from, glm::normalize(in_focus - from)};
}

struct Rgb8 {
    std::uint8_t r = 0, g = 0, b = 0;
    bool operator==(const Rgb8&) const = default;
};

struct ReferenceImage {
    Image8 image;
    std::vector<bool> ambiguous;  // per pixel, row 0 at the bottom
    // Per pixel and channel, the least and greatest value any of the pixel's
    // variant rays gave: an ambiguous pixel's bytes are expected within.
    std::vector<std::array<std::uint8_t, 6>> range;
};

class Tracer {
  public:
    Tracer(const Scene& scene, const Files& files) : scene_(scene) {
        for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
            const Primitive& p = scene.primitives[i];
            if (flattened(p.transforms)) continue;
            Placed q;
            q.index = i;
            q.shape = &p.shape;
            q.material = &p.material;
            const Map inverse = to_object(p.transforms);
            q.world_to_object = inverse;
            q.object_to_world = to_world(p.transforms);

            q.normal_matrix = glm::transpose(inverse.linear);
            if (const auto* plane = shape_if<Plane>(&p.shape))
                q.unit_normal = plane->normal / std::sqrt(glm::dot(plane->normal, plane->normal));
            if (const auto* mesh = shape_if<Mesh>(&p.shape)) {
                q.model = &files.models.at(mesh->file);
                q.file_materials = mesh->materials == kFileMaterials;
                if (mesh->shading == kSmoothShading && !q.model->normals.empty())
                    for (const auto& face : q.model->faces)
                        q.corner_normals.push_back({q.model->normals[face[0]],
                                                    q.model->normals[face[1]],
                                                    q.model->normals[face[2]]});
                else if (mesh->shading == kSmoothShading && mesh->smooth_angle)
                    q.corner_normals = generated_normals(*q.model, *mesh->smooth_angle);
                if (!(largest_row_sum(q.object_to_world.linear) *
                          largest_row_sum(q.world_to_object.linear) <=
                      kMaxPlainCondition))
                    for (const Vec3& v : q.model->positions)
                        q.own_extent = std::max(q.own_extent, max_abs(v));
            }
            if (!p.material.finish->image_map.empty())
                q.picture = &files.pictures.at(p.material.finish->image_map);
            transmissive_ = transmissive_ || p.material.finish->transmission > 0;
            placed_.push_back(q);
        }
        if (!scene.settings.background_map.empty())
            sky_ = &files.pictures.at(scene.settings.background_map);
    }

    ReferenceImage render(int camera_index) const {
        const Camera& camera = scene_.cameras[camera_index];
        const int w = scene_.settings.width, h = scene_.settings.height;
        const int n = scene_.settings.samples;
        ReferenceImage out;
        out.image = Image8(w, h);
        out.ambiguous.assign(static_cast<std::size_t>(w) * h, false);
        out.range.resize(static_cast<std::size_t>(w) * h);
        for (int j = 0; j < h; ++j) {
            for (int i = 0; i < w; ++i) {
                Colour sum(0.0), least(0.0), greatest(0.0), single(0.0), grazes(0.0);
                bool ambiguous = false;
                // Whether any sample's colour depends on where its rays went.
                bool varies = false;
                // Per channel: every sample's clamped value is 0 or 1 whatever
                // the rounding, so that the mean is exact (n a power of two).
                std::array<bool, 3> exact{true, true, true};
                for (int k = 0; k < n; ++k) {
                    const Sample s = sample(camera, i, j, k, n);
                    for (int c = 0; c < 3; ++c)
                        exact[c] =
                            exact[c] && (s.colour[c] == 0 || s.colour[c] >= 1 + kClampMargin);
                    sum += n == 1 ? s.colour : clamped(s.colour);
                    single = s.colour;
                    least += s.least;
                    greatest += s.greatest;
                    ambiguous = ambiguous || s.ambiguous;
                    varies = varies || s.varies;
                    // What grazed edges and in-plane normals can change it by.
                    grazes += s.graze_bound + s.in_plane_bound;
                }
                const Colour mean = n == 1 ? single : sum / static_cast<double>(n);
                const Rgb8 centre = quantize(mean);
                const Rgb8 low = quantize(least / static_cast<double>(n));
                const Rgb8 high = quantize(greatest / static_cast<double>(n));
                if (n == 1 || (n & (n - 1)) != 0) exact = {false, false, false};
                ambiguous = ambiguous || near_rounding_boundary(mean, exact, varies) ||
                            !(low == high) || moves_bytes(mean, grazes / static_cast<double>(n));
                std::uint8_t* p = out.image.pixel(i, j);
                p[0] = centre.r;
                p[1] = centre.g;
                p[2] = centre.b;
                const std::size_t at = static_cast<std::size_t>(j) * w + i;
                out.ambiguous[at] = ambiguous;
                out.range[at] = {std::min(centre.r, low.r),  std::min(centre.g, low.g),
                                 std::min(centre.b, low.b),  std::max(centre.r, high.r),
                                 std::max(centre.g, high.g), std::max(centre.b, high.b)};
            }
        }
        return out;
    }

  private:
    // One pixel sample: its colour, and the least and greatest clamped
    // colour its variant rays gave (itself included).
    struct Sample {
        Colour colour{0.0};
        Colour least{0.0}, greatest{0.0};
        bool ambiguous = false;
        // The most its shadow rays that grazed an edge could change it by.
        Colour graze_bound{0.0};
        // Its colour depends on where its rays went (Flags::varies).
        bool varies = false;
        // How far its colour moves with every smooth normal in its face's
        // plane turned to the other side: all that side can change.
        Colour in_plane_bound{0.0};
    };

    static Colour clamped(const Colour& c) { return glm::clamp(c, Colour(0.0), Colour(1.0)); }

    Sample sample(const Camera& camera, int i, int j, int k, int n) const {
        const int w = scene_.settings.width, h = scene_.settings.height;
        const Vec3 f = glm::normalize(camera.look_at - camera.position);
        const Vec3 r = glm::normalize(glm::cross(f, camera.up));
        const Vec3 u = glm::cross(r, f);
        constexpr double turn = 1e-8;
        const Vec3 d =
            sample_direction(camera, w, h, i + sample_offset(kR2X, k), j + sample_offset(kR2Y, k));
        const Ray ray = lens_ray(camera, d, i, j, k, n);
        Flags flags;
        flags.i = i;
        flags.j = j;
        flags.k = k;
        Sample out;
        out.colour = trace(ray.origin, ray.direction, 0, {}, 0.0, false, flags);
        out.ambiguous = flags.ambiguous;
        out.graze_bound = flags.graze_bound;
        out.varies = flags.varies;
        out.least = out.greatest = clamped(out.colour);
        const Flags plain = [&] {
            Flags p;
            p.i = i;
            p.j = j;
            p.k = k;
            return p;
        }();
        auto variant = [&](const Ray& v, bool lifted, const Flags& given) {
            Flags traced = given;
            Colour c = clamped(trace(v.origin, v.direction, 0, {}, 0.0, lifted, traced));
            out.least = glm::min(out.least, c);
            out.greatest = glm::max(out.greatest, c);
            // A smooth normal in its face's plane turns to either side on
            // this variant's rays as on the sample's own: a face forced at
            // a vertex whose normal runs along one of its edges is one.
            if (!traced.in_plane || given.turn_in_plane) return;
            Flags turned = given;
            turned.turn_in_plane = true;
            c = clamped(trace(v.origin, v.direction, 0, {}, 0.0, lifted, turned));
            out.least = glm::min(out.least, c);
            out.greatest = glm::max(out.greatest, c);
        };
        variant(ray, true, plain);
        for (const Vec3& axis : {r, u})
            for (double sign : {-1.0, 1.0})
                variant(lens_ray(camera, glm::normalize(d + sign * turn * axis), i, j, k, n), false,
                        plain);
        for (const auto& [placed, face] : faces_through(ray.origin, ray.direction)) {
            Flags forced = plain;
            forced.force_placed = placed;
            forced.force_face = face;
            variant(ray, false, forced);
            // And just inside it, where the faces around no longer hold the point.
            const Placed& q = placed_[placed];
            Root root;
            plane_root(q, face, ray.origin, ray.direction, root);
            const std::array<Vec3, 3> v = face_corners(q, face);
            const Vec3 at = (1 - root.u - root.v) * v[0] + root.u * v[1] + root.v * v[2];
            // Toward the centre by enough to cross the edge when the ray passes outside it.
            const double least = std::min({root.u, root.v, 1 - root.u - root.v});
            const double step = 1e-6 + 4 * std::max(0.0, -least);
            const Vec3 inside = at + step * ((v[0] + v[1] + v[2]) / 3.0 - at);
            const Vec3 aim = q.object_to_world.linear * inside + q.object_to_world.translation;
            variant({ray.origin, glm::normalize(aim - ray.origin)}, false, plain);
        }
        {
            Flags widened = plain;
            widened.widen_secondary = true;
            variant(ray, false, widened);
        }
        if (flags.grazed) {
            Flags turned = plain;
            turned.turn_grazes = true;
            variant(ray, false, turned);
        }
        if (flags.in_plane) {
            Flags turned = plain;
            turned.turn_in_plane = true;
            const Colour other = trace(ray.origin, ray.direction, 0, {}, 0.0, false, turned);
            out.least = glm::min(out.least, clamped(other));
            out.greatest = glm::max(out.greatest, clamped(other));
            // Unclamped: at least the change of the clamped colour it adds to
            // the pixel's sum.
            out.in_plane_bound = glm::abs(other - out.colour);
        }
        for (const auto& [placed, face] : faces_tied(ray.origin, ray.direction)) {
            Flags forced = plain;
            forced.force_placed = placed;
            forced.force_face = face;
            forced.force_slack = kTriangleTie;
            variant(ray, false, forced);
        }
        return out;
    }

    struct Placed {
        std::size_t index = 0;
        const Shape* shape = nullptr;
        const Material* material = nullptr;
        Map world_to_object;
        Map object_to_world;
        glm::dmat3 normal_matrix{1.0};
        Vec3 unit_normal{0.0};         // planes
        const Model* model = nullptr;  // meshes
        // A smooth mesh's normal at each corner of each face, object space:
        // the file's, or generated (§14.4); empty when shaded flat.
        std::vector<std::array<Vec3, 3>> corner_normals;
        bool file_materials = false;       // pigments from the model's parts (§14.5)
        const Picture* picture = nullptr;  // its image map
        // An ill-conditioned mesh's rays are moved into its model's space in
        // double precision, from where they enter its box (docs/language.md
        // §13.5): which of its own faces comes first is rounded at the model's
        // size, not at the ray's length. The model's extent then; else 0.
        double own_extent = 0;
    };

    // docs/language.md §13.5: past this product of the largest row sums of
    // |M| and |M^-1|, a mesh's map is ill-conditioned.
    static constexpr double kMaxPlainCondition = 64;

    static double largest_row_sum(const glm::dmat3& m) {
        double largest = 0;
        for (int r = 0; r < 3; ++r)
            largest = std::max(largest, std::abs(m[0][r]) + std::abs(m[1][r]) + std::abs(m[2][r]));
        return largest;
    }

    // Where a ray starts: on surface `part` of placed primitive `placed`, or
    // nowhere (placed < 0) for a primary or lifted ray.
    struct Origin {
        int placed = -1;
        int part = 0;  // sphere 0; cylinder side 0, bottom 1, top 2; plane 0; a mesh's face
        Vec3 object_point{0.0};  // meshes: where in object space it starts
        // Started 1e-7 off the surface: meets every surface but the face it
        // leaves (no surface reflects itself, §13.5), its own primitive included.
        bool lifted = false;
        // ε of §8.5 at the start: a face of its mesh that shares a corner with
        // the one it leaves is met only farther than this (§13.5).
        double epsilon = 0.0;
        // How far (barycentric) outside a triangle's edges it still meets it.
        double edge_slack = 0.0;
    };

    // One root: its part, the outward normal in object space (not unit
    // length) and, on a triangle, the barycentric weights of corners b and c.
    struct Root {
        double t = INFINITY;
        int part = 0;
        Vec3 normal{0.0};
        double u = 0, v = 0;
    };

    struct Hit {
        double t = INFINITY;
        int placed = -1;
        Root root;
    };

    struct Flags {
        bool ambiguous = false;
        Colour colour{0.0};  // the unclamped colour of the primary ray
        // The primary ray's hit taken on this face of this placed primitive,
        // when the ray meets the face's plane where it meets the nearest surface.
        int force_placed = -1, force_face = -1;
        // How much farther (relative) than the nearest surface the forced face may lie.
        double force_slack = 1e-9;
        int i = 0, j = 0, k = 0;  // the pixel and sample the ray descends from (§14.0)
        // A shadow ray passed within kEdgeGraze of a triangle's edge (graze()).
        bool grazed = false;
        // Each shadow ray turned just across the first such edge it passes.
        bool turn_grazes = false;
        // A smooth normal lay within kInPlaneNormal of its face's plane.
        bool in_plane = false;
        // Each such normal turned to the other side of the face.
        bool turn_in_plane = false;
        // Reflected and refracted rays meet triangles up to kEdgeGraze outside their edges.
        bool widen_secondary = false;
        // The last shadow ray passed within kEdgeGraze of an edge, and no
        // opaque surface surely blocks it: whether it reaches its light is a
        // matter of rounding. The light's caller weighs that in graze_bound.
        bool edge_grazed = false;
        // Per channel, the sum over such shadow rays of their light's term
        // (with all of it reaching) times their branch's weight in the
        // sample: the most whatever they meet can change its colour by.
        Colour graze_bound{0.0};
        // The colour took a term that depends on where the rays went: a
        // light's, a texel blend of an image or sky map. Without one it is a
        // sum of products of the scene's constants (ambient, pigments, the
        // background, reflection weights), which any renderer computes within
        // some ulps.
        bool varies = false;
    };

    static Rgb8 quantize(const Colour& c) {
        auto q = [](double v) {
            return static_cast<std::uint8_t>(std::floor(std::clamp(v, 0.0, 1.0) * 255 + 0.5));
        };
        return {q(c.x), q(c.y), q(c.z)};
    }

    // Above 1 by this (relative), a channel clamps to 1 under any rounding.
    static constexpr double kClampMargin = 1e-6;

    // Whether a channel not known `exact` lies within 1e-6 of a rounding
    // boundary, or within kConstantColourMargin when no sample's colour
    // `varies`. An exact mean of samples each 0 or 1 (two of four at 1: 127.5)
    // sits on a boundary that every renderer rounds alike.
    static bool near_rounding_boundary(const Colour& c, const std::array<bool, 3>& exact,
                                       bool varies) {
        const double margin = varies ? 1e-6 : kConstantColourMargin;
        for (int k = 0; k < 3; ++k) {
            if (exact[k]) continue;
            const double v = std::clamp(c[k], 0.0, 1.0) * 255 + 0.5;
            const double fraction = v - std::floor(v);
            if (v > 0.5 && v < 255.5 && (fraction < margin || fraction > 1 - margin)) return true;
        }
        return false;
    }

    // A colour made of the scene's constants alone is a few sums and products
    // in double precision: some ulps of 255 on the byte scale, far below this.
    static constexpr double kConstantColourMargin = 1e-9;

    // Whether a change of up to `bound` in any channel of colour c (each
    // sample's share of the pixel's mean: clamping cannot widen it) can move
    // a byte, or the change lies within rounding of a boundary.
    static bool moves_bytes(const Colour& c, const Colour& bound) {
        if (bound == Colour(0.0)) return false;
        const Colour margin = bound * (1 + 1e-6) + Colour(1e-6 / 255);
        return !(quantize(c - margin) == quantize(c + margin));
    }

    // Every root t > 0 of the ray with primitive q, except the ray's own start.
    template <class Visit>
    void roots(int which, const Vec3& world_origin, const Vec3& world_direction, const Origin& from,
               Visit visit) const {
        const Placed& q = placed_[which];
        const Vec3 o = q.world_to_object.linear * world_origin + q.world_to_object.translation;
        const Vec3 d = q.world_to_object.linear * world_direction;
        const bool own_face = from.placed == which;  // the triangle it leaves is never met
        const bool own = own_face && !from.lifted;
        auto offer = [&](double t, int part, const Vec3& normal, double u = 0, double v = 0) {
            if (t > 0 && std::isfinite(t)) visit(Root{t, part, normal, u, v});
        };
        // Moller-Trumbore, inside or on the edges.
        // Only roots beyond t_floor count.
        auto triangle = [&](const Vec3& a, const Vec3& b, const Vec3& c, int part,
                            double t_floor = 0.0) {
            const Vec3 e1 = b - a, e2 = c - a, p = glm::cross(d, e2);
            const double det = glm::dot(e1, p);
            if (det == 0) return;
            const Vec3 s = o - a, q = glm::cross(s, e1);
            const double u = glm::dot(s, p) / det, v = glm::dot(d, q) / det;
            const double slack = from.edge_slack;
            if (u < -slack || v < -slack || u + v > 1 + slack) return;
            const double t = glm::dot(e2, q) / det;
            if (t > t_floor) offer(t, part, glm::cross(e1, e2), u, v);
        };
        if (const auto* sphere = shape_if<Sphere>(q.shape)) {
            const Vec3 f = o - sphere->center;
            const double a = glm::dot(d, d), b = glm::dot(f, d);
            if (own) {  // roots 0 and -2b/a
                const double t = -2 * b / a;
                offer(t, 0, f + t * d);
                return;
            }
            const Vec3 perpendicular = f - (b / a) * d;
            const double h2 =
                sphere->radius * sphere->radius - glm::dot(perpendicular, perpendicular);
            if (h2 < 0) return;
            const double half = std::sqrt(h2 / a);
            for (double t : {-b / a - half, -b / a + half}) offer(t, 0, f + t * d);
        } else if (const auto* cylinder = shape_if<Cylinder>(q.shape)) {
            const double r = cylinder->radius, height = cylinder->height;
            const double a = d.x * d.x + d.z * d.z, b = o.x * d.x + o.z * d.z;
            auto side = [&](double t) {
                const double y = o.y + t * d.y;
                if (y >= 0 && y <= height) offer(t, 0, {o.x + t * d.x, 0, o.z + t * d.z});
            };
            if (a > 0) {
                if (own && from.part == 0) {
                    side(-2 * b / a);
                } else {
                    const double px = o.x - (b / a) * d.x, pz = o.z - (b / a) * d.z;
                    const double h2 = r * r - (px * px + pz * pz);
                    if (h2 >= 0) {
                        const double half = std::sqrt(h2 / a);
                        side(-b / a - half);
                        side(-b / a + half);
                    }
                }
            }
            for (int part : {1, 2}) {
                if ((own && from.part == part) || d.y == 0) continue;
                const double y = part == 1 ? 0.0 : height;
                const double t = (y - o.y) / d.y;
                const double x = o.x + t * d.x, z = o.z + t * d.z;
                if (x * x + z * z <= r * r) offer(t, part, {0, part == 1 ? -1.0 : 1.0, 0});
            }
        } else if (const auto* plane = shape_if<Plane>(q.shape)) {
            if (own) return;
            const double denominator = glm::dot(q.unit_normal, d);
            if (denominator == 0) return;
            offer((plane->distance - glm::dot(q.unit_normal, o)) / denominator, 0, q.unit_normal);
        } else if (const auto* t = shape_if<Triangle>(q.shape)) {
            if (!own_face) triangle(t->a, t->b, t->c, 0);
        } else if (q.model) {
            const Model& m = *q.model;
            for (int f = 0; f < static_cast<int>(m.faces.size()); ++f) {
                const Vec3 &a = m.positions[m.faces[f][0]], &b = m.positions[m.faces[f][1]],
                           &c = m.positions[m.faces[f][2]];
                if (own_face && f == from.part) continue;
                if (own && holds(a, b, c, from.object_point)) continue;
                // §13.5: a face that shares a corner with the one the ray
                // leaves is met only farther than ε. A start near that
                // corner, rounded into object space through a map that
                // translates far and back, lies off the face's plane by more
                // than holds() allows, and the ray crosses it a rounding away.
                const bool neighbour = own && shares_corner(m, f, from.part);
                triangle(a, b, c, f, neighbour ? from.epsilon : 0.0);
            }
        }
    }

    // The corners of face f of placed primitive q (a triangle's is face 0), object space.
    static std::array<Vec3, 3> face_corners(const Placed& q, int f) {
        if (const auto* t = shape_if<Triangle>(q.shape)) return {t->a, t->b, t->c};
        const auto& face = q.model->faces[f];
        return {q.model->positions[face[0]], q.model->positions[face[1]],
                q.model->positions[face[2]]};
    }

    // Where the ray meets the plane of face f, inside or not.
    static bool plane_root(const Placed& q, int f, const Vec3& world_origin,
                           const Vec3& world_direction, Root& root) {
        const Vec3 o = q.world_to_object.linear * world_origin + q.world_to_object.translation;
        const Vec3 d = q.world_to_object.linear * world_direction;
        const std::array<Vec3, 3> v = face_corners(q, f);
        const Vec3 e1 = v[1] - v[0], e2 = v[2] - v[0], p = glm::cross(d, e2);
        const double det = glm::dot(e1, p);
        if (det == 0) return false;
        const Vec3 sv = o - v[0], qv = glm::cross(sv, e1);
        root = {glm::dot(e2, qv) / det, f, glm::cross(e1, e2), glm::dot(sv, p) / det,
                glm::dot(d, qv) / det};
        return root.t > 0 && std::isfinite(root.t);
    }

    // The faces (placed primitive, face) whose edge or corner the ray passes
    // within rounding of.
    std::vector<std::pair<int, int>> faces_through(const Vec3& o, const Vec3& d) const {
        std::vector<std::pair<int, int>> found;
        for (int k = 0; k < static_cast<int>(placed_.size()); ++k) {
            const Placed& q = placed_[k];
            const bool loose = shape_is<Triangle>(*q.shape);
            if (!loose && !q.model) continue;
            const int faces = loose ? 1 : static_cast<int>(q.model->faces.size());
            for (int f = 0; f < faces; ++f) {
                Root r;
                if (!plane_root(q, f, o, d, r)) continue;
                const double least = std::min({r.u, r.v, 1 - r.u - r.v});
                if (std::abs(least) <= kEdgeGraze) found.emplace_back(k, f);
            }
        }
        return found;
    }

    // The triangles (placed primitive, face) other than the nearest surface
    // that the ray meets within kTriangleTie of it, when that surface is a
    // triangle: a single-precision test may meet any of them first.
    std::vector<std::pair<int, int>> faces_tied(const Vec3& o, const Vec3& d) const {
        Hit best;
        std::vector<Hit> triangles;
        for (int k = 0; k < static_cast<int>(placed_.size()); ++k) {
            roots(k, o, d, {}, [&](const Root& root) {
                if (root.t < best.t) best = {root.t, k, root};
                if (is_triangle(k)) triangles.push_back({root.t, k, root});
            });
        }
        std::vector<std::pair<int, int>> found;
        if (best.placed < 0 || !is_triangle(best.placed)) return found;
        for (const Hit& h : triangles)
            if (!(h.placed == best.placed && h.root.part == best.root.part) &&
                triangle_tied(best, h.placed, h.t, d, best.t))
                found.emplace_back(h.placed, h.root.part);
        return found;
    }

    // Whether faces f and g of the model have a corner at the same position.
    static bool shares_corner(const Model& m, int f, int g) {
        for (int i : m.faces[f])
            for (int j : m.faces[g])
                if (m.positions[i] == m.positions[j]) return true;
        return false;
    }

    // Whether the plane of triangle abc passes through p, up to rounding.
    static bool holds(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& p) {
        const Vec3 n = glm::normalize(glm::cross(b - a, c - a));
        return std::abs(glm::dot(n, p - a)) <= 1e-12 * (max_abs(a) + max_abs(p - a));
    }

    // The nearest hit; equal distances go to the lower primitive index.
    Hit nearest(const Vec3& o, const Vec3& d, const Origin& start, double magnitude,
                Flags& flags) const {
        Origin from = start;
        if (flags.widen_secondary && from.placed >= 0) from.edge_slack = kEdgeGraze;
        Hit best;
        double second = INFINITY;
        bool second_triangle = false;  // the second root is a triangle's
        for (int k = 0; k < static_cast<int>(placed_.size()); ++k) {
            roots(k, o, d, from, [&](const Root& root) {
                const double t = root.t;
                if (near_start(k, t, d, from, magnitude)) flags.ambiguous = true;
                if (t < best.t) {
                    second = best.t;
                    second_triangle = best.placed >= 0 && is_triangle(best.placed);
                    best = {t, k, root};
                } else if (t < second) {
                    second = t;
                    second_triangle = is_triangle(k);
                }
            });
        }
        // Which of two triangles a ray meets first is decided in single
        // precision (docs/language.md §13.5: Embree's float test picks the
        // triangle, and only its hit is refined in double).
        const double tie =
            best.placed >= 0 && is_triangle(best.placed) && second_triangle ? kTriangleTie : 1e-8;
        bool tied = second - best.t <= tie * std::max(best.t, magnitude);
        if (tied && placed_[best.placed].own_extent > 0)
            tied = tied_past_own_faces(o, d, from, magnitude, best);
        if (tied) flags.ambiguous = true;
        return best;
    }

    // Whether a triangle's root at t on placed primitive k lies within a
    // single-precision test's rounding of `best`, the nearest hit (a
    // triangle), along unit direction d: relative to `length`, or, for two
    // faces of an ill-conditioned mesh, to the model's size in its own space.
    bool triangle_tied(const Hit& best, int k, double t, const Vec3& d, double length) const {
        const Placed& q = placed_[best.placed];
        if (k == best.placed && q.own_extent > 0)
            return (t - best.t) * max_abs(q.world_to_object.linear * d) <=
                   kTriangleTie * q.own_extent;
        return t - best.t <= kTriangleTie * length;
    }

    // nearest()'s tie when `best` is a face of an ill-conditioned mesh: its
    // own faces weighed in its model's space, the other surfaces as before.
    bool tied_past_own_faces(const Vec3& o, const Vec3& d, const Origin& from, double magnitude,
                             const Hit& best) const {
        double second = INFINITY;
        bool second_triangle = false, own = false;
        for (int k = 0; k < static_cast<int>(placed_.size()); ++k) {
            roots(k, o, d, from, [&](const Root& root) {
                if (k != best.placed) {
                    if (root.t < second) second = root.t, second_triangle = is_triangle(k);
                } else if (root.part != best.root.part) {
                    own = own || triangle_tied(best, k, root.t, d, 0);
                }
            });
        }
        const double tie = second_triangle ? kTriangleTie : 1e-8;
        return own || second - best.t <= tie * std::max(best.t, magnitude);
    }

    // Whether a root at t on placed primitive k, along unit direction d, lies
    // within rounding of the start of a secondary ray that leaves `from`:
    // within 1e-6 of the scene's magnitude, where a surface touches the one
    // it leaves. Another face of the ill-conditioned mesh it leaves is weighed
    // in the model's own space, where §13.5 walks the ray: within 1e-6 of the
    // model's size there (across a sliver, a face 1e-7 of the magnitude on
    // may lie 1e-2 of the model's size on), or within twice ε, near the
    // cut-off a neighbour face is met beyond.
    bool near_start(int k, double t, const Vec3& d, const Origin& from, double magnitude) const {
        if (from.placed < 0) return false;
        const Placed& q = placed_[k];
        if (k == from.placed && q.own_extent > 0)
            return t * max_abs(q.world_to_object.linear * d) <= kTriangleTie * q.own_extent ||
                   t <= 2 * from.epsilon;
        return t < 1e-6 * magnitude;
    }

    bool q_is_mesh(int k) const { return placed_[k].model != nullptr; }

    // A triangle or a mesh: its hits are found in single precision.
    bool is_triangle(int k) const {
        return placed_[k].model != nullptr || shape_is<Triangle>(*placed_[k].shape);
    }

    // A unit smooth normal whose dot product with the unit geometric one is
    // within this of 0 may come out on either side of the face: both are
    // products of the map's inverse transpose, rounded in double precision,
    // and an ill-conditioned map scales their rounding by its condition.
    static constexpr double kInPlaneNormal = 1e-9;

    // R.V below minus this is negative under any renderer's rounding.
    static constexpr double kSpecularCutOffMargin = 1e-9;

    // Two triangles' hits nearer each other than this (relative) along a ray
    // are within the rounding of a single-precision test, some ulps of 6e-8.
    static constexpr double kTriangleTie = 1e-6;

    // A ray nearer than this (barycentric) to a triangle's edge may pass on
    // either side of it in a single-precision test: Embree tests a mesh's
    // triangles in floats in the mesh's space, where the ray's origin and
    // every product round at some ulps of 6e-8 of coordinates a few times
    // the triangle's size (§13.5 allows the core that).
    static constexpr double kEdgeGraze = 1e-6;

    // Farther than this (barycentric) outside a triangle, a double-precision
    // test puts a ray outside it, in the reference's rounding and the core's
    // alike (both move the ray into the model's space in double precision).
    static constexpr double kNeighbourOutside = 1e-9;

    // Flags a shadow ray that passes within kEdgeGraze of an edge of a
    // triangle farther than 1e-6 (relative) from its start and nearer than
    // the light; with flags.turn_grazes, the direction of the ray turned just
    // across the first such edge (into the triangle when it passes outside,
    // out of it when inside), which a single-precision test may have seen.
    std::optional<Vec3> graze(const Vec3& o, const Vec3& d, double distance, const Origin& from,
                              double magnitude, Flags& flags) const {
        for (int k = 0; k < static_cast<int>(placed_.size()); ++k) {
            if (!is_triangle(k)) continue;
            const Placed& q = placed_[k];
            const int faces = q.model ? static_cast<int>(q.model->faces.size()) : 1;
            for (int f = 0; f < faces; ++f) {
                if (from.placed == k && f == from.part) continue;
                Root r;
                if (!plane_root(q, f, o, d, r) || r.t <= 1e-6 * magnitude || !(r.t < distance))
                    continue;
                const double least = std::min({r.u, r.v, 1 - r.u - r.v});
                if (std::abs(least) > kEdgeGraze) continue;
                // §13.5: a face that shares a corner with the one the ray
                // leaves is met only where the ray, in double precision,
                // passes inside it: one passed outside is never met.
                if (from.placed == k && q.model && least < -kNeighbourOutside &&
                    shares_corner(*q.model, f, from.part))
                    continue;
                flags.edge_grazed = true;
                flags.grazed = true;
                if (!flags.turn_grazes) continue;
                const std::array<Vec3, 3> v = face_corners(q, f);
                const Vec3 at = (1 - r.u - r.v) * v[0] + r.u * v[1] + r.v * v[2];
                const double step = least < 0 ? 1e-6 - 4 * least : -(1e-6 + 4 * least);
                const Vec3 aim = at + step * ((v[0] + v[1] + v[2]) / 3.0 - at);
                const Vec3 world = q.object_to_world.linear * aim + q.object_to_world.translation;
                return glm::normalize(world - o);
            }
        }
        return std::nullopt;
    }

    // The fraction of a light that reaches across `distance`: 0 when an opaque
    // surface is in the way; with transmissive surfaces in the scene, the
    // product of the transmission of every crossing (one a distance on a mesh,
    // where two faces share an edge) (§13.2). Sets flags.edge_grazed when the
    // ray passes within rounding of an edge and no opaque surface blocks it
    // whatever rounding does: one met well inside its edges, not near the
    // ray's start or end. Behind such a surface an edge grazed cannot matter.
    double light_through(const Vec3& o, const Vec3& d, double distance, const Origin& from,
                         double magnitude, Flags& flags) const {
        flags.edge_grazed = false;
        if (const std::optional<Vec3> turned = graze(o, d, distance, from, magnitude, flags)) {
            Flags once = flags;
            once.turn_grazes = false;
            const double through = light_through(o, *turned, distance, from, magnitude, once);
            flags.ambiguous = flags.ambiguous || once.ambiguous;
            return through;
        }
        double through = 1.0;
        bool blocked = false;  // by an opaque surface, under any rounding
        for (int k = 0; k < static_cast<int>(placed_.size()); ++k) {
            std::vector<double> crossings;
            const bool opaque = !transmissive_ || placed_[k].material->finish->transmission == 0;
            roots(k, o, d, from, [&](const Root& root) {
                const double t = root.t;
                const bool near = near_start(k, t, d, from, magnitude) ||
                                  std::abs(t - distance) <= 1e-8 * magnitude;
                if (near) flags.ambiguous = true;
                if (t < distance) crossings.push_back(t);
                if (opaque && t < distance && !near &&
                    (!is_triangle(k) ||
                     std::min({root.u, root.v, 1 - root.u - root.v}) > kEdgeGraze))
                    blocked = true;
            });
            std::sort(crossings.begin(), crossings.end());
            for (std::size_t c = 0; c < crossings.size(); ++c) {
                if (c > 0 && q_is_mesh(k) &&
                    crossings[c] - crossings[c - 1] <= 1e-12 * crossings[c])
                    continue;
                through *= transmissive_ ? placed_[k].material->finish->transmission : 0.0;
            }
        }
        if (blocked) flags.edge_grazed = false;
        return through;
    }

    // How far the lifted variant's secondary rays leaving a hit on q (unit
    // normal ng, at `scale`) start off it: 1e-7 of the magnitude, or, off an
    // ill-conditioned mesh, no farther than what near_start() calls near its
    // faces, twice ε in the world or 1e-6 of the model's size in its space,
    // whichever is longer. There the whole 1e-7, 100 ε, may be 1e-3 of the
    // model's size: across a sliver of the mesh (a glass tetrahedron 9e-6
    // across where a refracted ray enters, lifted 1.5e-5) a ray would start
    // past a far face that §8.5's lift and §13.5's walk in the model's space
    // meet without doubt, a colour no renderer gives. Surfaces near the start
    // that the shorter lift does not pass are flagged all the same: within
    // 1e-6 of the magnitude (near_start()).
    double lift_off(const Placed& q, const Vec3& ng, double scale) const {
        const double lift = 1e-7 * scale;
        if (!(q.own_extent > 0)) return lift;
        const double near = std::max(
            2e-9 * scale, kTriangleTie * q.own_extent / max_abs(q.world_to_object.linear * ng));
        return std::min(lift, near);
    }

    // docs/language.md §8.5. `lifted`: secondary rays start 1e-7 of the magnitude off
    // the surface and meet every surface, their own included.
    Colour trace(const Vec3& o, const Vec3& d, int depth, const Origin& from, double magnitude,
                 bool lifted, Flags& flags, double weight = 1.0) const {
        Hit hit = nearest(o, d, from, magnitude, flags);
        Root forced;
        if (depth == 0 && flags.force_placed >= 0 &&
            plane_root(placed_[flags.force_placed], flags.force_face, o, d, forced) &&
            (hit.placed < 0 || forced.t <= hit.t * (1 + flags.force_slack)))
            hit = {forced.t, flags.force_placed, forced};
        if (hit.placed < 0) {
            const Colour missed = sky_ ? sky(*sky_, d) : scene_.settings.background;
            if (sky_) flags.varies = true;
            if (depth == 0) flags.colour = missed;
            return missed;
        }
        const Placed& q = placed_[hit.placed];
        const Material& m = *q.material;
        const Vec3 p = o + hit.t * d;
        const Root& root = hit.root;
        // Ng, outward (M^-T of the object's outward normal), then facing the ray.
        const Vec3 outward = glm::normalize(q.normal_matrix * root.normal);
        const bool entering = glm::dot(d, outward) < 0;
        const Vec3 ng = entering ? outward : -outward;
        Vec3 n = ng;
        const double w = 1 - root.u - root.v;
        if (!q.corner_normals.empty()) {
            const std::array<Vec3, 3>& corner = q.corner_normals[root.part];
            const Vec3 blend = w * corner[0] + root.u * corner[1] + root.v * corner[2];
            if (blend != Vec3(0.0)) {
                n = glm::normalize(q.normal_matrix * blend);
                // A smooth normal in the face's plane (as when the file's
                // normals at its three corners lie in it): the side it turns
                // to is the sign of a dot product that rounds about 0.
                const double side = glm::dot(n, ng);
                if (std::abs(side) <= kInPlaneNormal) flags.in_plane = true;
                if (side < 0) n = -n;
                if (flags.turn_in_plane && std::abs(side) <= kInPlaneNormal) n = -n;
            }
        }
        Colour pigment = m.pigment;
        if (q.file_materials && !q.model->face_part.empty() && q.model->face_part[root.part] >= 0)
            pigment = q.model->part_colours[q.model->face_part[root.part]];
        else if (q.picture) {
            const auto* t = shape_if<Triangle>(q.shape);
            const Vec3 uv = t ? w * t->uv_a + root.u * t->uv_b + root.v * t->uv_c : Vec3(0.0);
            pigment = bilinear(*q.picture, uv.x, uv.y);
            flags.varies = true;
        }
        const Vec3 v = -d;
        const double scale = std::max({max_abs(o), max_abs(p), hit.t});
        const Vec3 object_point = q.world_to_object.linear * p + q.world_to_object.translation;
        const Origin here{hit.placed, root.part, object_point, lifted, 1e-9 * scale};
        const double lift = lifted ? lift_off(q, ng, scale) : 0.0;
        const Vec3 start = lifted ? p + lift * ng : p;

        Colour c = scene_.settings.ambient_light * m.finish->ambient * pigment;
        for (const PointLight& light : scene_.lights) {
            if (light.radius > 0) {
                c += disk_light(light, p, n, ng, v, m, pigment, start, here, scale, lift, flags,
                                weight);
                continue;
            }
            const Vec3 l = glm::normalize(light.position - p);
            const double n_dot_l = glm::dot(n, l);
            if (n_dot_l <= 0) continue;
            const Vec3 reflected = 2 * n_dot_l * n - l;
            const double r_dot_v = glm::dot(reflected, v);
            // A light whose diffuse and specular terms are both zero here adds
            // nothing whatever reaches it: its shadow ray cannot change the
            // colour, so what that ray passes within rounding of (an edge, a
            // surface at its start) leaves the pixel unambiguous. The
            // specular term counts as zero only well past its cut-off, where
            // no rounding of R.V turns it on.
            if (m.finish->diffuse * pigment == Colour(0.0) &&
                (m.finish->specular == Colour(0.0) || r_dot_v < -kSpecularCutOffMargin))
                continue;
            const Vec3 to_light = light.position - start;
            const double distance = glm::length(to_light);
            const double through =
                light_through(start, to_light / distance, distance, here, scale, flags);
            if (flags.edge_grazed)
                flags.graze_bound +=
                    weight * light_term(light.intensity, m, pigment, n_dot_l, r_dot_v);
            if (!(through > 0)) continue;
            flags.varies = true;
            const Colour intensity = light.intensity * through;
            c += intensity * m.finish->diffuse * pigment *
                 std::pow(n_dot_l, 1 / m.finish->diffuse_k);
            if (r_dot_v > 0)
                c += intensity * m.finish->specular * std::pow(r_dot_v, m.finish->specular_k);
        }
        // §13.2: with glass in the scene, a branch whose weight in the pixel is
        // below 1e-6 is not traced.
        auto traced = [&](double factor) { return !transmissive_ || weight * factor >= 1e-6; };
        if (depth < scene_.settings.recurse_depth && m.finish->reflection > 0 &&
            traced(m.finish->reflection)) {
            const Vec3 mirrored = glm::normalize(d - 2 * glm::dot(d, n) * n);
            c += m.finish->reflection * trace(start, mirrored, depth + 1, here, scale, lifted,
                                              flags, weight * m.finish->reflection);
        }
        if (depth < scene_.settings.recurse_depth && m.finish->transmission > 0 &&
            traced(m.finish->transmission)) {
            const double eta = entering ? 1 / m.finish->ior : m.finish->ior;
            const double cosi = -glm::dot(d, n);
            const double k = 1 - eta * eta * (1 - cosi * cosi);
            const Vec3 t = glm::normalize(k < 0 ? d + 2 * cosi * n
                                                : eta * d + (eta * cosi - std::sqrt(k)) * n);
            const Vec3 from = lifted ? p + (glm::dot(t, ng) > 0 ? lift : -lift) * ng : p;
            c += m.finish->transmission * trace(from, t, depth + 1, here, scale, lifted, flags,
                                                weight * m.finish->transmission);
        }
        if (depth == 0) flags.colour = c;
        return c;
    }

    // The diffuse and specular terms of a light of `intensity` that all reaches
    // a point, as trace() adds them.
    static Colour light_term(const Colour& intensity, const Material& m, const Colour& pigment,
                             double n_dot_l, double r_dot_v) {
        Colour c =
            intensity * m.finish->diffuse * pigment * std::pow(n_dot_l, 1 / m.finish->diffuse_k);
        if (r_dot_v > 0)
            c += intensity * m.finish->specular * std::pow(r_dot_v, m.finish->specular_k);
        return c;
    }

    // docs/language.md §14.1: the diffuse and specular terms of a light of radius
    // r > 0 at hit point p, its intensity scaled by the share of the points of
    // its disk that p sees. `start`: where the point light's shadow ray would
    // start (p, or p lifted along ng); `lift`: how far the lifted variant's
    // rays start off the surface (lift_off()), 0 for the others.
    Colour disk_light(const PointLight& light, const Vec3& p, const Vec3& n, const Vec3& ng,
                      const Vec3& v, const Material& m, const Colour& pigment, const Vec3& start,
                      const Origin& here, double scale, double lift, Flags& flags,
                      double weight) const {
        const Vec3 to = light.position - p;
        const double dist = std::sqrt(to.x * to.x + to.y * to.y + to.z * to.z);
        if (std::abs(dist - light.radius) <= 1e-9 * std::max(dist, scale)) flags.ambiguous = true;
        double vis = 1.0;
        const Vec3 l = dist <= light.radius ? glm::normalize(to) : to / dist;
        const double n_dot_l = glm::dot(n, l);
        if (n_dot_l <= 0) return Colour(0.0);
        // All of the light's term: what one shadow ray grazing an edge (of
        // `count`) may change by its share.
        const Colour full =
            light_term(light.intensity, m, pigment, n_dot_l, glm::dot(2 * n_dot_l * n - l, v));
        if (dist <= light.radius) {  // inside the light's sphere: a point light
            const Vec3 to_light = light.position - start;
            const double distance = glm::length(to_light);
            vis = light_through(start, to_light / distance, distance, here, scale, flags);
            if (flags.edge_grazed) flags.graze_bound += weight * full;
        } else {
            Vec3 e1 = glm::cross(l, Vec3(0, 1, 0));
            if (e1.x == 0 && e1.y == 0 && e1.z == 0) e1 = glm::cross(l, Vec3(1, 0, 0));
            e1 = glm::normalize(e1);
            const Vec3 e2 = glm::cross(l, e1);
            const int count = light.shadow_samples;
            const double phi = pixel_angle(flags.i, flags.j, flags.k);
            double sum = 0.0;
            for (int k = 0; k < count; ++k) {
                const double rho = light.radius * std::sqrt((k + 0.5) / count);
                const double theta = k * kGoldenAngle + phi;
                const Vec3 q = light.position + rho * (std::cos(theta) * e1 + std::sin(theta) * e2);
                const Vec3 lk = glm::normalize(q - p);
                const double horizon = glm::dot(n, lk);
                if (std::abs(horizon) <= 1e-9) flags.ambiguous = true;
                if (horizon <= 0) continue;
                // A smooth mesh's point below its own face leaves through it.
                const double side = glm::dot(ng, lk) < 0 ? -1.0 : 1.0;
                const Vec3 from = lift > 0 ? p + side * lift * ng : p;
                const Vec3 to_point = q - from;
                const double distance = glm::length(to_point);
                sum += light_through(from, to_point / distance, distance, here, scale, flags);
                if (flags.edge_grazed)
                    flags.graze_bound += weight * full / static_cast<double>(count);
            }
            vis = sum / count;
        }
        if (!(vis > 0)) return Colour(0.0);
        flags.varies = true;
        const Colour intensity = light.intensity * vis;
        Colour c =
            intensity * m.finish->diffuse * pigment * std::pow(n_dot_l, 1 / m.finish->diffuse_k);
        const Vec3 reflected = 2 * n_dot_l * n - l;
        const double r_dot_v = glm::dot(reflected, v);
        if (r_dot_v > 0)
            c += intensity * m.finish->specular * std::pow(r_dot_v, m.finish->specular_k);
        return c;
    }

    // docs/language.md §14.4: each corner's normal, the area-weighted sum of the
    // faces that share its position within `degrees` of the corner's face,
    // in file order (the face itself always counts).
    static std::vector<std::array<Vec3, 3>> generated_normals(const Model& model, double degrees) {
        const double limit = std::cos(degrees * std::numbers::pi / 180) - 1e-12;
        std::vector<Vec3> area, unit;
        for (const auto& face : model.faces) {
            const Vec3 a = model.positions[face[0]], b = model.positions[face[1]],
                       c = model.positions[face[2]];
            area.push_back(glm::cross(b - a, c - a));
            unit.push_back(glm::normalize(area.back()));
        }
        std::vector<std::array<Vec3, 3>> out(model.faces.size());
        for (std::size_t f = 0; f < model.faces.size(); ++f) {
            for (int corner = 0; corner < 3; ++corner) {
                const Vec3 at = model.positions[model.faces[f][corner]];
                Vec3 sum(0.0);
                for (std::size_t g = 0; g < model.faces.size(); ++g) {
                    bool shares = false;
                    for (int k : model.faces[g]) shares = shares || model.positions[k] == at;
                    if (shares && (g == f || glm::dot(unit[f], unit[g]) >= limit)) sum += area[g];
                }
                out[f][corner] = sum == Vec3(0.0) ? unit[f] : glm::normalize(sum);
            }
        }
        return out;
    }

    // docs/language.md §14.3: the sky map in unit direction d, u wrapped, v held
    // at the poles.
    static Colour sky(const Picture& picture, const Vec3& d) {
        const double u = 0.5 + std::atan2(d.x, -d.z) / (2 * std::numbers::pi);
        const double v = 0.5 + std::asin(std::clamp(d.y, -1.0, 1.0)) / std::numbers::pi;
        const double wrapped = u - std::floor(u) < 1 ? u - std::floor(u) : 0.0;
        const double x = wrapped * picture.width - 0.5;
        const double y = std::clamp(v * picture.height - 0.5, 0.0, picture.height - 1.0);
        const double fx = std::floor(x), fy = std::floor(y);
        const int row0 = static_cast<int>(fy), row1 = std::min(row0 + 1, picture.height - 1);
        auto column = [&](double i) {
            const long long m = static_cast<long long>(i) % picture.width;
            return static_cast<int>(m < 0 ? m + picture.width : m);
        };
        auto texel = [&](double i, int row) {
            const std::uint8_t* t =
                &picture.rgb[3 * (static_cast<std::size_t>(row) * picture.width + column(i))];
            return Colour(t[0] / 255.0f, t[1] / 255.0f, t[2] / 255.0f);
        };
        const Colour bottom = (1 - (x - fx)) * texel(fx, row0) + (x - fx) * texel(fx + 1, row0);
        const Colour top = (1 - (x - fx)) * texel(fx, row1) + (x - fx) * texel(fx + 1, row1);
        return (1 - (y - fy)) * bottom + (y - fy) * top;
    }

    // The bilinear blend of the four texel centres nearest (u, v), wrapped
    // round both edges (§13.4), each channel byte / 255 in single precision.
    static Colour bilinear(const Picture& picture, double u, double v) {
        auto wrap = [](double x) { return x - std::floor(x) < 1 ? x - std::floor(x) : 0.0; };
        const double x = wrap(u) * picture.width - 0.5, y = wrap(v) * picture.height - 0.5;
        const double fx = std::floor(x), fy = std::floor(y);
        auto index = [](double k, int n) {
            const long long m = static_cast<long long>(k) % n;
            return static_cast<int>(m < 0 ? m + n : m);
        };
        auto texel = [&](double i, double j) {
            const std::uint8_t* t =
                &picture
                     .rgb[3 * (static_cast<std::size_t>(index(j, picture.height)) * picture.width +
                               index(i, picture.width))];
            return Colour(t[0] / 255.0f, t[1] / 255.0f, t[2] / 255.0f);
        };
        const Colour bottom = (1 - (x - fx)) * texel(fx, fy) + (x - fx) * texel(fx + 1, fy);
        const Colour top = (1 - (x - fx)) * texel(fx, fy + 1) + (x - fx) * texel(fx + 1, fy + 1);
        return (1 - (y - fy)) * bottom + (y - fy) * top;
    }

    const Scene& scene_;
    std::vector<Placed> placed_;
    bool transmissive_ = false;
    const Picture* sky_ = nullptr;  // the background map, when the scene has one
};

// The camera docs/language.md §7.1 says renders: the one named by active_camera, else the first.
inline int active_camera(const Scene& scene) {
    for (std::size_t i = 0; i < scene.cameras.size(); ++i)
        if (!scene.settings.active_camera.empty() &&
            scene.cameras[i].name == scene.settings.active_camera)
            return static_cast<int>(i);
    return 0;
}

inline ReferenceImage render(const Scene& scene, const Files& files = {}) {
    return Tracer(scene, files).render(active_camera(scene));
}

}  // namespace jt::reference
