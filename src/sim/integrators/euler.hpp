// Forward (explicit) Euler, the paper's integrator.
#pragma once

#include "sim/integrators/integrators.hpp"

namespace sim {

// Matyka & Ollila (2003), Eq. 11: positions and velocities both from the state at the start of the step,
// x' = x + h v, v' = v + h a(x, v). First order; the energy of an undamped oscillator of angular frequency
// ω grows by the factor (1 + h²ω²) every step, so it needs damping to stay bounded. Carries nothing.
class ForwardEuler final : public Integrator {
 public:
  void step(Dynamics& dynamics, State& state, double dt) override;
};

}  // namespace sim
