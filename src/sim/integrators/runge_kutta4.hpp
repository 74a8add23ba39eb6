// The classical fourth-order Runge–Kutta method.
#pragma once

#include "sim/integrators/stage.hpp"

namespace sim {

// k1 = f(y), k2 = f(y + h/2 k1), k3 = f(y + h/2 k2), k4 = f(y + h k3), y' = y + h/6 (k1 + 2k2 + 2k3 + k4)
// (Hairer, Nørsett & Wanner, Solving ODEs I, Sect. II.1). Fourth order, four force evaluations per step;
// dampers are simply part of f. Not symplectic: the energy error drifts, slowly at small h.
class RungeKutta4 final : public Integrator {
 public:
  void step(Dynamics& dynamics, State& state, double dt) override;

 private:
  std::array<Slope, 4> k_;
  State stage_;
};

}  // namespace sim
