// The XPBD substep: predict with gravity and the gas (and, linearised, the springs and dampers), one coloured
// pass over the edge constraints (and the bending links), velocities.
#include "sim/integrators/xpbd.hpp"

#include <cmath>

#include "sim/forces.hpp"
#include "sim/stability.hpp"

namespace sim {
namespace {

// One pass over distance constraints C = |x_i − x_j| − L0 in colour order (see xpbd.hpp for Δλ): the edges'
// with k, c, or the bending links' with k_b, c_b. x: the body's positions, previous: the same at the start of
// the substep, w: inverse masses [1/kg]. Linearised (previous_v: v at the start of the substep; empty: the
// classical form), the pass corrects only what the explicit spring and damper forces of the prediction got
// wrong: C − C(x_prev) and ∇C·(x − x_prev) − h Ċ(x_prev, v_prev).
void solve_distances(std::span<const std::array<int, 2>> edges, std::span<const double> rest, double k, double c,
                     const EdgeColouring& colouring, double h, std::span<Vec3> x, std::span<const Vec3> previous,
                     std::span<const Vec3> previous_v, std::span<const double> w) {
  if (k == 0.0 && c == 0.0) return;
  const double kh2 = k * h * h, ch = c * h;  // k h² [kg], c h [kg]: the constraint's stiffness and damping per step
  for (const int e : colouring.edges) {
    const auto [i, j] = edges[static_cast<std::size_t>(e)];
    const Vec3 d = x[i] - x[j];
    const double length = d.norm();
    if (length == 0.0) continue;  // coincident ends: no direction, no correction
    const Vec3 n = d / length;    // ∇_i C
    double stretch = length - rest[static_cast<std::size_t>(e)];               // C [m]
    double approach = n.dot((x[i] - previous[i]) - (x[j] - previous[j]));     // ∇C·(x − x_prev) [m]
    if (!previous_v.empty()) {
      stretch = length - (previous[i] - previous[j]).norm();                   // C − C(x_prev) [m]
      approach -= h * n.dot(previous_v[i] - previous_v[j]);                    // minus h Ċ at the start [m]
    }
    const double lambda = (-kh2 * stretch - ch * approach) / ((kh2 + ch) * (w[i] + w[j]) + 1.0);  // Δλ
    x[i] += (w[i] * lambda) * n;
    x[j] -= (w[j] * lambda) * n;
  }
}

// f += the springs' and dampers' forces of one body (the edges, and the bending links if any) [N].
void add_body_spring_forces(const Body& body, std::span<const Vec3> x, std::span<const Vec3> v, std::span<Vec3> f) {
  add_spring_dampers(body.topology.edges, body.rest.edge_length_m, body.params.stiffness_N_per_m,
                     body.params.damping_N_s_per_m, x, v, f);
  if (body.params.bending_N_per_m == 0.0) return;
  add_spring_dampers(body.topology.bending_links, body.rest.bending_length_m, body.params.bending_N_per_m,
                     body.params.bending_damping_N_s_per_m, x, v, f);
}

}  // namespace

void Xpbd::prepare_once(const Model& model) {
  if (colourings_.size() == model.bodies.size()) return;
  colourings_.clear();
  link_colourings_.clear();
  for (const Body& body : model.bodies) {
    colourings_.push_back(colour_edges(body.topology.edges, body.vertex_count));
    link_colourings_.push_back(colour_edges(body.topology.bending_links, body.vertex_count));
  }
  StabilityEstimate estimate = estimate_stability(model.bodies, model.initial_x);  // the initial state: deterministic
  scale_for_contacts(estimate, model);
  linearised_dt_.clear();
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    linearised_dt_.push_back(xpbd_linearised_dt(estimate.bodies[b].omega_max(), model.bodies[b].vertex_count));
  }
}

void Xpbd::step(Dynamics& dynamics, State& state, double dt) {
  const Model& model = dynamics.model();
  prepare_once(model);
  const double h = dt;
  previous_x_ = state.x;
  previous_v_ = state.v;
  // 1. Predict with the forces that are not constraints (linearised bodies: and the springs'): x* = x + h v + h² f/m.
  dynamics.gravity_and_gas_forces(state, force_);
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    if (!linearised(b, h)) continue;
    const Body& body = model.bodies[b];
    const auto first = static_cast<std::size_t>(body.first_vertex), count = static_cast<std::size_t>(body.vertex_count);
    add_body_spring_forces(body, std::span<const Vec3>(state.x.data() + first, count),
                           std::span<const Vec3>(state.v.data() + first, count),
                           std::span<Vec3>(force_.data() + first, count));
  }
  for (std::size_t i = 0; i < state.x.size(); ++i) {
    state.v[i] += (h * model.inverse_mass[i]) * force_[i];
    state.x[i] += h * state.v[i];
  }
  // 2. The edge constraints, body by body.
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const Body& body = model.bodies[b];
    const auto first = static_cast<std::size_t>(body.first_vertex), count = static_cast<std::size_t>(body.vertex_count);
    const std::span<Vec3> x(state.x.data() + first, count);
    const std::span<const Vec3> previous(previous_x_.data() + first, count);
    const std::span<const double> w(model.inverse_mass.data() + first, count);
    const std::span<const Vec3> previous_v =
        linearised(b, h) ? std::span<const Vec3>(previous_v_.data() + first, count) : std::span<const Vec3>();
    solve_distances(body.topology.edges, body.rest.edge_length_m, body.params.stiffness_N_per_m,
                    body.params.damping_N_s_per_m, colourings_[b], h, x, previous, previous_v, w);
    if (body.params.bending_N_per_m == 0.0) continue;
    solve_distances(body.topology.bending_links, body.rest.bending_length_m, body.params.bending_N_per_m,
                    body.params.bending_damping_N_s_per_m, link_colourings_[b], h, x, previous, previous_v, w);
  }
  // 3. Velocities from the positions.
  const double inverse_h = 1.0 / h;
  for (std::size_t i = 0; i < state.x.size(); ++i) state.v[i] = (state.x[i] - previous_x_[i]) * inverse_h;
}

}  // namespace sim
