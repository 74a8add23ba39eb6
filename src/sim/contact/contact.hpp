// Contact with the floor plane y = height, applied after each integration step (the paper's and the friction
// model). Both put every vertex found below the plane back on it, so no vertex passes through the floor at
// any speed. The smooth contact is a force instead (sim/contact/smooth_contact.hpp).
#pragma once

#include <span>
#include <vector>

#include "core/vec.hpp"
#include "sim/model/settings.hpp"

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
FloorContactFound resolve_floor_paper(double height_m, std::span<Vec3> x, std::span<Vec3> v,
                                      std::vector<int>& reversed);

// Velocity-level impulse per vertex below the floor (per unit mass, so masses cancel), by the rule of
// sim/contact/contact_response.hpp:
//   normal:     v_n' = −e v_n for an impact, 0 for a resting contact;
//   tangential: Δv_n = v_n' − v_n is the normal impulse; if |v_t| ≤ μ Δv_n the vertex sticks (v_t' = 0,
//               static friction), else it slides and loses μ Δv_n of tangential speed (sliding friction).
// The deepest penetration of any vertex below the floor (0: none) [m], for the smooth contact, which leaves
// vertices where its force put them.
double deepest_below_floor(double height_m, std::span<const Vec3> x);

FloorContactFound resolve_floor_friction(double height_m, const ContactMaterial& material, std::span<Vec3> x,
                                         std::span<Vec3> v);

// The friction floor of a position-based integrator (xpbd), after each substep of h seconds whose velocities
// are v = (x − x_prev)/h, as in Müller et al., "Detailed Rigid Body Simulation with Extended Position Based
// Dynamics" (SCA 2020, Sect. 3.5–3.6) for a particle (masses cancel). A vertex below the floor by d:
//   position:   y ← floor (the normal constraint y ≥ floor, correction d);
//               static friction: if the substep's tangential travel |h v_t| ≤ μ d, it is undone (x_t ← x_prev,t,
//               v_t = 0): the vertex sticks where it touched down;
//   velocity:   otherwise sliding friction takes min(μ d / h, |v_t|) of the tangential speed (the normal force
//               of the correction, f_n = d m / h², over the substep: Δv = h μ f_n / m);
//               the normal speed becomes −e v_n for an impact, 0 for a resting contact
//               (sim/contact/contact_response.hpp), never the d/h that the correction itself would imply.
FloorContactFound resolve_floor_positional(double height_m, const ContactMaterial& material, double h,
                                           std::span<Vec3> x, std::span<Vec3> v);

}  // namespace sim
