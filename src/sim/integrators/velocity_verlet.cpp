// Velocity Verlet step.
#include "sim/integrators/velocity_verlet.hpp"

namespace sim {

void VelocityVerlet::prepare(Dynamics& dynamics, State& state) {
  if (state.carry.acceleration.empty()) dynamics.accelerations(state, state.carry.acceleration);
}

void VelocityVerlet::step(Dynamics& dynamics, State& state, double dt) {
  std::vector<Vec3>& a = state.carry.acceleration;  // a_n on entry, a(x', v*) on return
  const std::size_t n = state.x.size();
  predicted_.x.resize(n);
  predicted_.v.resize(n);
  predicted_.time_s = state.time_s + dt;  // the end of the step (a keyframed collider's pose)
  const double half = 0.5 * dt;
  for (std::size_t i = 0; i < n; ++i) {
    state.v[i] += half * a[i];      // first kick: v½
    state.x[i] += dt * state.v[i];  // drift
    predicted_.x[i] = state.x[i];
    predicted_.v[i] = state.v[i] + half * a[i];  // v* = v + h a_n, only the dampers see it
  }
  dynamics.accelerations(predicted_, a);
  for (std::size_t i = 0; i < n; ++i) state.v[i] += half * a[i];  // second kick
}

}  // namespace sim
