// The XPBD substep: predict with gravity and the gas (and, carried, the last substep's constraint forces), one
// coloured pass over the edge constraints (and the bending links), velocities.
#include "sim/integrators/xpbd.hpp"

#include <cmath>

#include "core/profile.hpp"
#include "sim/step/stability.hpp"

namespace sim {
namespace {

// The set in the pass's order: the edges' colours, then the bending links' (each part coloured on its own), so
// that a pass solves every edge before any link; consecutive constraints with the same k and c form a segment.
Pass pass_order(const DistanceConstraints& constraints, int vertex_count) {
  const std::span<const std::array<int, 2>> ends(constraints.ends);
  Pass pass;
  pass.constraints.reserve(constraints.size());
  const auto append = [&](const EdgeColouring& colouring, std::size_t offset) {
    for (const int e : colouring.edges) {
      const std::size_t index = offset + static_cast<std::size_t>(e);
      const double k = constraints.stiffness_N_per_m[index], c = constraints.damping_N_s_per_m[index];
      if (pass.segments.empty() || pass.segments.back().stiffness_N_per_m != k ||
          pass.segments.back().damping_N_s_per_m != c) {
        const std::size_t at = pass.constraints.size();
        pass.segments.push_back({at, at, k, c, k == 0.0 ? 0.0 : 1.0 / k});
      }
      pass.constraints.push_back({ends[index][0], ends[index][1], index, constraints.rest_length_m[index]});
      pass.segments.back().end = pass.constraints.size();
    }
  };
  append(colour_edges(ends.first(constraints.edge_count), vertex_count), 0);
  append(colour_edges(ends.subspan(constraints.edge_count), vertex_count), constraints.edge_count);
  return pass;
}

// One pass over a body's distance constraints C = |x_i − x_j| − L0 in colour order (see xpbd.hpp for Δλ), each
// segment with its k and c. x: the body's positions, previous: the same at the start of the substep, w: inverse
// masses [1/kg], tension: the constraints' carried forces T [N], updated to this pass's. Carried (the prediction
// applied T), the pass solves for the change: C − T/k; classical, for all of it.
void solve_distances(const Pass& pass, double h, bool carried, std::span<Vec3> x, std::span<const Vec3> previous,
                     std::span<const double> w, std::span<double> tension) {
  const double inverse_h2 = 1.0 / (h * h);
  for (const PassSegment& segment : pass.segments) {
    const double k = segment.stiffness_N_per_m, c = segment.damping_N_s_per_m;
    if (k == 0.0 && c == 0.0) continue;
    const bool carries = carried && k != 0.0;  // a damper alone carries nothing (its force would count twice: xpbd.hpp)
    const double kh2 = k * h * h, ch = c * h;  // k h² [kg], c h [kg]: the constraint's stiffness and damping per step
    const double inverse_k = segment.inverse_stiffness;
    for (std::size_t s = segment.begin; s < segment.end; ++s) {
      const PassConstraint& constraint = pass.constraints[s];
      const std::size_t edge = constraint.index;
      const int i = constraint.i, j = constraint.j;
      const Vec3 d = x[i] - x[j];
      const double length = d.norm();
      if (length == 0.0) continue;                                   // coincident ends: no direction, no correction
      const Vec3 n = d / length;                                     // ∇_i C
      const double carried_tension = carries ? tension[edge] : 0.0;  // T [N]
      const double stretch = length - constraint.rest_length_m - carried_tension * inverse_k;  // C − T/k [m]
      const double approach = n.dot((x[i] - previous[i]) - (x[j] - previous[j]));  // ∇C·(x − x_prev) [m]
      const double lambda = (-kh2 * stretch - ch * approach) / ((kh2 + ch) * (w[i] + w[j]) + 1.0);  // Δλ
      x[i] += (w[i] * lambda) * n;
      x[j] -= (w[j] * lambda) * n;
      tension[edge] = carried_tension - lambda * inverse_h2;  // the constraint's force this substep [N]
    }
  }
}

// f_i −= T_e n̂_e, f_j += T_e n̂_e for every constraint e = (i, j) with a spring (k ≠ 0): the carried tensions as
// forces [N].
void add_carried_forces(const DistanceConstraints& constraints, std::span<const double> tension,
                        std::span<const Vec3> x, std::span<Vec3> f) {
  for (std::size_t e = 0; e < constraints.size(); ++e) {
    if (constraints.stiffness_N_per_m[e] == 0.0) continue;
    const auto [i, j] = constraints.ends[e];
    const Vec3 d = x[i] - x[j];
    const double length = d.norm();
    if (length == 0.0) continue;
    const Vec3 pull = (tension[e] / length) * d;  // T n̂ [N]
    f[i] -= pull;
    f[j] += pull;
  }
}

}  // namespace

void Xpbd::prepare_once(const Model& model) {
  if (passes_.size() == model.bodies.size()) return;
  passes_.clear();
  first_tension_.clear();
  tension_count_ = 0;
  for (const Body& body : model.bodies) {
    passes_.push_back(pass_order(body.constraints, body.vertex_count));
    first_tension_.push_back(tension_count_);
    tension_count_ += body.constraints.size();
  }
  StabilityEstimate estimate = estimate_stability(model.bodies, model.initial_x);  // the initial state: deterministic
  scale_for_contacts(estimate, model);
  carried_dt_.clear();
  for (std::size_t b = 0; b < model.bodies.size(); ++b)
    carried_dt_.push_back(xpbd_carried_dt(estimate.bodies[b].omega_max()));
}

void Xpbd::step(Dynamics& dynamics, State& state, double dt) {
  const Model& model = dynamics.model();
  prepare_once(model);
  const double h = dt;
  std::vector<double>& tension = state.carry.edge_tension_N;
  const bool first_substep = tension.size() != tension_count_;  // of the run (or after State::forget_carry)
  if (first_substep) tension.assign(tension_count_, 0.0);       // none carried yet: no force
  const double kick = first_substep ? 0.5 * h : h;  // the leapfrog start: v_{1/2} = v_0 + ½ h a_0 (xpbd.hpp)
  previous_x_ = state.x;
  // 1. Predict with the forces that are not constraints (carried bodies: and their constraints' last forces).
  dynamics.gravity_and_gas_forces(state, force_);
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    if (!carried(b, h)) continue;
    const Body& body = model.bodies[b];
    const std::span<const Vec3> x = Model::of(body, state.x);
    const std::span<Vec3> f = Model::of(body, force_);
    add_carried_forces(body.constraints, std::span(tension).subspan(first_tension_[b], body.constraints.size()), x, f);
  }
  for (std::size_t i = 0; i < state.x.size(); ++i) {
    state.v[i] += (kick * model.inverse_mass[i]) * force_[i];
    state.x[i] += h * state.v[i];
  }
  // 2. The distance constraints (edges, then bending links), body by body.
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const softbody::ProfileScope profile(softbody::ProfilePhase::constraint_sweeps);
    const Body& body = model.bodies[b];
    const std::span<Vec3> x = Model::of(body, state.x);
    const std::span<const Vec3> previous = Model::of(body, previous_x_);
    const std::span<const double> w = Model::of(body, model.inverse_mass);
    solve_distances(passes_[b], h, carried(b, h), x, previous, w,
                    std::span(tension).subspan(first_tension_[b], body.constraints.size()));
  }
  // 3. Velocities from the positions.
  const double inverse_h = 1.0 / h;
  for (std::size_t i = 0; i < state.x.size(); ++i) state.v[i] = (state.x[i] - previous_x_[i]) * inverse_h;
}

}  // namespace sim
