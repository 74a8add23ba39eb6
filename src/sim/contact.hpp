// Contact with the floor plane y = height, applied after each integration step (the paper's and the friction
// model). Both put every vertex found below the plane back on it, so no vertex passes through the floor at
// any speed. The smooth contact is a force instead (sim/smooth_contact.hpp).
#pragma once

#include <span>
#include <vector>

#include "core/vec.hpp"
#include "sim/settings.hpp"

namespace sim {

using softbody::Vec3;

// What a floor pass found: how many vertices were below the floor, and how deep the deepest was before it
// was put back [m] (how far a step carried a vertex into the floor: a tunnelling check that can fail).
struct FloorContactFound {
  int below = 0;
  double deepest_m = 0.0;
};

// The paper's collision response (Matyka & Ollila 2003, Sect. 2.5): a vertex found below the floor
// gets the impulse J = m Δv with Δv = −2v, i.e. its whole velocity is reflected (v ← −v), and it is put
// back on the floor. Appends the indices of the vertices below to `reversed` (symplectic Euler needs to know
// whose motion was reversed: State::coasting).
FloorContactFound resolve_floor_paper(double height_m, std::span<Vec3> x, std::span<Vec3> v, std::vector<int>& reversed);

// Velocity-level impulse per vertex below the floor (per unit mass, so masses cancel), by the rule of
// sim/contact_response.hpp:
//   normal:     v_n' = −e v_n for an impact, 0 for a resting contact;
//   tangential: Δv_n = v_n' − v_n is the normal impulse; if |v_t| ≤ μ Δv_n the vertex sticks (v_t' = 0,
//               static friction), else it slides and loses μ Δv_n of tangential speed (sliding friction).
// The deepest penetration of any vertex below the floor (0: none) [m], for the smooth contact, which leaves
// vertices where its force put them.
double deepest_below_floor(double height_m, std::span<const Vec3> x);

FloorContactFound resolve_floor_friction(double height_m, const ContactMaterial& material, std::span<Vec3> x,
                                         std::span<Vec3> v);

}  // namespace sim
