// Contact with the floor plane y = height, applied after each integration step. Both models put every
// vertex found below the plane back on it, so no vertex passes through the floor at any speed.
#pragma once

#include <span>
#include <vector>

#include "core/vec.hpp"

namespace sim {

using softbody::Vec3;

// The paper's collision response (Matyka & Ollila 2003, Sect. 2.5): a vertex found below the floor
// gets the impulse J = m Δv with Δv = −2v, i.e. its whole velocity is reflected (v ← −v), and it is put
// back on the floor. Returns the number of vertices that were below; appends their indices to `reversed`
// when given (the integrator may need to know whose motion was reversed: Integrator::velocities_reversed).
int resolve_floor_paper(double height_m, std::span<Vec3> x, std::span<Vec3> v, std::vector<int>* reversed = nullptr);

struct FrictionContact {
  double height_m = 0.0;
  double restitution = 0.5;  // e: normal speed after an impact = e × approach speed
  double friction = 0.5;     // μ: tangential impulse ≤ μ × normal impulse (Coulomb)
  // Below this approach speed a contact is resting, not an impact: no bounce, so that a body lying on
  // the floor does not jitter. 0.05 m/s is the speed gravity gives in 5 ms, well above one step's g·dt.
  double resting_speed_m_per_s = 0.05;
};

// Velocity-level impulse per vertex below the floor (per unit mass, so masses cancel):
//   normal:     v_n' = −e v_n if the approach speed −v_n exceeds the resting speed, else 0;
//   tangential: Δv_n = v_n' − v_n is the normal impulse; if |v_t| ≤ μ Δv_n the vertex sticks (v_t' = 0,
//               static friction), else it slides and loses μ Δv_n of tangential speed (sliding friction).
// Returns the number of vertices that were below.
int resolve_floor_friction(const FrictionContact& contact, std::span<Vec3> x, std::span<Vec3> v);

}  // namespace sim
