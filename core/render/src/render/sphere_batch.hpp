#pragma once
// The early answers of intersect_sphere for a few listed spheres at once.
//
// A list walk offers most spheres only to have intersect_sphere's first tests
// (starting outside and heading away, passes_wide_of_sphere, enters_beyond)
// answer no_hit. Those tests take a handful of multiplications each, and the
// same ones for every sphere: here they run in double-precision vector lanes,
// one sphere a lane. Every lane computes the same IEEE operations on the same
// operands as the scalar code (lane-wise, no fused multiply-add, no
// reassociation), so a lane it decides is a sphere the scalar test answers
// no_hit for; the walk gives every other lane to the scalar test.

#include "geometry/intersect.hpp"
#include "jtracer/vector_unit.hpp"
#include "render/prepared_scene.hpp"

#include <cstddef>
#include <cstdint>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

namespace jt {

// sphere_batch (spheres decided at once: two SSE2 registers a value) and
// SphereLanes are in prepared_scene.hpp, whose ShapeGroups hold batches.

#if defined(__SSE2__)

// A ray's values in both lanes of a register, made once a walk.
struct BatchRay {
    __m128d ox, oy, oz;  // origin
    __m128d dx, dy, dz;  // direction
    __m128d a;           // dot(direction, direction), as intersect_sphere computes it
    // Whether |d|^2 is large enough for the answers that need it.
    bool scaled;
    // intersect_sphere gives the exact roots every ray starting at a
    // negative t_min that does not pass wide.
    bool from_ahead;
};

inline BatchRay batch_ray(const Vec3& origin, const Vec3& direction, double t_min) {
    const double a = glm::dot(direction, direction);
    return {_mm_set1_pd(origin.x),    _mm_set1_pd(origin.y),           _mm_set1_pd(origin.z),
            _mm_set1_pd(direction.x), _mm_set1_pd(direction.y),        _mm_set1_pd(direction.z),
            _mm_set1_pd(a),           a > smallest_early_answer_scale, t_min >= 0.0};
}

// The early tests of intersect_sphere for the two spheres p and q, lane 0
// and lane 1 of each register; one bit a lane, lane 0 in bit 0. `t` holds
// t_max in both lanes.
template <bool DecideEntryBeyond>
inline unsigned pair_missed_early(__m128d cx, __m128d cy, __m128d cz, __m128d r,
                                  const BatchRay& ray, __m128d t) {
    const __m128d fx = _mm_sub_pd(ray.ox, cx);
    const __m128d fy = _mm_sub_pd(ray.oy, cy);
    const __m128d fz = _mm_sub_pd(ray.oz, cz);
    // glm::dot sums (x + y) + z.
    const __m128d b = _mm_add_pd(_mm_add_pd(_mm_mul_pd(fx, ray.dx), _mm_mul_pd(fy, ray.dy)),
                                 _mm_mul_pd(fz, ray.dz));
    const __m128d ff =
        _mm_add_pd(_mm_add_pd(_mm_mul_pd(fx, fx), _mm_mul_pd(fy, fy)), _mm_mul_pd(fz, fz));
    const __m128d c = _mm_sub_pd(ff, _mm_mul_pd(r, r));
    const __m128d zero = _mm_setzero_pd();
    const __m128d outside_start = _mm_cmpgt_pd(c, zero);
    __m128d missed = ray.from_ahead ? _mm_and_pd(outside_start, _mm_cmpge_pd(b, zero)) : zero;
    if (!ray.scaled) return static_cast<unsigned>(_mm_movemask_pd(missed));
    const __m128d scaled = _mm_cmpgt_pd(ff, _mm_set1_pd(smallest_early_answer_scale));
    const __m128d wide_margin =
        _mm_mul_pd(_mm_set1_pd(wide_miss_margin_ulps * 0x1p-53), _mm_mul_pd(ff, ray.a));
    const __m128d wide =
        _mm_cmpgt_pd(_mm_sub_pd(_mm_mul_pd(ray.a, c), _mm_mul_pd(b, b)), wide_margin);
    missed = _mm_or_pd(missed, _mm_and_pd(scaled, wide));
    if (DecideEntryBeyond && ray.from_ahead) {
        const __m128d approach = _mm_add_pd(_mm_mul_pd(ray.a, t), b);
        const __m128d outside = _mm_add_pd(_mm_mul_pd(_mm_add_pd(approach, b), t), c);
        const __m128d entry_margin =
            _mm_mul_pd(_mm_set1_pd(entry_beyond_margin_ulps * 0x1p-53), ff);
        const __m128d beyond = _mm_and_pd(_mm_and_pd(outside_start, _mm_cmplt_pd(approach, zero)),
                                          _mm_and_pd(scaled, _mm_cmpgt_pd(outside, entry_margin)));
        missed = _mm_or_pd(missed, beyond);
    }
    return static_cast<unsigned>(_mm_movemask_pd(missed));
}

template <bool DecideEntryBeyond>
inline unsigned sphere_pair_missed_early(const WorldSphere& p, const WorldSphere& q,
                                         const BatchRay& ray, __m128d t) {
    // _mm_set_pd takes the high lane first.
    return pair_missed_early<DecideEntryBeyond>(
        _mm_set_pd(q.center.x, p.center.x), _mm_set_pd(q.center.y, p.center.y),
        _mm_set_pd(q.center.z, p.center.z), _mm_set_pd(q.radius, p.radius), ray, t);
}

// Which of `spheres` (lane k the sphere spheres[k]) intersect_sphere<
// DecideEntryBeyond>(origin, direction, centre, radius, t_min, t) answers
// no_hit for by its early tests, for every t <= t_max, `ray` being made of
// origin, direction and t_min: starting outside and heading away and passing
// wide do not depend on t, and an entry beyond t_max is beyond any nearer t.
// One bit a lane, lane k in bit k.
template <bool DecideEntryBeyond>
inline unsigned spheres_missed_early(const WorldSphere* const (&spheres)[sphere_batch],
                                     const BatchRay& ray, double t_max) {
    const __m128d t = _mm_set1_pd(t_max);
    return sphere_pair_missed_early<DecideEntryBeyond>(*spheres[0], *spheres[1], ray, t) |
           sphere_pair_missed_early<DecideEntryBeyond>(*spheres[2], *spheres[3], ray, t) << 2;
}

// spheres_missed_early of the four spheres of `s`.
template <bool DecideEntryBeyond>
inline unsigned lanes_missed_early(const SphereLanes& s, const BatchRay& ray, double t_max) {
    const __m128d t = _mm_set1_pd(t_max);
    return pair_missed_early<DecideEntryBeyond>(_mm_load_pd(s.x), _mm_load_pd(s.y),
                                                _mm_load_pd(s.z), _mm_load_pd(s.r), ray, t) |
           pair_missed_early<DecideEntryBeyond>(_mm_load_pd(s.x + 2), _mm_load_pd(s.y + 2),
                                                _mm_load_pd(s.z + 2), _mm_load_pd(s.r + 2), ray, t)
               << 2;
}

#if defined(__x86_64__)
#define JT_SPHERE_BATCH_AVX 1
// Whether this process runs spheres_missed_early_avx: the CPU has AVX and
// JTRACER_SIMD does not ask for SSE2 (jtracer/vector_unit.hpp).
inline bool sphere_batch_avx() {
    static const bool avx = vector_unit().unit == VectorUnit::avx;
    return avx;
}

// spheres_missed_early in one AVX register a value, for processors that have
// it: the same operations, four lanes at a time. AVX only, never FMA, so
// that no multiplication and addition fuse.
template <bool DecideEntryBeyond>
__attribute__((target("avx"), always_inline)) inline unsigned quad_missed_early_avx(
    __m256d cx, __m256d cy, __m256d cz, __m256d r, const BatchRay& ray, double t_max) {
    const __m256d fx = _mm256_sub_pd(_mm256_broadcast_pd(&ray.ox), cx);
    const __m256d fy = _mm256_sub_pd(_mm256_broadcast_pd(&ray.oy), cy);
    const __m256d fz = _mm256_sub_pd(_mm256_broadcast_pd(&ray.oz), cz);
    const __m256d av = _mm256_broadcast_pd(&ray.a);
    // glm::dot sums (x + y) + z.
    const __m256d b = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(fx, _mm256_broadcast_pd(&ray.dx)),
                                                  _mm256_mul_pd(fy, _mm256_broadcast_pd(&ray.dy))),
                                    _mm256_mul_pd(fz, _mm256_broadcast_pd(&ray.dz)));
    const __m256d ff = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(fx, fx), _mm256_mul_pd(fy, fy)),
                                     _mm256_mul_pd(fz, fz));
    const __m256d c = _mm256_sub_pd(ff, _mm256_mul_pd(r, r));
    const __m256d zero = _mm256_setzero_pd();
    // The predicates of the SSE2 comparisons: ordered, false on a NaN.
    const __m256d outside_start = _mm256_cmp_pd(c, zero, _CMP_GT_OS);
    __m256d missed =
        ray.from_ahead ? _mm256_and_pd(outside_start, _mm256_cmp_pd(b, zero, _CMP_GE_OS)) : zero;
    if (!ray.scaled) return static_cast<unsigned>(_mm256_movemask_pd(missed));
    const __m256d scaled =
        _mm256_cmp_pd(ff, _mm256_set1_pd(smallest_early_answer_scale), _CMP_GT_OS);
    const __m256d wide_margin =
        _mm256_mul_pd(_mm256_set1_pd(wide_miss_margin_ulps * 0x1p-53), _mm256_mul_pd(ff, av));
    const __m256d wide = _mm256_cmp_pd(_mm256_sub_pd(_mm256_mul_pd(av, c), _mm256_mul_pd(b, b)),
                                       wide_margin, _CMP_GT_OS);
    missed = _mm256_or_pd(missed, _mm256_and_pd(scaled, wide));
    if (DecideEntryBeyond && ray.from_ahead) {
        const __m256d t = _mm256_set1_pd(t_max);
        const __m256d approach = _mm256_add_pd(_mm256_mul_pd(av, t), b);
        const __m256d outside = _mm256_add_pd(_mm256_mul_pd(_mm256_add_pd(approach, b), t), c);
        const __m256d entry_margin =
            _mm256_mul_pd(_mm256_set1_pd(entry_beyond_margin_ulps * 0x1p-53), ff);
        const __m256d beyond =
            _mm256_and_pd(_mm256_and_pd(outside_start, _mm256_cmp_pd(approach, zero, _CMP_LT_OS)),
                          _mm256_and_pd(scaled, _mm256_cmp_pd(outside, entry_margin, _CMP_GT_OS)));
        missed = _mm256_or_pd(missed, beyond);
    }
    return static_cast<unsigned>(_mm256_movemask_pd(missed));
}

