// Semi-implicit Euler step.
#include "sim/integrators/symplectic_euler.hpp"

namespace sim {

void SymplecticEuler::step(Dynamics& dynamics, State& state, double dt) {
  dynamics.accelerations(state, a_);
  for (int i : coasting_) a_[i] = Vec3::Zero();  // the time-reversed vertex: v already holds −v_{n+½}
  coasting_.clear();
  for (std::size_t i = 0; i < state.x.size(); ++i) {
    state.v[i] += dt * a_[i];
    state.x[i] += dt * state.v[i];  // the new velocity
  }
}

void SymplecticEuler::velocities_reversed(std::span<const int> vertices) {
  coasting_.insert(coasting_.end(), vertices.begin(), vertices.end());
}

}  // namespace sim
