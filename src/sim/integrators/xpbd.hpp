// Substepped extended position-based dynamics (XPBD) for the same springs, dampers and gas.
#pragma once

#include <vector>

#include "sim/edge_colouring.hpp"
#include "sim/integrators.hpp"
#include "sim/stability.hpp"

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
//   2b. bending  the same pass over the bending links (sim/bending.hpp) with k_b, c_b and their own colouring,
//                after the edges (bodies without bending stiffness skip it)
//   3. velocity  v = (x − x_prev)/h
//
// The linearised form, taken when h ≤ xpbd_linearised_dt (sim/stability.hpp; from ω_max of the body at the
// initial state, springs, gas and contact, and its vertex count): step 1 also takes the springs' and dampers' forces at the start
// of the substep, f_s(x, v), and step 2 corrects only what they got wrong, with C and ∇C·(x − x_prev) replaced by
//                  C − C(x_prev)  and  ∇C·(x − x_prev) − h Ċ(x_prev, v_prev)
// in the same Δλ. For one spring it is still exactly backward Euler (the explicit force cancels in the algebra);
// for the network it removes the classical form's bias: at rest (x* = x) there is nothing left to correct, so
// the one Gauss–Seidel pass cannot leave the network short of its equilibrium, and the pressurised ball flies
// at the converged volume. The explicit part costs a stability limit like symplectic Euler's (h ω_max below
// about 2 on icosphere:3, 1 on icosphere:5, measured), which the switch keeps away from; above it the classical form needs no limit.
//
// Why it is the same model: for h → 0 the correction is Δx_i = −h² w_i (k C + c Ċ) n̂ = h² f_i/m_i, the
// spring-damper force of sim/forces.hpp, so the substeps converge to the same ODE as the other integrators,
// at first order (the pass is one Gauss–Seidel sweep, symplectic Euler in the limit). At large h the springs
// behave like backward Euler: no step limit from them; the explicit gas and gravity in step 1 keep
// symplectic Euler's limit h < 2/ω_gas (sim/stability.hpp). Nothing is carried between substeps but x, v.
// The linearised form converges to the same ODE (its corrections vanish faster as h → 0).
class Xpbd final : public Integrator {
 public:
  void step(Dynamics& dynamics, State& state, double dt) override;

 private:
  // The colourings and every body's fastest mode, on the first step.
  void prepare_once(const Model& model);
  // Whether body b's substeps of h take the linearised form (h ≤ xpbd_linearised_dt).
  bool linearised(std::size_t b, double h) const { return h <= linearised_dt_[b]; }

  std::vector<EdgeColouring> colourings_;  // per body of the model, computed on the first step
  std::vector<EdgeColouring> link_colourings_;  // per body: its bending links (empty without bending)
  std::vector<double> linearised_dt_;      // per body: xpbd_linearised_dt at the initial state, contacts included [s]
  std::vector<Vec3> previous_x_;           // scratch: x at the start of the substep
  std::vector<Vec3> previous_v_;           // scratch: v at the start of the substep
  std::vector<Vec3> force_;                // scratch: gravity + gas on every vertex [N]
};

}  // namespace sim
