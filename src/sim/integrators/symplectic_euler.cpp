// Semi-implicit Euler step.
#include "sim/integrators/symplectic_euler.hpp"

namespace sim {

void SymplecticEuler::step(Dynamics& dynamics, State& state, double dt) {
  // The vertices the floor reversed coast: their kick is skipped (see the header). The fused step kicks
  // every vertex, so their x and v are kept and set afterwards to x + h v, v.
  coasting_state_.clear();
  for (int i : coasting_) coasting_state_.push_back({state.x[i], state.v[i]});
  dynamics.first_order_step(state, dt, FirstOrderUpdate::Symplectic, a_);
  for (std::size_t c = 0; c < coasting_.size(); ++c) {
    const auto [x, v] = coasting_state_[c];
    state.v[coasting_[c]] = v;
    state.x[coasting_[c]] = x + dt * v;  // the drift with the unkicked velocity
  }
  coasting_.clear();
}

void SymplecticEuler::velocities_reversed(std::span<const int> vertices) {
  coasting_.insert(coasting_.end(), vertices.begin(), vertices.end());
}

}  // namespace sim
