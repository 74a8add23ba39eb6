// Semi-implicit Euler step.
#include "sim/integrators/symplectic_euler.hpp"

namespace sim {

void SymplecticEuler::step(Dynamics& dynamics, State& state, double dt) {
  // The vertices the floor reversed coast: their kick is skipped (see the header). The fused step kicks
  // every vertex, so their x and v are kept and set afterwards to x + h v, v.
  coasting_state_.clear();
  for (int i : state.coasting) coasting_state_.push_back({state.x[i], state.v[i]});
  dynamics.first_order_step(state, dt, FirstOrderUpdate::Symplectic);
  for (std::size_t c = 0; c < state.coasting.size(); ++c) {
    const auto [x, v] = coasting_state_[c];
    state.v[state.coasting[c]] = v;
    state.x[state.coasting[c]] = x + dt * v;  // the drift with the unkicked velocity
  }
  state.coasting.clear();
}

}  // namespace sim
