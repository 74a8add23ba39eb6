// The rule of an impulse contact, shared by the friction floor, the colliders and contact between bodies: how fast a
// contact separates after an impact (restitution, with resting contacts kept at rest), and how much
// tangential impulse Coulomb friction allows.
#pragma once

#include <algorithm>

#include "core/vec.hpp"
#include "sim/model/settings.hpp"

namespace sim {

// The normal speed after the impulse [m/s] for an approach at `normal_speed` < 0 (along the outward
// normal): −e v_n for an impact, 0 for a resting contact (approach slower than the resting speed).
inline double separating_speed(double normal_speed, const ContactMaterial& material) {
  return -normal_speed > material.resting_speed_m_per_s ? -material.restitution * normal_speed : 0.0;
}

// Coulomb's law for an impulse: the tangential impulse is at most μ × the normal impulse, and never more
// than the one that stops the tangential motion (static friction). Both in the same units (per unit mass
// for the floor, kg·m/s between bodies).
inline double friction_impulse(const ContactMaterial& material, double normal_impulse, double stopping_impulse) {
  return std::min(material.friction * normal_impulse, stopping_impulse);
}

// The tangential velocity after an impulse with `normal_impulse` (both per unit mass): zero where static friction
// holds the vertex, else slowed by Coulomb's μ × the normal impulse (sliding friction).
inline softbody::Vec3 tangential_after_impulse(softbody::Vec3 tangential, double normal_impulse,
                                               const ContactMaterial& material) {
  const double tangential_speed = tangential.norm();
  const double friction = friction_impulse(material, normal_impulse, tangential_speed);
  if (friction == tangential_speed) return softbody::Vec3::Zero();  // static friction
  tangential *= 1.0 - friction / tangential_speed;                  // sliding friction
  return tangential;
}

}  // namespace sim
