// Linearised backward Euler: assemble M − h ∂f/∂v − h² ∂f/∂x, solve for Δv by conjugate gradients.
#include "sim/integrators/implicit_euler.hpp"

#include "sim/forces/spring_jacobian.hpp"

namespace sim {
namespace {

constexpr double kSolverTolerance = 1e-10;  // CG stops at |r| <= tol·|b|: far below the method's O(h) error
constexpr int kMaxSolverIterations = 1000;

}  // namespace

void ImplicitEuler::build_pattern(const Model& model, std::size_t vertex_count) {
  springs_.clear();
  std::vector<std::array<int, 2>> pairs;
  for (const Body& body : model.bodies) {
    const DistanceConstraints& constraints = body.constraints;  // the edges, then the bending links
    for (std::size_t e = 0; e < constraints.size(); ++e) {
      Spring spring;
      spring.i = body.first_vertex + constraints.ends[e][0];
      spring.j = body.first_vertex + constraints.ends[e][1];
      spring.rest_length_m = constraints.rest_length_m[e];
      spring.stiffness_N_per_m = constraints.stiffness_N_per_m[e];
      spring.damping_N_s_per_m = constraints.damping_N_s_per_m[e];
      springs_.push_back(spring);
      pairs.push_back({spring.i, spring.j});
    }
  }
  system_.build(vertex_count, pairs);
  rhs_.setZero(system_.size());
  pattern_vertices_ = vertex_count;
}

// Matrix A = M + h² K + h C with K = −∂f/∂x (springs, clamped) and C = −∂f/∂v (dampers), both as
// graph Laplacians of 3×3 spring blocks; rhs b = h (f0 − h K v0).
void ImplicitEuler::assemble(const State& state, std::span<const double> mass_kg, double dt) {
  system_.set_zero();
  for (std::size_t v = 0; v < mass_kg.size(); ++v)
    system_.add_diagonal(static_cast<int>(v), mass_kg[v] * Eigen::Matrix3d::Identity());
  for (std::size_t v = 0; v < force_.size(); ++v)
    rhs_.segment<3>(BlockSystem::dof(static_cast<int>(v))) = dt * force_[v];
  for (std::size_t p = 0; p < springs_.size(); ++p) {
    const Spring& s = springs_[p];
    const Vec3 d = state.x[s.i] - state.x[s.j];
    const Eigen::Matrix3d stiffness = spring_stiffness_block(d, s.rest_length_m, s.stiffness_N_per_m);
    const Eigen::Matrix3d block = dt * dt * stiffness + dt * damper_block(d, s.damping_N_s_per_m);
    system_.add_diagonal(s.i, block);
    system_.add_diagonal(s.j, block);
    system_.add_coupling(p, -block);
    const Vec3 kv = stiffness * (state.v[s.i] - state.v[s.j]);  // (K v0)_i for this spring; −it on j
    rhs_.segment<3>(BlockSystem::dof(s.i)) -= dt * dt * kv;
    rhs_.segment<3>(BlockSystem::dof(s.j)) += dt * dt * kv;
  }
}

void ImplicitEuler::step(Dynamics& dynamics, State& state, double dt) {
  const std::size_t n = state.x.size();
  if (pattern_vertices_ != n) build_pattern(dynamics.model(), n);  // first step, or another model
  dynamics.forces(state, force_);
  assemble(state, dynamics.model().mass_kg, dt);
  Eigen::VectorXd& delta_v = state.carry.velocity_change;  // the last step's Δv: a warm start, deterministic
  cg_.solve(system_, {}, rhs_, delta_v, kSolverTolerance, kMaxSolverIterations, CgStart::Given);  // profiled there
  for (std::size_t i = 0; i < n; ++i) {
    state.v[i] += delta_v.segment<3>(BlockSystem::dof(static_cast<int>(i)));
    state.x[i] += dt * state.v[i];
  }
}

}  // namespace sim
