// Classical Runge–Kutta step.
#include "sim/integrators/runge_kutta4.hpp"

namespace sim {

void RungeKutta4::step(Dynamics& dynamics, State& state, double dt) {
  evaluate_slope(dynamics, state, k_[0]);
  combine<1>(state, 0.5 * dt, {1.0}, {&k_[0]}, stage_);
  evaluate_slope(dynamics, stage_, k_[1]);
  combine<1>(state, 0.5 * dt, {1.0}, {&k_[1]}, stage_);
  evaluate_slope(dynamics, stage_, k_[2]);
  combine<1>(state, dt, {1.0}, {&k_[2]}, stage_);
  evaluate_slope(dynamics, stage_, k_[3]);
  combine<4>(state, dt, {1.0 / 6.0, 2.0 / 6.0, 2.0 / 6.0, 1.0 / 6.0}, {&k_[0], &k_[1], &k_[2], &k_[3]}, stage_);
  std::swap(state.x, stage_.x);  // swaps buffers, no copy and no allocation
  std::swap(state.v, stage_.v);
}

}  // namespace sim
