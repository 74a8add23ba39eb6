// Semi-implicit Euler step.
#include "sim/integrators/symplectic_euler.hpp"

namespace sim {

void SymplecticEuler::step(Dynamics& dynamics, State& state, double dt) {
  dynamics.accelerations(state, a_);
  for (std::size_t i = 0; i < state.x.size(); ++i) {
    state.v[i] += dt * a_[i];
    state.x[i] += dt * state.v[i];  // the new velocity
  }
}

}  // namespace sim
