// Semi-implicit (symplectic) Euler.
#pragma once

#include "sim/integrators.hpp"

namespace sim {

// v' = v + h a(x, v), then x' = x + h v' (Hairer, Lubich & Wanner, Geometric Numerical Integration,
// Sect. I.1.2). First order, one force evaluation per step; for conservative forces it is symplectic, so
// the energy error stays bounded (oscillates) instead of drifting. Dampers use the old velocity.
class SymplecticEuler final : public Integrator {
 public:
  void step(Dynamics& dynamics, State& state, double dt) override;

 private:
  std::vector<Vec3> a_;
};

}  // namespace sim
