// One vertex's part of vbd's step energy: gradient, Hessian block, and the change along a move.
#include "sim/integrators/vertex_energy.hpp"

#include <limits>

#include "sim/integrators/vertex_contacts.hpp"

namespace sim {
namespace {

// The tangential speed's regularised norm r = √(|v_t|² + ε²), v_t = (x_t − x̃_t)/ĥ [m/s].
double regularised_slip(const Vec3& x, const Vec3& base, double h_hat, double slip_speed2) {
  const double vx = (x.x() - base.x()) / h_hat, vz = (x.z() - base.z()) / h_hat;
  return std::sqrt(vx * vx + vz * vz + slip_speed2);
}

}  // namespace

FloorLag add_floor_terms(const SmoothFloor& floor, double m, const Vec3& x, const Vec3& base, double h_hat,
                         Vec3& gradient, Block3& hessian) {
  FloorLag lag;
  lag.depth_m = floor.height_m - x.y();
  lag.slip_speed2 = floor.slip_speed_m_per_s * floor.slip_speed_m_per_s;
  if (lag.depth_m <= 0.0) return lag;
  const double elastic = m * smooth_elastic_per_mass(floor, lag.depth_m);  // m ω² δ P(d/δ) [N]
  gradient.y() -= elastic;
  hessian.yy += m * floor.omega2 * smooth_dashpot_weight(floor, lag.depth_m);  // m ω² s(d/δ)
  lag.dashpot_kg_s = m * floor.damping_rate * smooth_dashpot_weight(floor, lag.depth_m);
  gradient.y() += lag.dashpot_kg_s * (x.y() - base.y()) / h_hat;  // m b w v'_y
  hessian.yy += lag.dashpot_kg_s / h_hat;
  lag.friction_N = floor.friction * elastic;
  if (lag.friction_N > 0.0) {
    const double vx = (x.x() - base.x()) / h_hat, vz = (x.z() - base.z()) / h_hat;
    const double r = std::sqrt(vx * vx + vz * vz + lag.slip_speed2);
    gradient.x() += lag.friction_N * vx / r;  // N v'_t / r
    gradient.z() += lag.friction_N * vz / r;
    const double a = lag.friction_N / (h_hat * r), b = a / (r * r);  // (N/(ĥ r)) (I − v vᵀ/r²) in x, z
    hessian.xx += a - b * vx * vx;
    hessian.xz -= b * vx * vz;
    hessian.zz += a - b * vz * vz;
  }
  return lag;
}

double floor_energy_change(const SmoothFloor& floor, const FloorLag& lag, double m, const Vec3& x, const Vec3& step,
                           const Vec3& base, double h_hat) {
  const double depth_after = lag.depth_m - step.y();
  const double spring = m * ((depth_after > 0.0 ? smooth_energy_per_mass(floor, depth_after) : 0.0) -
                             (lag.depth_m > 0.0 ? smooth_energy_per_mass(floor, lag.depth_m) : 0.0));
  const double dashpot = lag.dashpot_kg_s / (2.0 * h_hat) * step.y() * (2.0 * (x.y() - base.y()) + step.y());
  double friction = 0.0;
  if (lag.friction_N > 0.0) {
    friction =
        lag.friction_N * h_hat *
        (regularised_slip(x + step, base, h_hat, lag.slip_speed2) - regularised_slip(x, base, h_hat, lag.slip_speed2));
  }
  return spring + dashpot + friction;
}

ColliderLag add_collider_terms(const SmoothCollider& collider, double m, const Vec3& x, const Vec3& base, double h_hat,
                               Vec3& gradient, Block3& hessian) {
  const ColliderLag lag = lag_smooth_collider(collider, m, x);
  Mat3 block = Mat3::Zero();
  add_smooth_collider_derivatives(collider, lag, m, x, base, h_hat, gradient, block);
  hessian.add(block);
  return lag;
}

double collider_energy_change(const SmoothCollider& collider, const ColliderLag& lag, double m, const Vec3& x,
                              const Vec3& step, const Vec3& base, double h_hat) {
  return smooth_collider_terms(collider, lag, m, x + step, base, h_hat) -
         smooth_collider_terms(collider, lag, m, x, base, h_hat);
}

Vec3 six_volume_gradient(const VertexBlocks& blocks, int i, std::span<const Vec3> x, const ConstraintLags& lags) {
  const Vec3 xi = x[static_cast<std::size_t>(i)];
  Vec3 sum = Vec3::Zero();
  for (int f = blocks.face_start[static_cast<std::size_t>(i)]; f < blocks.face_start[static_cast<std::size_t>(i) + 1];
       ++f) {
    const auto vf = static_cast<std::size_t>(f);
    const auto [slot_b, slot_c] = blocks.face_slots[vf];
    if (slot_b >= 0 && slot_c >= 0) {  // (x_i − x_b) × (x_i − x_c), the same bits as (x_b − x_i) × (x_c − x_i)
      sum += lags.offset[static_cast<std::size_t>(slot_b)].cross(lags.offset[static_cast<std::size_t>(slot_c)]);
      continue;
    }
    const auto [b, c] = blocks.face_others[vf];
    sum += (x[static_cast<std::size_t>(b)] - xi).cross(x[static_cast<std::size_t>(c)] - xi);
  }
  return sum;
}

Vec3 six_volume_gradient(const VertexBlocks& blocks, std::size_t i, std::span<const Vec3> x) {
  Vec3 sum = Vec3::Zero();
  for (int f = blocks.face_start[i]; f < blocks.face_start[i + 1]; ++f) {
    const auto [b, c] = blocks.face_others[static_cast<std::size_t>(f)];
    sum += (x[static_cast<std::size_t>(b)] - x[i]).cross(x[static_cast<std::size_t>(c)] - x[i]);
  }
  return sum;
}

VertexTerms vertex_terms(const BodySolve& s, int i, std::span<const Vec3> x, double volume, ConstraintLags& lags) {
  const auto vi = static_cast<std::size_t>(i);
  const VertexBlocks& blocks = s.blocks;
  const Vec3 xi = x[vi], base_i = s.base[vi];
  const double m = s.mass_kg[vi];
  VertexTerms terms;
  terms.gradient = (m * s.inverse_h2) * (xi - s.target[vi]);  // inertia: m (x − y)/ĥ²
  terms.hessian.add_diagonal(m * s.inverse_h2);
  const double inverse_h = 1.0 / s.h_hat;
  const Vec3 moved_i = xi - base_i;  // ĥ v'_i [m]
  const int first = blocks.constraint_start[vi], last = blocks.constraint_start[vi + 1];
  terms.shortest_m = first < last ? std::numeric_limits<double>::infinity() : 0.0;
  // The edge vectors and lengths first, in a loop of their own, so that the square roots of several edges overlap
  // (7 % of a run at icosphere:5).
  for (int e = first; e < last; ++e) {
    const auto slot = static_cast<std::size_t>(e - first);
    const Vec3 d = xi - x[static_cast<std::size_t>(blocks.other_end[static_cast<std::size_t>(e)])];
    lags.offset[slot] = d;
    lags.length_m[slot] = d.norm();
  }
  for (int e = first; e < last; ++e) {
    const auto ve = static_cast<std::size_t>(e), slot = static_cast<std::size_t>(e - first);
    const auto j = static_cast<std::size_t>(blocks.other_end[ve]);
    const Vec3 d = lags.offset[slot];
    const double length = lags.length_m[slot];
    terms.shortest_m = std::min(terms.shortest_m, length);
    if (length == 0.0) {  // coincident ends: no direction, no force, no curvature
      lags.axis[slot] = Vec3::Zero();
      lags.rate_m[slot] = 0.0;
      continue;
    }
    const double inverse_length = 1.0 / length, rest = blocks.rest_length_m[ve];
    const Vec3 axis = inverse_length * d;
    const double k = blocks.stiffness_N_per_m[ve], c_over_h = blocks.damping_N_s_per_m[ve] * inverse_h;
    terms.spring_variation += k * rest * inverse_length * inverse_length;
    const double rate = (moved_i - (x[j] - s.base[j])).dot(axis);  // ĥ × the approach speed [m]
    lags.axis[slot] = axis;
    lags.rate_m[slot] = rate;
    terms.gradient += (k * (length - rest) + c_over_h * rate) * axis;
    const double transverse = k * std::max(0.0, 1.0 - rest * inverse_length);
    terms.hessian.add_diagonal(transverse);
    terms.hessian.add_outer(k + c_over_h - transverse, axis);
  }
  if (s.gas) {
    terms.volume_gradient = six_volume_gradient(blocks, i, x, lags) * (1.0 / 6.0);  // g_i [m²]
    terms.gradient -= s.gas->pressure(volume) * terms.volume_gradient;
    terms.hessian.add_outer(s.gas->stiffness(volume), terms.volume_gradient);
  }
  if (s.floor) terms.floor = add_floor_terms(*s.floor, m, xi, base_i, s.h_hat, terms.gradient, terms.hessian);
  for (std::size_t c = 0; c < s.colliders.size(); ++c) {
    lags.colliders[c] = add_collider_terms(s.colliders[c], m, xi, base_i, s.h_hat, terms.gradient, terms.hessian);
  }
  if (s.contacts) s.contacts->add_terms(s.first_vertex + i, terms.gradient, terms.hessian);
  return terms;
}

bool sure_descent(const BodySolve& s, const VertexTerms& terms, const Vec3& x, double volume, const Vec3& step,
                  double slope) {
  if (!s.colliders.empty() || s.contacts != nullptr) return false;  // their terms are not in the bound
  if (s.floor && (terms.floor.depth_m > 0.0 || s.floor->height_m - (x.y() + step.y()) > 0.0)) return false;
  const double length = step.norm();
  if (!(length < 0.5 * terms.shortest_m)) return false;
  // Along the step every l ≥ l (1 − |Δ|/l_shortest) ≥ l/2, so the springs' B ≤ β |Δ| Σ k L0/l² / (1 − |Δ|/l_shortest)²;
  // both sides below are multiplied by (l_shortest − |Δ|)² / l_shortest² to spare the divisions.
  const double margin = terms.shortest_m - length, margin2 = margin * margin;  // [m²]
  const double allowed = -0.5 * slope * margin2;  // ½|∇E·Δ| (l_shortest − |Δ|)² [J m²]
  const double length2 = length * length;
  double spent =
      kSpringHessianVariation * length * length2 * terms.spring_variation * terms.shortest_m * terms.shortest_m;
  if (s.gas) {
    if (volume <= s.gas->guard_m3) return false;                    // E linear in V here, curving up past the guard
    const double after = volume + terms.volume_gradient.dot(step);  // V₁: V is affine in x_i
    if (after < volume) {
      const double least = std::max(after, s.gas->guard_m3);
      const double gas = s.gas->nRT_J * terms.volume_gradient.squaredNorm() * (volume - least) * (volume + least) /
                         (least * least * volume * volume);  // nRT |g|² (1/V₁² − 1/V²) [N/m]
      spent += gas * length2 * margin2;
    }
  }
  return spent <= allowed;
}

double vertex_energy_change(const BodySolve& s, int i, std::span<const Vec3> x, double volume, const VertexTerms& terms,
                            const ConstraintLags& lags, const Vec3& step) {
  const auto vi = static_cast<std::size_t>(i);
  const VertexBlocks& blocks = s.blocks;
  const Vec3 xi = x[vi], moved = xi + step;
  const double m = s.mass_kg[vi];
  double change = 0.5 * m * s.inverse_h2 * step.dot(2.0 * (xi - s.target[vi]) + step);  // inertia
  const double half_over_h = 0.5 / s.h_hat;
  const int first = blocks.constraint_start[vi], last = blocks.constraint_start[vi + 1];
  for (int e = first; e < last; ++e) {
    const auto ve = static_cast<std::size_t>(e), slot = static_cast<std::size_t>(e - first);
    const double k = blocks.stiffness_N_per_m[ve], rest = blocks.rest_length_m[ve];
    const double before = lags.length_m[slot];
    const double after = (moved - x[static_cast<std::size_t>(blocks.other_end[ve])]).norm();
    change += 0.5 * k * (after - before) * (after + before - 2.0 * rest);  // ½k((l₁−L0)² − (l₀−L0)²)
    const double along = step.dot(lags.axis[slot]);
    change +=
        half_over_h * blocks.damping_N_s_per_m[ve] * along * (2.0 * lags.rate_m[slot] + along);  // c/(2ĥ) Δ(rate²)
  }
  if (s.gas) change += s.gas->energy_change(volume, terms.volume_gradient.dot(step));  // exact: V is affine in x_i
  if (s.floor) change += floor_energy_change(*s.floor, terms.floor, m, xi, step, s.base[vi], s.h_hat);
  for (std::size_t c = 0; c < s.colliders.size(); ++c) {
    change += collider_energy_change(s.colliders[c], lags.colliders[c], m, xi, step, s.base[vi], s.h_hat);
  }
  if (s.contacts) change += s.contacts->energy_change(s.first_vertex + i, step);
  return change;
}

}  // namespace sim
