// lane_math.hpp's names for eight lanes (AVX-512F, eight doubles), for the lane loops written for any width
// (vertex_move_lanes.inc). Only plain IEEE operations: the functions are compiled for target("avx512f"), whose
// fused multiply-adds GCC would form from a * b + c, so a file that includes this header is compiled with
// -ffp-contract=off (CMakeLists.txt). A mask is a __mmask8, one bit per lane. Included by
// vertex_move_lanes_avx512.cpp only, on x86-64.
#pragma once

#if defined(__x86_64__)

#include <immintrin.h>

#include <cstddef>
#include <span>

#include "core/vec.hpp"

#define SOFTBODY_WIDE_LANES_TARGET __attribute__((target("avx512f")))

namespace sim::lane_math_avx512 {

using softbody::Vec3;
using Lane = __m512d;  // one double per vertex
using Mask = __mmask8;
inline constexpr int kWidth = 8;

SOFTBODY_WIDE_LANES_TARGET inline Lane splat(double a) { return _mm512_set1_pd(a); }
SOFTBODY_WIDE_LANES_TARGET inline Lane load(const double* a) { return _mm512_loadu_pd(a); }
SOFTBODY_WIDE_LANES_TARGET inline void store(double* to, Lane a) { _mm512_storeu_pd(to, a); }
SOFTBODY_WIDE_LANES_TARGET inline Lane select(Mask mask, Lane a, Lane b) { return _mm512_mask_blend_pd(mask, b, a); }
SOFTBODY_WIDE_LANES_TARGET inline Lane negate(Lane a) {
  return _mm512_castsi512_pd(_mm512_xor_si512(_mm512_castpd_si512(a), _mm512_castpd_si512(splat(-0.0))));
}
template <int kPredicate>
SOFTBODY_WIDE_LANES_TARGET inline Mask compare(Lane a, Lane b) {
  return _mm512_cmp_pd_mask(a, b, kPredicate);
}
SOFTBODY_WIDE_LANES_TARGET inline Mask less(Lane a, Lane b) { return compare<_CMP_LT_OQ>(a, b); }
inline Mask any_of(Mask a, Mask b) { return static_cast<Mask>(a | b); }
inline Mask both(Mask a, Mask b) { return static_cast<Mask>(a & b); }
inline Mask all_lanes() { return static_cast<Mask>(0xff); }
inline unsigned mask_bits(Mask m) { return m; }
// The zero-masked forms, all lanes kept: GCC 12 warns of the plain forms' undefined pass-through operand.
SOFTBODY_WIDE_LANES_TARGET inline Lane root(Lane a) { return _mm512_maskz_sqrt_pd(all_lanes(), a); }
SOFTBODY_WIDE_LANES_TARGET inline Lane lane_numbers() { return _mm512_set_pd(7, 6, 5, 4, 3, 2, 1, 0); }
SOFTBODY_WIDE_LANES_TARGET inline Lane from_ints(const int* a) {
  return _mm512_maskz_cvtepi32_pd(all_lanes(), _mm256_loadu_si256(reinterpret_cast<const __m256i*>(a)));
}

// A vector per lane, each component as one Lane.
struct Lane3 {
  Lane x, y, z;
};
SOFTBODY_WIDE_LANES_TARGET inline Lane gather(std::span<const double> a, const std::size_t* i) {
  return _mm512_set_pd(a[i[7]], a[i[6]], a[i[5]], a[i[4]], a[i[3]], a[i[2]], a[i[1]], a[i[0]]);
}
SOFTBODY_WIDE_LANES_TARGET inline Lane3 gather(std::span<const Vec3> p, const std::size_t* i) {
  const Vec3 &p0 = p[i[0]], &p1 = p[i[1]], &p2 = p[i[2]], &p3 = p[i[3]];
  const Vec3 &p4 = p[i[4]], &p5 = p[i[5]], &p6 = p[i[6]], &p7 = p[i[7]];
  return {_mm512_set_pd(p7.x(), p6.x(), p5.x(), p4.x(), p3.x(), p2.x(), p1.x(), p0.x()),
          _mm512_set_pd(p7.y(), p6.y(), p5.y(), p4.y(), p3.y(), p2.y(), p1.y(), p0.y()),
          _mm512_set_pd(p7.z(), p6.z(), p5.z(), p4.z(), p3.z(), p2.z(), p1.z(), p0.z())};
}
SOFTBODY_WIDE_LANES_TARGET inline Lane3 minus(const Lane3& a, const Lane3& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
SOFTBODY_WIDE_LANES_TARGET inline Lane3 times(Lane a, const Lane3& u) { return {a * u.x, a * u.y, a * u.z}; }
// (a_x b_x + a_y b_y) + a_z b_z: Eigen's order for Vec3::dot and squaredNorm.
SOFTBODY_WIDE_LANES_TARGET inline Lane dot(const Lane3& a, const Lane3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

}  // namespace sim::lane_math_avx512

#endif
