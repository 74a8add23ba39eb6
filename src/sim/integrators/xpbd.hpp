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
//   2. edges     one pass over every edge constraint C = |x_i − x_j| − L0, colour by colour (EdgeColouring):
//                with compliance α = 1/k, damping β = c (the Rayleigh dissipation ½ β Ċ² of the dashpot c along
//                the edge) and γ = α β / h (XPBD Eq. 26, λ = 0 at the start of the single iteration):
//                  Δλ = (−C − γ ∇C·(x − x_prev)) / ((1 + γ) (w_i + w_j) + α/h²)
//                multiplied through by k h², which also serves k = 0 (a damper alone) and c = 0:
//                  Δλ = (−k h² C − c h ∇C·(x − x_prev)) / ((k h² + c h)(w_i + w_j) + 1)      [m·kg]
//                  x_i += w_i Δλ n̂,  x_j −= w_j Δλ n̂,  n̂ = (x_i − x_j)/|x_i − x_j|, w = 1/m
//   2b. bending  the same pass over the bending links (sim/forces/bending.hpp) with k_b, c_b and their own colouring,
//                after the edges (bodies without bending stiffness skip it)
//   3. velocity  v = (x − x_prev)/h
//
// The velocities are those of the half substeps, (x − x_prev)/h, as in the leapfrog form of symplectic Euler:
// the first substep of a run (nothing carried yet: the start, a state whose carry was forgotten) kicks by h/2,
// v_{1/2} = v_0 + ½ h a_0, and the others by h. The positions are then exact for a constant force (gravity: a
// falling centre of mass) instead of leading by ½ g h t as a whole first kick makes them (tests/integrators/
// free_fall_test.cpp); the velocity written out at a frame is the last half substep's, ½ h a behind.
//
// The carried form, taken when h ≤ xpbd_carried_dt (sim/step/stability.hpp; from ω_max of the body at the initial
// state, springs, gas and contact): every edge and link carries the force its constraint exerted in the last
// substep, T_e = −Δλ/h² (a tension along the edge, in State::carry.edge_tension_N), step 1 also applies those
// forces, f_i −= T_e n̂_e at the start of the substep, and step 2 solves only for the change, with C replaced by
//                  C − T_e/k      (and, as always, ∇C·(x − x_prev) from the predicted x, which includes T's push)
// after which T_e ← T_e − Δλ/h² (a constraint without a spring, k = 0, carries nothing: its damper's carried
// force would have no C − T/k to cancel it and would count twice). This is a warm start carried across substeps: one
// Gauss–Seidel pass per substep cannot carry a steady load (the gas's) across the network, so the classical form leaves
// a pressurised ball short of its equilibrium (inflated); with the load carried there is nothing left to correct at
// rest (x* = x: C − T_e/k = 0 when T_e = k C), and the pass only has to follow the load's changes. For one spring it is
// still exactly backward Euler (the carried push cancels in the algebra: Δλ = Δλ_classical + h² T). Its explicit
// part costs a stability limit (measured on the bounce ball: icosphere:5 ran at h ω_max 3.1 and diverged at
// 4.7; icosphere:3 ran at 2.9), which the switch keeps away from; the classical form needs no limit.
// (It replaced a linearised form that applied the springs' forces at the start of the substep, k C(x_prev) and
// the damper's, explicitly: that one diverged on icosphere:5 at h ω_max 1.08 and needed 188 substeps per 1/60 s.)
//
// Why it is the same model: for h → 0 the correction is Δx_i = −h² w_i (k C + c Ċ) n̂ = h² f_i/m_i, the
// spring-damper force of sim/forces/forces.hpp (in the carried form the carried part and the correction sum to it, to
// first order: the carried force's direction is the start of the substep's), so the substeps converge to the
// same ODE as the other integrators, at first order (one Gauss–Seidel sweep, symplectic Euler in the limit). At
// large h the springs behave like backward Euler: no step limit from them; the explicit gas and gravity in
// step 1 keep symplectic Euler's limit h < 2/ω_gas (sim/step/stability.hpp).
// One distance constraint as xpbd's pass reads it: a copy of the body's set laid out in the pass's (colour) order,
// so that the pass reads one record after another.
struct PassConstraint {
  int i = 0, j = 0;       // the body's local vertices
  std::size_t index = 0;  // in the body's constraint set (and its carried tensions)
  double rest_length_m = 0.0, stiffness_N_per_m = 0.0, damping_N_s_per_m = 0.0;
  double inverse_stiffness = 0.0;  // 1/k [m/N] (0 without a spring)
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
  std::vector<std::vector<PassConstraint>> passes_;
  std::vector<double> carried_dt_;          // per body: xpbd_carried_dt at the initial state, contacts included [s]
  std::vector<std::size_t> first_tension_;  // per body: its constraints' first entry in carry.edge_tension_N
  std::size_t tension_count_ = 0;           // every body's constraints
  std::vector<Vec3> previous_x_;            // scratch: x at the start of the substep
  std::vector<Vec3> force_;                 // scratch: gravity + gas (+ carried tensions) on every vertex [N]
};

}  // namespace sim
