// Integrator implementations.
#include "sim/integrators.hpp"

namespace sim {

void ForwardEuler::step(Dynamics& dynamics, State& state, double dt) {
  dynamics.accelerations(state, a_);
  for (std::size_t i = 0; i < state.x.size(); ++i) {
    state.x[i] += dt * state.v[i];  // the old velocity: explicit in both
    state.v[i] += dt * a_[i];
  }
}

std::unique_ptr<Integrator> make_integrator(scene::Integrator kind) {
  switch (kind) {
    case scene::Integrator::Euler: return std::make_unique<ForwardEuler>();
  }
  return nullptr;
}

}  // namespace sim
