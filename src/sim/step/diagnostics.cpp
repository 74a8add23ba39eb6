// Energies and centre-of-mass quantities of one body.
#include "sim/step/diagnostics.hpp"

#include <algorithm>
#include <limits>

#include "sim/contact/body_collision.hpp"
#include "sim/contact/smooth_collider.hpp"
#include "sim/contact/smooth_contact.hpp"
#include "sim/forces/energy.hpp"
#include "sim/forces/forces.hpp"

namespace sim {

BodyDiagnostics diagnose(const Body& body, std::span<const Vec3> x, std::span<const Vec3> v, const Vec3& gravity) {
  BodyDiagnostics d;
  d.com_m = centre_of_mass(body, x);
  d.momentum_kg_m_per_s = momentum(body, v);
  d.com_velocity_m_per_s = d.momentum_kg_m_per_s / body.masses.total_kg;
  d.kinetic_J = kinetic_energy(body, v);
  d.min_y_m = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < x.size(); ++i) {
    d.gravitational_J -= body.masses.kg[i] * gravity.dot(x[i]);  // −Σ m g·x
    d.min_y_m = std::min(d.min_y_m, x[i].y());
  }
  d.spring_J = spring_energy(body, x);
  d.volume_m3 = enclosed_volume(body.topology.faces, x);
  d.gas_J = gas_energy(body, d.volume_m3);
  return d;
}

BodyDiagnostics diagnose(const Model& model, const State& state, std::size_t index) {
  const Body& body = model.bodies[index];
  BodyDiagnostics d = diagnose(body, model.of(body, state.x), model.of(body, state.v), model.gravity_m_per_s2);
  if (model.floor && model.floor->contact == FloorContact::Smooth) {
    d.contact_J = smooth_floor_energy(resolve_smooth_floor(*model.floor), body.masses.kg, model.of(body, state.x));
  }
  for (const Collider& collider : model.colliders) {
    if (collider.contact != FloorContact::Smooth) continue;
    d.contact_J += smooth_collider_energy(resolve_smooth_collider(collider, state.time_s), body.masses.kg,
                                          model.of(body, state.x));
  }
  if (searches_body_contact(model.bodies) && model.body_contact.contact == BodyContactModel::Smooth) {
    BodyCollider collider;  // a search per call: diagnostics run per frame, not per step
    const SmoothResponse contact = resolve_smooth_response(model.body_contact.smooth, model.body_contact.material);
    d.contact_J += collider.smooth_energy(model.bodies, model.mass_kg, state.x, contact, index);
  }
  return d;
}

}  // namespace sim
