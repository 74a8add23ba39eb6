// Linearised backward Euler (Baraff & Witkin 1998) with a conjugate-gradient solve.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "sim/integrators/integrators.hpp"
#include "sim/solvers/block_jacobi_cg.hpp"
#include "sim/solvers/block_system.hpp"

namespace sim {

// Baraff & Witkin, "Large steps in cloth simulation", SIGGRAPH 1998, Eqs. 6 and 15–16: one Newton step
// of backward Euler, v' = v + Δv, x' = x + h v', with
//   (M − h ∂f/∂v − h² ∂f/∂x) Δv = h (f0 + h ∂f/∂x v0).
// What is linearised and what is not:
//   - springs (the body's distance constraints: the edges and the bending links, sim/forces/bending.hpp): ∂f/∂x
//     assembled exactly except for the definiteness fix below;
//   - dampers: ∂f/∂v assembled exactly; their ∂f/∂x (small, non-symmetric) is dropped, as in the paper;
//   - pressure and gravity: explicit, in f0 only. The gas force's Jacobian is a dense rank-one term plus
//     an indefinite face term; the gas is soft next to the springs, so it does not limit the step here.
// Definiteness: a compressed spring's geometric term k (1 − L0/|d|)(I − d̂d̂ᵀ) is negative, which can make
// the matrix indefinite (Choi & Ko 2002). It is clamped at zero, so every spring block is positive
// semi-definite, the system matrix is symmetric positive definite, and conjugate gradients apply: the
// block-Jacobi preconditioned ones (sim/solvers/block_jacobi_cg.hpp), started from the last step's Δv.
// First order; its numerical damping removes energy at large h, so it is stable far beyond the explicit
// methods' limit (tests/integrators/stability_test.cpp).
//
// Allocation: the system's pattern and the vectors are built on the first step (and again if the number of
// vertices changes, i.e. another model); later steps only overwrite values.
// Carried over (State::carry.velocity_change): the last step's Δv, the solve's warm start.
class ImplicitEuler final : public Integrator {
 public:
  void step(Dynamics& dynamics, State& state, double dt) override;

 private:
  struct Spring {  // one distance constraint, world vertex indices
    int i = 0, j = 0;
    double rest_length_m = 0.0, stiffness_N_per_m = 0.0, damping_N_s_per_m = 0.0;
  };

  void build_pattern(const Model& model, std::size_t vertex_count);
  void assemble(const State& state, std::span<const double> mass_kg, double dt);

  std::vector<Spring> springs_;  // every body's constraints, in the system's pair order
  BlockSystem system_;           // A = M + h² K + h C
  BlockJacobiCg cg_;
  Eigen::VectorXd rhs_;
  std::vector<Vec3> force_;
  std::size_t pattern_vertices_ = 0;
};

}  // namespace sim
