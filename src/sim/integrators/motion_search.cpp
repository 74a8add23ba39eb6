// The line search of vbd's coarse corrections: E's change along a whole-body motion, with the lags taken at x.
#include "sim/integrators/motion_search.hpp"

#include "sim/forces/forces.hpp"
#include "sim/integrators/correction_lanes.hpp"
#include "sim/integrators/vertex_contacts.hpp"
#include "sim/step/chunked_sum.hpp"

namespace sim {
namespace {

// det(I + M) − 1 without the cancellation of forming det(I + M) where M is small: tr M + ½(tr² M − tr M²) + det M.
double determinant_change(const Eigen::Matrix3d& M) {
  const double trace = M.trace();
  return trace + 0.5 * (trace * trace - (M * M).trace()) + M.determinant();
}

// V(x + α motion) − V(x) [m³].
double volume_change(const Body& body, const BodySolve& s, std::span<const Vec3> x, double volume, double alpha,
                     MotionScratch& scratch) {
  if (scratch.linear_part) return volume * determinant_change(alpha * *scratch.linear_part);
  std::vector<Vec3>& trial = scratch.trial;
  trial.resize(x.size());
  chunked_for(s.runner, x.size(), [&](std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last; ++i) trial[i] = x[i] + alpha * scratch.motion[i];
  });
  return enclosed_volume_in_lanes(body.topology.faces, trial, s.runner, scratch.volume_sums) - volume;
}

// The vertices' part of E's change along α motion (inertia, floor, colliders) over [first, last) [J].
double vertex_energy_changes(const BodySolve& s, std::span<const Vec3> x, double alpha, const MotionScratch& scratch,
                             std::size_t first, std::size_t last) {
  const std::vector<Vec3>& motion = scratch.motion;
  const std::size_t n = x.size();
  double change = 0.0;
  for (std::size_t i = first; i < last; ++i) {
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
  return change;
}

// The constraints' part (springs and dampers) over [first, last) [J].
double constraint_energy_changes(const Body& body, const BodySolve& s, std::span<const Vec3> x, double alpha,
                                 const MotionScratch& scratch, std::size_t first, std::size_t last) {
  const std::vector<Vec3>& motion = scratch.motion;
  const DistanceConstraints& constraints = body.constraints;
  const double half_over_h = 0.5 / s.h_hat;
  double change = 0.0;
  for (std::size_t e = edge_energy_changes_in_lanes(constraints, s, x, alpha, scratch, first, last, change); e < last;
       ++e) {
    const double before = scratch.edge_length_m[e];
    if (before == 0.0) continue;
    const auto [i, j] = constraints.ends[e];
    const auto vi = static_cast<std::size_t>(i), vj = static_cast<std::size_t>(j);
    const Vec3 d = x[vi] - x[vj];
    const Vec3 relative = alpha * (motion[vi] - motion[vj]);
    const double after = (d + relative).norm();
    const double k = constraints.stiffness_N_per_m[e], rest = constraints.rest_length_m[e];
    change += 0.5 * k * (after - before) * (after + before - 2.0 * rest);
    const double rate = scratch.edge_rate_m[e], along = relative.dot(d) * scratch.edge_inverse_length[e];
    change += half_over_h * constraints.damping_N_s_per_m[e] * along * (2.0 * rate + along);
  }
  return change;
}

// E(x + α motion) − E(x) [J], with the lags in scratch; `volume_step`: V's change [m³].
double energy_change(const Body& body, const BodySolve& s, std::span<const Vec3> x, double volume, double alpha,
                     double volume_step, MotionScratch& scratch) {
  double change =
      chunked_sum(s.runner, x.size(), 0.0, scratch.energy_sums, [&](std::size_t first, std::size_t last, double& part) {
        part = vertex_energy_changes(s, x, alpha, scratch, first, last);
      });
  change += chunked_sum(s.runner, body.constraints.size(), 0.0, scratch.energy_sums,
                        [&](std::size_t first, std::size_t last, double& part) {
                          part = constraint_energy_changes(body, s, x, alpha, scratch, first, last);
                        });
  if (s.gas) change += s.gas->energy_change(volume, volume_step);
  if (s.contacts) change += s.contacts->motion_energy_change(s.first_vertex, scratch.motion, alpha);
  return change;
}

}  // namespace

void take_edge_lag(const DistanceConstraints& constraints, const BodySolve& s, std::span<const Vec3> x, std::size_t e,
                   MotionScratch& scratch) {
  const auto [i, j] = constraints.ends[e];
  const auto vi = static_cast<std::size_t>(i), vj = static_cast<std::size_t>(j);
  const Vec3 d = x[vi] - x[vj];
  const double length = d.norm(), inverse_length = length == 0.0 ? 0.0 : 1.0 / length;
  scratch.edge_length_m[e] = length;
  scratch.edge_inverse_length[e] = inverse_length;
  scratch.edge_rate_m[e] = ((x[vi] - s.base[vi]) - (x[vj] - s.base[vj])).dot(inverse_length * d);
}

double motion_energy_change(const Body& body, const BodySolve& s, std::span<const Vec3> x, double volume, double alpha,
                            MotionScratch& scratch) {
  const double volume_step = s.gas ? volume_change(body, s, x, volume, alpha, scratch) : 0.0;
  return energy_change(body, s, x, volume, alpha, volume_step, scratch);
}

bool search_along_motion(const Body& body, const BodySolve& s, std::span<Vec3> x, double volume, double slope,
                         MotionScratch& scratch) {
  scratch.volume_after = volume;
  for (double alpha = 1.0; alpha > 1e-3; alpha *= 0.5) {
    const double volume_step = s.gas ? volume_change(body, s, x, volume, alpha, scratch) : 0.0;
    if (energy_change(body, s, x, volume, alpha, volume_step, scratch) <= kArmijo * alpha * slope) {
      chunked_for(s.runner, x.size(), [&](std::size_t first, std::size_t last) {
        for (std::size_t i = first; i < last; ++i) x[i] += alpha * scratch.motion[i];
      });
      scratch.volume_after = volume + volume_step;
      return true;
    }
  }
  return false;
}

}  // namespace sim
