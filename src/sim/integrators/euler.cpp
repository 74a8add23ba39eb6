// Forward Euler step.
#include "sim/integrators/euler.hpp"

namespace sim {

void ForwardEuler::step(Dynamics& dynamics, State& state, double dt) {
  dynamics.first_order_step(state, dt, FirstOrderUpdate::Forward);
}

}  // namespace sim