template <bool DecideEntryBeyond>
__attribute__((target("avx"))) unsigned spheres_missed_early_avx(
    const WorldSphere* const (&spheres)[sphere_batch], const BatchRay& ray, double t_max) {
    const WorldSphere& s0 = *spheres[0];
    const WorldSphere& s1 = *spheres[1];
    const WorldSphere& s2 = *spheres[2];
    const WorldSphere& s3 = *spheres[3];
    // _mm256_set_pd takes the highest lane first.
    return quad_missed_early_avx<DecideEntryBeyond>(
        _mm256_set_pd(s3.center.x, s2.center.x, s1.center.x, s0.center.x),
        _mm256_set_pd(s3.center.y, s2.center.y, s1.center.y, s0.center.y),
        _mm256_set_pd(s3.center.z, s2.center.z, s1.center.z, s0.center.z),
        _mm256_set_pd(s3.radius, s2.radius, s1.radius, s0.radius), ray, t_max);
}

// lanes_missed_early in AVX.
template <bool DecideEntryBeyond>
__attribute__((target("avx"))) unsigned lanes_missed_early_avx(const SphereLanes& s,
                                                               const BatchRay& ray, double t_max) {
    return quad_missed_early_avx<DecideEntryBeyond>(_mm256_load_pd(s.x), _mm256_load_pd(s.y),
                                                    _mm256_load_pd(s.z), _mm256_load_pd(s.r), ray,
                                                    t_max);
}
#endif

