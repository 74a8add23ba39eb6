// Velocity Verlet with one force evaluation per step.
#pragma once

#include "sim/integrators/integrators.hpp"

namespace sim {

// Kick–drift–kick (Swope et al. 1982):
//   v½ = v + (h/2) a_n,   x' = x + h v½,   a' = a(x', v*),   v' = v½ + (h/2) a'.
// The acceleration a' is carried to the next step's first kick (State::carry.acceleration), so each step
// costs one force evaluation.
//
// Dampers make a depend on v, and v' is not known when a' is needed. Using v½ there would leave an O(h)
// error in a', i.e. O(h²) per step: first order in the damping part. Instead the damping is evaluated at
// the predicted velocity v* = v½ + (h/2) a_n = v + h a_n, which is O(h²) from v', so the kick's error is
// O(h³) per step and the method stays second order with dampers too (checked in
// tests/integrators/convergence_test.cpp). Without dampers v* does not matter and this is the textbook,
// symplectic, time-reversible method.
class VelocityVerlet final : public Integrator {
 public:
  // Without a carried acceleration (the first step, or after a contact moved the state): a(x, v).
  void prepare(Dynamics& dynamics, State& state) override;
  void step(Dynamics& dynamics, State& state, double dt) override;

 private:
  State predicted_;  // scratch: (x', v*), where the end-of-step acceleration is evaluated
};

}  // namespace sim
