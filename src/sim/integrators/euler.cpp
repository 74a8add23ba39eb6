// Forward Euler step.
#include "sim/integrators/euler.hpp"

namespace sim {

void ForwardEuler::step(Dynamics& dynamics, State& state, double dt) {
  dynamics.accelerations(state, a_);
  for (std::size_t i = 0; i < state.x.size(); ++i) {
    state.x[i] += dt * state.v[i];  // the old velocity: explicit in both
    state.v[i] += dt * a_[i];
  }
}

}  // namespace sim
