// Velocity Verlet step.
#include "sim/integrators/velocity_verlet.hpp"

namespace sim {

void VelocityVerlet::step(Dynamics& dynamics, State& state, double dt) {
  if (!have_acceleration_) dynamics.accelerations(state, a_);
  const std::size_t n = state.x.size();
  predicted_.x.resize(n);
  predicted_.v.resize(n);
  const double half = 0.5 * dt;
  for (std::size_t i = 0; i < n; ++i) {
    state.v[i] += half * a_[i];                        // first kick: v½
    state.x[i] += dt * state.v[i];                     // drift
    predicted_.x[i] = state.x[i];
    predicted_.v[i] = state.v[i] + half * a_[i];       // v* = v + h a_n, only the dampers see it
  }
  dynamics.accelerations(predicted_, a_);
  for (std::size_t i = 0; i < n; ++i) state.v[i] += half * a_[i];  // second kick
  have_acceleration_ = true;
}

}  // namespace sim
