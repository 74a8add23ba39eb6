// Backward Euler solved by Newton's method on its incremental potential, with a line search.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "sim/integrators/incremental_potential.hpp"
#include "sim/integrators/integrators.hpp"
#include "sim/solvers/block_jacobi_cg.hpp"
#include "sim/solvers/block_system.hpp"

namespace sim {

// Backward Euler, x' = x + h v', M v' = M v + h f(x', v'), every force implicit (springs, dampers, gas,
// gravity), solved as the minimisation of the incremental potential E (sim/integrators/incremental_potential.hpp;
// Gast et al. 2015) by Newton's method:
//   x ← x̂ = x_n + h v_n; repeat: solve ∇²E Δ = −∇E (inexactly, below), then a backtracking line search
//   x ← x + αΔ, α = 1, ½, ..., until E(x + αΔ) ≤ E(x) + 10⁻⁴ α ∇E·Δ (Armijo; Nocedal & Wright, Numerical
//   Optimization, Sect. 3.1); stop once |Δ|∞ ≤ kNewtonTolerance·h (no velocity changes by more than 10⁻⁷ m/s;
//   that last step is taken without a search), or after kMostNewtonIterations; then v' = (x − x_n) / h.
// The Hessian: the exact ∇²E while it is positive definite, which gives Newton's fast local convergence; once
// conjugate gradients meet a direction of non-positive curvature, for the rest of the step, the definite form
// (compressed springs clamped, the gas's face curvature projected: sim/integrators/incremental_potential.hpp).
// Either way Δ is a descent direction and every accepted iterate lowers E: the iteration cannot run away,
// whatever h.
// The solve (a truncated Newton method, Nocedal & Wright Sect. 7.1): ∇²E = A + Σ_b u_b u_bᵀ, A the sparse
// part (BlockSystem: pattern built once per model, values overwritten each iteration), u_b the gas's rank-one
// term of body b (and the smooth body contact's terms, three per contact over its four vertices), applied as the
// product u_b (u_bᵀ p) inside conjugate gradients, so the dense matrix is never formed
// (sim/solvers/block_jacobi_cg.hpp: block-Jacobi preconditioned, started from zero), to a relative residual of
// kSolveTolerance: a direct LDLᵀ costs far more per step, and its fill grows faster than the vertices. Why backward
// Euler and not BDF2 or the implicit midpoint rule: it is L-stable (stiff modes are damped, not left ringing at 1/60 s
// steps) and a pure minimisation (the line search needs no energy safeguard); the price is first-order accuracy and
// numerical damping of the slow modes (measured: docs/physics/integrators.md, "Large steps: `newton`"; the direct
// solve: docs/notes/2026-12-01-newton.md).
//
// Nothing is carried between steps (the Newton iteration starts from x̂ and each solve from zero), so a State
// copy is a checkpoint. No allocation per step once sizes settle: the pattern, the gas terms and every vector are
// built on the first step (again only for a model with another vertex count); the body contacts' list grows to
// the most contacts met.
class NewtonEuler final : public Integrator {
 public:
  // Counts over every step this object took, for benchmarks and tests.
  struct Statistics {
    long long steps = 0;
    long long iterations = 0;         // Newton iterations
    long long solves = 0;             // conjugate-gradient solves (a non-definite exact Hessian costs a second)
    long long cg_iterations = 0;      // over all solves
    long long halvings = 0;           // line-search step halvings
    long long unconverged_steps = 0;  // stopped by kMostNewtonIterations or a failed line search
    int most_iterations = 0;          // in one step
  };

  void step(Dynamics& dynamics, State& state, double dt) override;
  const Statistics& statistics() const { return statistics_; }

 private:
  void build(const Model& model);
  // direction_ ≈ −(∇²E)⁻¹ ∇E with the Hessian in `form` (assembled here with the gradient); false if the
  // Hessian was not positive definite.
  bool solve_for_direction(const Model& model, IncrementalPotential::Hessian form);
  // trial_ = x_ + alpha · direction_.
  void move_along_direction(double alpha);

  IncrementalPotential potential_;
  BlockSystem hessian_;
  BlockJacobiCg cg_;
  std::vector<RankOneTerm> gas_terms_;  // views of the potential's gas terms
  std::vector<RankOneTerm> terms_;      // gas_terms_, then views of the body contacts' terms of this assembly
  Eigen::VectorXd gradient_, right_side_, direction_;
  std::vector<Vec3> x_, trial_;
  std::size_t built_for_vertices_ = 0;
  Statistics statistics_;
};

}  // namespace sim
