// Backward Euler by Newton: iterate, solve by conjugate gradients (the gas as rank-one products), line-search on E.
#include "sim/integrators/newton_euler.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sim {
namespace {

constexpr double kNewtonTolerance = 1e-7;  // m/s: stop when the Newton step changes no velocity by more
// A cap, not the usual count: smooth motion converges in 2–3 iterations; steps in which the post-step floor
// contact has squashed the body start far from a minimum of a non-convex E (compressed springs) and converge
// only linearly with the definite Hessian (docs/physics/integrators.md, "Large steps: `newton`", has the measured
// counts).
constexpr int kMostNewtonIterations = 30;
// Each Newton system is solved to this relative residual (an inexact Newton method: the outer iteration then
// converges linearly at about this rate, far faster than the tolerance above needs), in at most this many
// conjugate-gradient iterations.
constexpr double kSolveTolerance = 1e-3;
constexpr int kMostCgIterations = 2000;
// The smooth floor's lagged dashpot weights and friction forces (floor_potential.hpp) follow the iterate in the first
// this many iterations, then stay: E is then fixed, so the line search converges (a vertex crossing the floor's
// 2 mm smoothing band between iterates changes its weights, and following them every iteration could cycle).
constexpr int kMostLagUpdates = 5;
constexpr double kArmijo = 1e-4;  // sufficient-decrease fraction of the predicted ∇E·Δ
constexpr int kMostHalvings = 30;
// A predicted decrease below this fraction of the size of E's terms is round-off in E: the step is taken
// without a search.
constexpr double kEnergyRoundOff = 64.0 * std::numeric_limits<double>::epsilon();

}  // namespace

void NewtonEuler::build(const Model& model) {
  potential_.build(model);
  hessian_.build(model.vertex_count(), potential_.pairs());
  gas_terms_.clear();
  for (const IncrementalPotential::GasTerm& term : potential_.gas_terms()) {
    gas_terms_.push_back({model.bodies[term.body].first_vertex, term.direction, {}});
  }
  const Eigen::Index size = hessian_.size();
  gradient_.setZero(size);
  right_side_.setZero(size);
  direction_.setZero(size);
  built_for_vertices_ = model.vertex_count();
}

bool NewtonEuler::solve_for_direction(const Model& model, IncrementalPotential::Hessian form) {
  potential_.assemble(model, x_, form, hessian_, gradient_);
  right_side_ = -gradient_;
  terms_.assign(gas_terms_.begin(), gas_terms_.end());
  for (const BodyContactPotential::Term& term : potential_.contact_terms()) terms_.push_back({0, term.u, term.vertex});
  const CgResult result = cg_.solve(hessian_, terms_, right_side_, direction_, kSolveTolerance, kMostCgIterations);
  ++statistics_.solves;
  statistics_.cg_iterations += result.iterations;
  return !result.negative_curvature;
}

void NewtonEuler::move_along_direction(double alpha) {
  for (std::size_t i = 0; i < x_.size(); ++i) {
    trial_[i] = x_[i] + alpha * direction_.segment<3>(hessian_.dof(static_cast<int>(i)));
  }
}

void NewtonEuler::step(Dynamics& dynamics, State& state, double dt) {
  const Model& model = dynamics.model();
  if (built_for_vertices_ != state.x.size()) build(model);
  potential_.begin_step(model, state, dt);
  x_.resize(state.x.size());
  trial_.resize(state.x.size());
  for (std::size_t i = 0; i < x_.size(); ++i) x_[i] = state.x[i] + dt * state.v[i];  // x̂
  double energy_scale = 0.0;  // the size of E's terms, for its round-off
  double energy = potential_.energy(model, x_, energy_scale);
  int iterations = 0;
  bool converged = false;
  IncrementalPotential::Hessian form = IncrementalPotential::Hessian::Exact;
  while (iterations < kMostNewtonIterations) {
    if (potential_.has_lagged_terms() && iterations < kMostLagUpdates) {
      potential_.update_lags(model, x_);
      energy = potential_.energy(model, x_, energy_scale);  // E with the new lags
    }
    // The exact Hessian while it is positive definite; once it is not, the definite one for the rest of the step.
    bool definite = solve_for_direction(model, form);
    if (!definite && form == IncrementalPotential::Hessian::Exact) {
      form = IncrementalPotential::Hessian::Definite;
      definite = solve_for_direction(model, form);
    }
    if (!definite) break;  // only with values that are not finite: the guard reports the state
    ++iterations;
    const double largest = direction_.lpNorm<Eigen::Infinity>();
    if (!std::isfinite(largest)) break;
    const double slope = gradient_.dot(direction_);  // ∇E·Δ < 0: a descent direction
    if (largest <= kNewtonTolerance * dt || -slope <= kEnergyRoundOff * energy_scale) {
      move_along_direction(1.0);
      std::swap(x_, trial_);
      converged = largest <= kNewtonTolerance * dt;
      if (converged) break;
      energy = potential_.energy(model, x_, energy_scale);
      continue;
    }
    double alpha = 1.0;
    bool decreased = false;
    for (int halving = 0; halving <= kMostHalvings; ++halving, alpha *= 0.5) {
      move_along_direction(alpha);
      double trial_scale = 0.0;
      const double trial_energy = potential_.energy(model, trial_, trial_scale);
      if (trial_energy <= energy + kArmijo * alpha * slope) {
        energy = trial_energy;
        energy_scale = trial_scale;
        decreased = true;
        break;
      }
      ++statistics_.halvings;
    }
    if (!decreased) break;  // no decrease along Δ: x_ is as close as the round-off in E allows
    std::swap(x_, trial_);
  }
  for (std::size_t i = 0; i < x_.size(); ++i) {
    state.v[i] = (x_[i] - state.x[i]) / dt;
    state.x[i] = x_[i];
  }
  ++statistics_.steps;
  statistics_.iterations += iterations;
  statistics_.most_iterations = std::max(statistics_.most_iterations, iterations);
  if (!converged) ++statistics_.unconverged_steps;
}

}  // namespace sim
