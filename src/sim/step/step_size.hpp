// Step-size control for adaptive integrators: whether an attempt is accepted, and the next step size.
#pragma once

#include "sim/model/state.hpp"

namespace sim {

struct StepSizeDecision {
  bool accepted = false;   // the attempt's error was within the tolerance
  double next_dt_s = 0.0;  // the step to try next
};

// After an attempt of dt with scaled error norm `error` (<= 1: within the tolerance). Accepted: PI control
// (Gustafsson 1991; Hairer, Nørsett & Wanner, Solving ODEs II, Sect. IV.2, and Hairer's DOPRI5 code),
// h_new = h · 0.9 · err^(−α) · err_prev^β with α = 1/5 − 0.75 β, growing at most 5× and not at all right
// after a rejection; the controller's memory in `carry` is updated. Rejected (also a NaN or infinite error):
// h shrinks by 0.9·err^(−1/5) (Hairer et al., Eq. II.4.13), at least to a fifth; `carry` is left alone (the
// caller restores the state and then records the rejection with record_rejection()).
StepSizeDecision decide_step_size(double dt, double error, IntegratorCarry& carry);

// The controller's memory after a rejected attempt: the next accepted step may not grow.
inline void record_rejection(IntegratorCarry& carry) { carry.rejected_last = true; }

}  // namespace sim
