// The SIMD lanes' arithmetic (AVX2, four doubles, one per vertex or constraint), for the lane loops of
// vertex_move_lanes.cpp and correction_lanes.cpp. Only plain IEEE operations (no fused multiply-add: the functions are
// compiled for target("avx2") alone), so that a lane evaluating the scalar code's expressions in its order gives its
// bits. Included by those two files only, on x86-64.
#pragma once

#if defined(__x86_64__)

#include <immintrin.h>

#include <cstddef>
#include <span>
#include <vector>

#include "core/vec.hpp"

#define SOFTBODY_LANES_TARGET __attribute__((target("avx2")))

namespace sim::lane_math {

using softbody::Vec3;
using Lane = __m256d;  // one double per vertex or constraint

SOFTBODY_LANES_TARGET inline Lane splat(double a) { return _mm256_set1_pd(a); }
SOFTBODY_LANES_TARGET inline Lane lanes_of(double a0, double a1, double a2, double a3) {
  return _mm256_set_pd(a3, a2, a1, a0);
}
SOFTBODY_LANES_TARGET inline Lane select(Lane mask, Lane a, Lane b) { return _mm256_blendv_pd(b, a, mask); }
SOFTBODY_LANES_TARGET inline Lane negate(Lane a) { return _mm256_xor_pd(a, splat(-0.0)); }
SOFTBODY_LANES_TARGET inline Lane less(Lane a, Lane b) { return _mm256_cmp_pd(a, b, _CMP_LT_OQ); }
SOFTBODY_LANES_TARGET inline Lane any_of(Lane a, Lane b) { return _mm256_or_pd(a, b); }

// A vector per lane, each component as one Lane.
struct Lane3 {
  Lane x, y, z;
};
SOFTBODY_LANES_TARGET inline Lane3 gather(std::span<const Vec3> p, const std::size_t* i) {
  return {lanes_of(p[i[0]].x(), p[i[1]].x(), p[i[2]].x(), p[i[3]].x()),
          lanes_of(p[i[0]].y(), p[i[1]].y(), p[i[2]].y(), p[i[3]].y()),
          lanes_of(p[i[0]].z(), p[i[1]].z(), p[i[2]].z(), p[i[3]].z())};
}
SOFTBODY_LANES_TARGET inline Lane3 minus(const Lane3& a, const Lane3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
SOFTBODY_LANES_TARGET inline Lane3 plus(const Lane3& a, const Lane3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
SOFTBODY_LANES_TARGET inline Lane3 times(Lane a, const Lane3& u) { return {a * u.x, a * u.y, a * u.z}; }
// (a_x b_x + a_y b_y) + a_z b_z: Eigen's order for Vec3::dot and squaredNorm.
SOFTBODY_LANES_TARGET inline Lane dot(const Lane3& a, const Lane3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// The names that the lane loops written for any width use (vertex_move_lanes.inc; lane_math_avx512.hpp has the
// same for eight lanes). A lane's mask is a Lane here, all bits set where true.
inline constexpr int kWidth = 4;
using Mask = Lane;
SOFTBODY_LANES_TARGET inline Mask all_lanes() { return _mm256_castsi256_pd(_mm256_set1_epi64x(-1)); }
SOFTBODY_LANES_TARGET inline Mask both(Mask a, Mask b) { return _mm256_and_pd(a, b); }
template <int kPredicate>
SOFTBODY_LANES_TARGET inline Mask compare(Lane a, Lane b) {
  return _mm256_cmp_pd(a, b, kPredicate);
}
SOFTBODY_LANES_TARGET inline unsigned mask_bits(Mask m) { return static_cast<unsigned>(_mm256_movemask_pd(m)); }
SOFTBODY_LANES_TARGET inline Lane root(Lane a) { return _mm256_sqrt_pd(a); }
SOFTBODY_LANES_TARGET inline Lane lane_numbers() { return lanes_of(0, 1, 2, 3); }
SOFTBODY_LANES_TARGET inline Lane from_ints(const int* a) { return lanes_of(a[0], a[1], a[2], a[3]); }
SOFTBODY_LANES_TARGET inline Lane load(const double* a) { return _mm256_loadu_pd(a); }
SOFTBODY_LANES_TARGET inline void store(double* to, Lane a) { _mm256_storeu_pd(to, a); }
SOFTBODY_LANES_TARGET inline Lane gather(std::span<const double> a, const std::size_t* i) {
  return lanes_of(a[i[0]], a[i[1]], a[i[2]], a[i[3]]);
}

}  // namespace sim::lane_math

#endif
