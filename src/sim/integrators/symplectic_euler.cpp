// Semi-implicit Euler step.
#include "sim/integrators/symplectic_euler.hpp"

namespace sim {

void SymplecticEuler::step(Dynamics& dynamics, State& state, double dt) {
  dynamics.first_order_step(state, dt, FirstOrderUpdate::Symplectic, a_);
}

}  // namespace sim