#else

// Without SSE2 the lanes are taken one by one, with the same operations.
struct BatchRay {
    Vec3 origin, direction;
    double a;
    bool scaled;
    bool from_ahead;
};

inline BatchRay batch_ray(const Vec3& origin, const Vec3& direction, double t_min) {
    const double a = glm::dot(direction, direction);
    return {origin, direction, a, a > smallest_early_answer_scale, t_min >= 0.0};
}

template <bool DecideEntryBeyond>
inline unsigned spheres_missed_early(const WorldSphere* const (&spheres)[sphere_batch],
                                     const BatchRay& ray, double t_max) {
    unsigned missed = 0;
    for (std::size_t k = 0; k < sphere_batch; ++k) {
        const Vec3 f = ray.origin - spheres[k]->center;
        const double b = glm::dot(f, ray.direction);
        const double ff = glm::dot(f, f);
        const double c = ff - spheres[k]->radius * spheres[k]->radius;
        if ((c > 0.0 && b >= 0.0 && ray.from_ahead) || passes_wide_of_sphere(ray.a, b, c, ff) ||
            (DecideEntryBeyond && ray.from_ahead && enters_beyond(ray.a, b, c, ff, t_max)))
            missed |= 1u << k;
    }
    return missed;
}

template <bool DecideEntryBeyond>
inline unsigned lanes_missed_early(const SphereLanes& s, const BatchRay& ray, double t_max) {
    WorldSphere spheres[sphere_batch];
    const WorldSphere* lanes[sphere_batch];
    for (std::size_t k = 0; k < sphere_batch; ++k) {
        spheres[k] = {Vec3(s.x[k], s.y[k], s.z[k]), s.r[k], 0};
        lanes[k] = &spheres[k];
    }
    return spheres_missed_early<DecideEntryBeyond>(lanes, ray, t_max);
}

