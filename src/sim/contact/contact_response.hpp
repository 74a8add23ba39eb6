// The rule of an impulse contact, shared by the friction floor and contact between bodies: how fast a
// contact separates after an impact (restitution, with resting contacts kept at rest), and how much
// tangential impulse Coulomb friction allows.
#pragma once

#include <algorithm>

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

}  // namespace sim
