// Dormand–Prince 5(4): an embedded Runge–Kutta pair with step-size control.
#pragma once

#include "sim/integrators/stage.hpp"

namespace sim {

// Dormand & Prince (1980), "A family of embedded Runge–Kutta formulae", J. Comput. Appl. Math. 6:19–26;
// coefficients as in Hairer, Nørsett & Wanner, Solving ODEs I, Table II.5.2. Seven stages; the fifth-order
// solution is propagated (local extrapolation) and the last stage is f at the new state, so it serves as
// the next step's first stage (FSAL): six force evaluations per accepted step.
//
// Error control: err = RMS_i (ŷ_i − y_i) / (tol + tol·max(|y0_i|, |y_i|)) over every position [m] and
// velocity [m/s] component, where ŷ − y is the difference of the embedded 4th- and 5th-order solutions.
// A step is accepted when err <= 1. After a rejection the step shrinks by 0.9·err^(−1/5) (Hairer et al.,
// Eq. II.4.13); after an acceptance a PI controller sets it (see dormand_prince.cpp), growing at most 5×
// and not at all right after a rejection.
class DormandPrince final : public AdaptiveIntegrator {
 public:
  explicit DormandPrince(double tolerance) : tolerance_(tolerance) {}

  // One fifth-order step of exactly dt, no error control (used for reference solutions).
  void step(Dynamics& dynamics, State& state, double dt) override;
  Attempt attempt(Dynamics& dynamics, State& state, double dt) override;
  void restart() override { have_first_slope_ = false; }

 private:
  // Runs the seven stages from `state`; leaves the 5th-order result in result_ and k_[6] = f(result_).
  void stages(Dynamics& dynamics, const State& state, double dt);
  // The scaled RMS error of the step just computed by stages().
  double error_norm(const State& state, double dt) const;
  void accept(State& state);

  double tolerance_;
  std::array<Slope, 7> k_;
  State stage_;
  State result_;
  bool have_first_slope_ = false;  // k_[0] = f(state) from the previous step's last stage
  bool rejected_last_ = false;     // the previous attempt failed: do not grow the step now
  double previous_error_ = 1e-4;   // err of the last accepted step, for the PI controller
};

}  // namespace sim