#endif

#if !defined(JT_SPHERE_BATCH_AVX)
inline bool sphere_batch_avx() {
    return false;
}
#endif

// spheres_missed_early and lanes_missed_early in AVX where `avx` (the walk's
// sphere_batch_avx(), read once) says so. Forced inline: the walks call them
// for every batch.
template <bool DecideEntryBeyond>
[[gnu::always_inline]] inline unsigned spheres_missed(
    bool avx, const WorldSphere* const (&spheres)[sphere_batch], const BatchRay& ray,
    double t_max) {
#if defined(JT_SPHERE_BATCH_AVX)
    if (avx) return spheres_missed_early_avx<DecideEntryBeyond>(spheres, ray, t_max);
#endif
    static_cast<void>(avx);
    return spheres_missed_early<DecideEntryBeyond>(spheres, ray, t_max);
}

template <bool DecideEntryBeyond>
[[gnu::always_inline]] inline unsigned lanes_missed(bool avx, const SphereLanes& lanes,
                                                    const BatchRay& ray, double t_max) {
#if defined(JT_SPHERE_BATCH_AVX)
    if (avx) return lanes_missed_early_avx<DecideEntryBeyond>(lanes, ray, t_max);
#endif
    static_cast<void>(avx);
    return lanes_missed_early<DecideEntryBeyond>(lanes, ray, t_max);
}

}  // namespace jt
