// Four constraints at once, one per AVX2 lane (see lane_math.hpp): each expression is the scalar loop's, in its order.
#include "sim/integrators/correction_lanes.hpp"

#include "sim/forces/forces.hpp"
#include "sim/integrators/lane_math.hpp"
#include "sim/integrators/vertex_move_lanes.hpp"
#include "sim/step/chunked_sum.hpp"

namespace sim {

#if defined(__x86_64__)

namespace {

using namespace lane_math;

// The two ends of constraints e .. e + 3.
struct LaneEnds {
  std::size_t i[kLanes], j[kLanes];
};
LaneEnds lane_ends(const DistanceConstraints& constraints, std::size_t e) {
  LaneEnds ends;
  for (int l = 0; l < kLanes; ++l) {
    ends.i[l] = static_cast<std::size_t>(constraints.ends[e + static_cast<std::size_t>(l)][0]);
    ends.j[l] = static_cast<std::size_t>(constraints.ends[e + static_cast<std::size_t>(l)][1]);
  }
  return ends;
}

SOFTBODY_LANES_TARGET inline Lane load(const std::vector<double>& a, std::size_t e) { return _mm256_loadu_pd(&a[e]); }

SOFTBODY_LANES_TARGET std::size_t edge_forces_avx2(const DistanceConstraints& constraints, const BodySolve& s,
                                                   std::span<const Vec3> x, std::size_t first, std::size_t last,
                                                   MotionScratch& scratch, std::span<Vec3> force) {
  const Lane zero = splat(0.0), inverse_h = splat(1.0 / s.h_hat);
  std::size_t e = first;
  for (; e + kLanes <= last; e += kLanes) {
    const LaneEnds ends = lane_ends(constraints, e);
    const Lane3 xi = gather(x, ends.i), xj = gather(x, ends.j);
    // take_edge_lag
    const Lane3 d = minus(xi, xj);
    const Lane length = _mm256_sqrt_pd(dot(d, d));
    const Lane zero_length = _mm256_cmp_pd(length, zero, _CMP_EQ_OQ);
    const Lane inverse_length = select(zero_length, zero, splat(1.0) / length);
    const Lane3 approach = minus(minus(xi, gather(s.base, ends.i)), minus(xj, gather(s.base, ends.j)));
    const Lane rate = dot(approach, times(inverse_length, d));
    _mm256_storeu_pd(&scratch.edge_length_m[e], length);
    _mm256_storeu_pd(&scratch.edge_inverse_length[e], inverse_length);
    _mm256_storeu_pd(&scratch.edge_rate_m[e], rate);
    // The force: (k (l − L0) + c (1/ĥ) ĥ l̇) d/l, with ĥ l̇ along d/l (the lag's is along d (1/l): other bits).
    const Lane3 axis{d.x / length, d.y / length, d.z / length};
    const Lane magnitude = load(constraints.stiffness_N_per_m, e) * (length - load(constraints.rest_length_m, e)) +
                           load(constraints.damping_N_s_per_m, e) * inverse_h * dot(approach, axis);
    double fx[kLanes], fy[kLanes], fz[kLanes];
    _mm256_storeu_pd(fx, select(zero_length, zero, magnitude * axis.x));
    _mm256_storeu_pd(fy, select(zero_length, zero, magnitude * axis.y));
    _mm256_storeu_pd(fz, select(zero_length, zero, magnitude * axis.z));
    for (int l = 0; l < kLanes; ++l) force[e + static_cast<std::size_t>(l)] = Vec3(fx[l], fy[l], fz[l]);
  }
  return e;
}

SOFTBODY_LANES_TARGET std::size_t edge_energy_changes_avx2(const DistanceConstraints& constraints, const BodySolve& s,
                                                           std::span<const Vec3> x, double alpha,
                                                           const MotionScratch& scratch, std::size_t first,
                                                           std::size_t last, double& change) {
  const std::span<const Vec3> motion = scratch.motion;
  const Lane half_over_h = splat(0.5 / s.h_hat), a = splat(alpha);
  std::size_t e = first;
  for (; e + kLanes <= last; e += kLanes) {
    const LaneEnds ends = lane_ends(constraints, e);
    const Lane3 d = minus(gather(x, ends.i), gather(x, ends.j));
    const Lane3 relative = times(a, minus(gather(motion, ends.i), gather(motion, ends.j)));
    const Lane3 moved = plus(d, relative);
    const Lane after = _mm256_sqrt_pd(dot(moved, moved)), before = load(scratch.edge_length_m, e);
    const Lane k = load(constraints.stiffness_N_per_m, e), rest = load(constraints.rest_length_m, e);
    const Lane spring = splat(0.5) * k * (after - before) * (after + before - splat(2.0) * rest);
    const Lane rate = load(scratch.edge_rate_m, e), along = dot(relative, d) * load(scratch.edge_inverse_length, e);
    const Lane damper = half_over_h * load(constraints.damping_N_s_per_m, e) * along * (splat(2.0) * rate + along);
    double springs[kLanes], dampers[kLanes];
    _mm256_storeu_pd(springs, spring);
    _mm256_storeu_pd(dampers, damper);
    for (int l = 0; l < kLanes; ++l) {
      if (scratch.edge_length_m[e + static_cast<std::size_t>(l)] == 0.0) continue;
      change += springs[l];
      change += dampers[l];
    }
  }
  return e;
}

// The faces' six-volume terms (x_a − o)·((x_b − o) × (x_c − o)) from `first`, four at a time, added to six_volume one
// at a time in face order (forces.cpp's six_volume_of, Eigen's cross and dot). Returns where it stopped.
SOFTBODY_LANES_TARGET std::size_t six_volume_avx2(std::span<const Triangle> faces, std::span<const Vec3> x,
                                                  const Vec3& origin, std::size_t first, std::size_t last,
                                                  double& six_volume) {
  const Lane3 o{splat(origin.x()), splat(origin.y()), splat(origin.z())};
  std::size_t f = first;
  for (; f + kLanes <= last; f += kLanes) {
    std::size_t corner[3][kLanes];
    for (int l = 0; l < kLanes; ++l) {
      for (int k = 0; k < 3; ++k) {
        corner[k][l] = static_cast<std::size_t>(faces[f + static_cast<std::size_t>(l)][static_cast<std::size_t>(k)]);
      }
    }
    const Lane3 a = minus(gather(x, corner[0]), o), b = minus(gather(x, corner[1]), o),
                c = minus(gather(x, corner[2]), o);
    const Lane3 b_cross_c{b.y * c.z - b.z * c.y, b.z * c.x - b.x * c.z, b.x * c.y - b.y * c.x};
    double terms[kLanes];
    store(terms, dot(a, b_cross_c));
    for (int l = 0; l < kLanes; ++l) six_volume += terms[l];
  }
  return f;
}

}  // namespace

namespace {
// The faces' terms from `first` in lanes where they run, added to six_volume; returns where it stopped.
std::size_t six_volume_in_lanes(std::span<const Triangle> faces, std::span<const Vec3> x, const Vec3& origin,
                                std::size_t first, std::size_t last, double& six_volume) {
  if (!lanes_on()) return first;
  return six_volume_avx2(faces, x, origin, first, last, six_volume);
}
}  // namespace

std::size_t edge_forces_in_lanes(const DistanceConstraints& constraints, const BodySolve& s, std::span<const Vec3> x,
                                 std::size_t first, std::size_t last, MotionScratch& scratch, std::span<Vec3> force) {
  if (!lanes_on()) return first;
  return edge_forces_avx2(constraints, s, x, first, last, scratch, force);
}

std::size_t edge_energy_changes_in_lanes(const DistanceConstraints& constraints, const BodySolve& s,
                                         std::span<const Vec3> x, double alpha, const MotionScratch& scratch,
                                         std::size_t first, std::size_t last, double& change) {
  if (!lanes_on()) return first;
  return edge_energy_changes_avx2(constraints, s, x, alpha, scratch, first, last, change);
}

#else

namespace {
std::size_t six_volume_in_lanes(std::span<const Triangle>, std::span<const Vec3>, const Vec3&, std::size_t first,
                                std::size_t, double&) {
  return first;
}
}  // namespace

std::size_t edge_forces_in_lanes(const DistanceConstraints&, const BodySolve&, std::span<const Vec3>, std::size_t first,
                                 std::size_t, MotionScratch&, std::span<Vec3>) {
  return first;
}

std::size_t edge_energy_changes_in_lanes(const DistanceConstraints&, const BodySolve&, std::span<const Vec3>, double,
                                         const MotionScratch&, std::size_t first, std::size_t, double&) {
  return first;
}

#endif

double enclosed_volume_in_lanes(std::span<const Triangle> faces, std::span<const Vec3> x, PartRunner* runner,
                                std::vector<double>& partials) {
  const Vec3& origin = x[0];
  const double six_volume =
      chunked_sum(runner, faces.size(), 0.0, partials, [&](std::size_t first, std::size_t last, double& part) {
        double sum = 0.0;
        const std::size_t tail = six_volume_in_lanes(faces, x, origin, first, last, sum);
        part = six_volume_of(faces, x, origin, tail, last, sum);
      });
  return six_volume / 6.0;
}

}  // namespace sim
