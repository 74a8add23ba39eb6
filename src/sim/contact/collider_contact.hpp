// The floor's post-step contact models (sim/contact/contact.hpp) against a collider: the same rules with the
// floor's height and +y replaced by the collider's signed distance d and outward normal n at each vertex
// (sim/contact/collider_shape.hpp). A vertex inside (d < 0) is put on the nearest surface point, so none stays
// inside at any speed; the smooth contact is a force instead (sim/contact/smooth_collider.hpp). A moving collider's
// responses act on the velocity relative to its surface's, v − u(x) (sim/contact/collider_motion.hpp). Given the
// step's start (`start`), a vertex that the step took through the shape or past its middle is put back on the face
// it came in by (sim/contact/collider_sweep.hpp); without it (nullptr) the test is the discrete one.
#pragma once

#include <span>
#include <vector>

#include "sim/contact/collider_sweep.hpp"
#include "sim/contact/contact.hpp"
#include "sim/model/settings.hpp"

namespace sim {

// The paper's response (Matyka & Ollila 2003, Sect. 2.5): v ← −v, x ← the closest surface point. Appends the
// vertices reversed to `reversed` (symplectic Euler's State::coasting).
FloorContactFound resolve_collider_paper(const ColliderGeometry& collider, std::span<Vec3> x, std::span<Vec3> v,
                                         std::vector<int>& reversed, const ColliderStepStart* start = nullptr);

// Restitution and Coulomb friction impulses per unit mass (contact_response.hpp) on v = v_n n + v_t:
// v_n' = −e v_n for an impact (0 for a resting contact); the tangential part sticks if |v_t| ≤ μ (v_n' − v_n), else
// loses μ (v_n' − v_n) of its speed.
FloorContactFound resolve_collider_friction(const ColliderGeometry& collider, const ContactMaterial& material,
                                            std::span<Vec3> x, std::span<Vec3> v,
                                            const ColliderStepStart* start = nullptr);

// The positional friction contact of a position-based integrator after a substep of h (resolve_floor_positional's
// rule along n): static friction undoes the substep's tangential travel when |h v_t| ≤ μ d.
FloorContactFound resolve_collider_positional(const ColliderGeometry& collider, const ContactMaterial& material,
                                              double h, std::span<Vec3> x, std::span<Vec3> v,
                                              const ColliderStepStart* start = nullptr);

// The smooth contact's continuous check: a vertex that the step took through the shape or past its middle (its
// spring, which acts only once it is inside, let it sink v τ) is put back on the face it came in by, with its
// approach relative to the surface stopped. The others are the spring's.
FloorContactFound resolve_collider_tunnelling(const ColliderGeometry& collider, const ColliderStepStart& start,
                                              std::span<Vec3> x, std::span<Vec3> v);

// The deepest any vertex is inside the collider (0: none) [m].
double deepest_inside_collider(const ColliderGeometry& collider, std::span<const Vec3> x);

}  // namespace sim
