// Semi-implicit (symplectic) Euler.
#pragma once

#include <array>

#include "sim/integrators/integrators.hpp"

namespace sim {

// v' = v + h a(x, v), then x' = x + h v' (Hairer, Lubich & Wanner, Geometric Numerical Integration,
// Sect. I.1.2). First order, one force evaluation per step; for conservative forces it is symplectic, so
// the energy error stays bounded (oscillates) instead of drifting. Dampers use the old velocity.
//
// Floor contact (the paper's v ← −v). Kick-drift is leapfrog with the stored velocity at the half step:
// after a step the state is (x_{n+1}, v_{n+½}), the velocity that drifted x_n to x_{n+1}. Negating v_{n+½}
// is not the time reversal of the motion (symplectic Euler is not symmetric: R G R ≠ G⁻¹ for R = diag(1, −1)),
// and a vertex pressed onto the floor, reversed every step or two, gains energy: for a mode
// ẍ = −μx − γẋ the map R·G has det −(1 − hγ) and trace hγ − h²μ, so |eigenvalues| ≤ 1 only while
// h ≤ 2γ/μ = 2c/k (springs and dampers share λ), and at no h without dampers (docs/physics/stability.md,
// "Floor contact and the step"). The reversal in the integrator's own terms negates the velocity at x_{n+1},
// v_{n+1} = v_{n+½} + (h/2) a_{n+1}: the stored velocity becomes −v_{n+½} − h a_{n+1}, so the next kick gives
// exactly −v_{n+½}. A reversed vertex therefore skips its next kick, and the floor costs symplectic Euler nothing.
// The floor's contact phase lists the vertices it reversed in State::coasting; the next step reads the list
// and empties it.
class SymplecticEuler final : public Integrator {
 public:
  void step(Dynamics& dynamics, State& state, double dt) override;

 private:
  std::vector<std::array<Vec3, 2>> coasting_state_;  // scratch: the coasting vertices' x and v before the step
};

}  // namespace sim
