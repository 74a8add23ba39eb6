// Substepped extended position-based dynamics (XPBD) for the same springs, dampers and gas.
#pragma once

#include <vector>

#include "sim/integrators/integrators.hpp"
#include "sim/solvers/edge_colouring.hpp"
#include "sim/step/stability.hpp"

namespace sim {

// One call of step(h) is one XPBD substep (Macklin, Müller & Chentanez, "XPBD: Position-Based Simulation of
// Compliant Constrained Dynamics", MIG 2016; Macklin et al., "Small Steps in Physics Simulation", SCA 2019:
// n substeps of one constraint iteration each). The frame clock splits each frame interval into
// solver.substeps of them (sim::Solver), and sim::step runs the contacts after each one.
//
//   1. predict   v ← v + h (f_gravity + f_gas)/m,  x ← x + h v      x* = x + h v + h² f/m, the gas explicit
//   2. edges     one pass over every edge constraint C = |x_i − x_j| − L0, colour by colour (EdgeColouring),
//                compliance α = 1/k, damping β = c, γ = α β / h (XPBD Eq. 26), multiplied through by k h²:
//                  Δλ = (−k h² C − c h ∇C·(x − x_prev)) / ((k h² + c h)(w_i + w_j) + 1)      [m·kg]
//                  x_i += w_i Δλ n̂,  x_j −= w_j Δλ n̂,  n̂ = (x_i − x_j)/|x_i − x_j|, w = 1/m
//   2b. bending  the same pass over the bending links (sim/forces/bending.hpp) with k_b, c_b and their own colouring
//   3. velocity  v = (x − x_prev)/h
//
// Leapfrog start: the first substep of a run (nothing carried) kicks by h/2, the others by h, so the positions
// are exact for a constant force (tests/integrators/free_fall_test.cpp); the velocity written out is ½ h a behind.
//
// The carried form, taken when h ≤ xpbd_carried_dt (sim/step/stability.hpp): every edge and link carries the
// tension of its last substep, T_e = −Δλ/h² [N] (State::carry.edge_tension_N), step 1 applies it and step 2
// solves for its change, with C − T_e/k in place of C. Why: one Gauss–Seidel pass per substep cannot carry the
// gas's steady load across the network, so the classical form leaves a pressurised ball inflated; carried,
// nothing is left to correct at rest. Its explicit part costs a stability limit, which the switch keeps away from.
// Both forms converge to the spring-damper ODE of sim/forces/forces.hpp at first order as h → 0; at large h the
// springs behave like backward Euler, and the explicit gas keeps h < 2/ω_gas.
// The derivation, the measurements and the form this replaced: docs/notes/2026-12-05-header-derivations.md;
// for users: docs/physics/integrators.md, "Large steps: `xpbd`".
// One distance constraint as xpbd's pass reads it: a copy of the body's set laid out in the pass's (colour) order,
// so that the pass reads one record after another.
struct PassConstraint {
  int i = 0, j = 0;            // the body's local vertices
  std::size_t index = 0;       // in the body's constraint set (and its carried tensions)
  double rest_length_m = 0.0;  // L0
};

// A run of the pass whose constraints share their k and c (the edges' run, then the bending links'), so that the
// inner loop reads only ends and rest lengths.
struct PassSegment {
  std::size_t begin = 0, end = 0;  // [begin, end) in Pass::constraints
  double stiffness_N_per_m = 0.0, damping_N_s_per_m = 0.0;
  double inverse_stiffness = 0.0;  // 1/k [m/N] (0 without a spring)
};

struct Pass {
  std::vector<PassConstraint> constraints;
  std::vector<PassSegment> segments;
};

class Xpbd final : public Integrator {
 public:
  void step(Dynamics& dynamics, State& state, double dt) override;

 private:
  // The passes' orders, every body's offsets into the carried tensions and its form's limit, on the first step.
  void prepare_once(const Model& model);
  // Whether body b's substeps of h take the carried form (h ≤ xpbd_carried_dt).
  bool carried(std::size_t b, double h) const { return h <= carried_dt_[b]; }

  // Per body of the model: its constraints in colour order (the edges' colours, then the links'), on the first step.
  std::vector<Pass> passes_;
  std::vector<double> carried_dt_;          // per body: xpbd_carried_dt at the initial state, contacts included [s]
  std::vector<std::size_t> first_tension_;  // per body: its constraints' first entry in carry.edge_tension_N
  std::size_t tension_count_ = 0;           // every body's constraints
  std::vector<Vec3> previous_x_;            // scratch: x at the start of the substep
  std::vector<Vec3> force_;                 // scratch: gravity + gas (+ carried tensions) on every vertex [N]
};

}  // namespace sim
