// The line search of vbd's coarse corrections: E's change along a whole-body motion, with the lags taken at x.
#include "sim/integrators/motion_search.hpp"

#include "sim/forces/forces.hpp"
#include "sim/integrators/vertex_contacts.hpp"

namespace sim {

// The floor's and the smooth colliders' lags of every vertex at x, as the vertex's own terms take them.
void take_motion_lags(const BodySolve& s, std::span<const Vec3> x, MotionScratch& scratch) {
  const std::size_t n = x.size();
  Vec3 unused_gradient = Vec3::Zero();
  Block3 unused_hessian;
  if (s.floor) {
    scratch.floor_lags.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      scratch.floor_lags[i] =
          add_floor_terms(*s.floor, s.mass_kg[i], x[i], s.base[i], s.h_hat, unused_gradient, unused_hessian);
    }
  }
  scratch.collider_lags.resize(s.colliders.size() * n);
  for (std::size_t c = 0; c < s.colliders.size(); ++c) {
    for (std::size_t i = 0; i < n; ++i) {
      scratch.collider_lags[c * n + i] =
          add_collider_terms(s.colliders[c], s.mass_kg[i], x[i], s.base[i], s.h_hat, unused_gradient, unused_hessian);
    }
  }
}

// E(x + α motion) − E(x) [J], with the lags in scratch.
double motion_energy_change(const Body& body, const BodySolve& s, std::span<const Vec3> x, double volume, double alpha,
                            MotionScratch& scratch) {
  const std::vector<Vec3>& motion = scratch.motion;
  const std::size_t n = x.size();
  double change = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 step = alpha * motion[i];
    const double m = s.mass_kg[i];
    change += 0.5 * m * s.inverse_h2 * step.dot(2.0 * (x[i] - s.target[i]) + step);
    if (s.floor && (x[i].y() < s.floor->height_m || x[i].y() + step.y() < s.floor->height_m)) {
      change += floor_energy_change(*s.floor, scratch.floor_lags[i], m, x[i], step, s.base[i], s.h_hat);
    }
    for (std::size_t c = 0; c < s.colliders.size(); ++c) {
      change +=
          collider_energy_change(s.colliders[c], scratch.collider_lags[c * n + i], m, x[i], step, s.base[i], s.h_hat);
    }
  }
  const DistanceConstraints& constraints = body.constraints;
  for (std::size_t e = 0; e < constraints.size(); ++e) {
    const auto [i, j] = constraints.ends[e];
    const auto vi = static_cast<std::size_t>(i), vj = static_cast<std::size_t>(j);
    const Vec3 d = x[vi] - x[vj];
    const double before = d.norm();
    if (before == 0.0) continue;
    const Vec3 axis = d / before;
    const Vec3 relative = alpha * (motion[vi] - motion[vj]);
    const double after = (d + relative).norm();
    const double k = constraints.stiffness_N_per_m[e], rest = constraints.rest_length_m[e];
    change += 0.5 * k * (after - before) * (after + before - 2.0 * rest);
    const double rate = ((x[vi] - s.base[vi]) - (x[vj] - s.base[vj])).dot(axis), along = relative.dot(axis);
    change += 0.5 * constraints.damping_N_s_per_m[e] / s.h_hat * along * (2.0 * rate + along);
  }
  if (s.gas) {
    std::vector<Vec3>& trial = scratch.trial;
    trial.resize(n);
    for (std::size_t i = 0; i < n; ++i) trial[i] = x[i] + alpha * motion[i];
    change += s.gas->energy_change(volume, enclosed_volume(body.topology.faces, trial) - volume);
  }
  if (s.contacts) change += s.contacts->motion_energy_change(s.first_vertex, motion, alpha);
  return change;
}

bool search_along_motion(const Body& body, const BodySolve& s, std::span<Vec3> x, double volume, double slope,
                         MotionScratch& scratch) {
  take_motion_lags(s, x, scratch);  // once: they do not depend on α
  for (double alpha = 1.0; alpha > 1e-3; alpha *= 0.5) {
    if (motion_energy_change(body, s, x, volume, alpha, scratch) <= kArmijo * alpha * slope) {
      for (std::size_t i = 0; i < x.size(); ++i) x[i] += alpha * scratch.motion[i];
      return true;
    }
  }
  return false;
}

}  // namespace sim
