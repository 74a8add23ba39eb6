// Dormand–Prince 5(4): an embedded Runge–Kutta pair with step-size control.
#pragma once

#include "sim/integrators/stage.hpp"

namespace sim {

// Dormand & Prince (1980), "A family of embedded Runge–Kutta formulae", J. Comput. Appl. Math. 6:19–26;
// coefficients as in Hairer, Nørsett & Wanner, Solving ODEs I, Table II.5.2. Seven stages; the fifth-order
// solution is propagated (local extrapolation) and the last stage is f at the new state, so it serves as
// the next step's first stage (FSAL): six force evaluations per accepted step.
//
// Error estimate: err = RMS_i (ŷ_i − y_i) / (tol + tol·max(|y0_i|, |y_i|)) over every position [m] and
// velocity [m/s] component, where ŷ − y is the difference of the embedded 4th- and 5th-order solutions.
// sim::advance_to accepts a step when err <= 1 and sets the next step from err (sim/step/step_size.hpp).
//
// Carried over (State::carry.acceleration): the first stage's acceleration a(x, v) of the state, which the
// last step's seventh stage computed (FSAL).
class DormandPrince final : public AdaptiveIntegrator {
 public:
  explicit DormandPrince(double tolerance) : tolerance_(tolerance) {}

  // Without a carried first stage (the first step, or after a contact moved the state): a(x, v).
  void prepare(Dynamics& dynamics, State& state) override;
  // One fifth-order step of exactly dt, no error control (used for reference solutions).
  void step(Dynamics& dynamics, State& state, double dt) override;
  double attempt(Dynamics& dynamics, State& state, double dt) override;

 private:
  // Runs the seven stages from `state`; leaves the 5th-order result in result_ and k_[6] = f(result_).
  void stages(Dynamics& dynamics, const State& state, double dt);
  // The scaled RMS error of the step just computed by stages().
  double error_norm(const State& state, double dt) const;
  // state ← result_, and its first stage carried over.
  void advance(State& state);

  double tolerance_;
  std::array<Slope, 7> k_;  // scratch: the stages
  State stage_;
  State result_;
};

}  // namespace sim
