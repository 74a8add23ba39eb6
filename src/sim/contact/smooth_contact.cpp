// The smooth floor contact's force and energy (the derivation is in smooth_contact.hpp).
#include "sim/contact/smooth_contact.hpp"

#include <cmath>
#include <numbers>

namespace sim {
namespace {

// s(t) = 6t⁵ − 15t⁴ + 10t³ on [0, 1], 0 below, 1 above: C² at both ends.
double smootherstep(double t) {
  if (t >= 1.0) return 1.0;
  return t * t * t * (t * (6.0 * t - 15.0) + 10.0);
}

// P(t) = ∫₀ᵗ s = t⁶ − 3t⁵ + 5t⁴/2 on [0, 1] (P(1) = ½), t − ½ beyond.
double smootherstep_integral(double t) {
  if (t >= 1.0) return t - 0.5;
  const double t2 = t * t;
  return t2 * t2 * (t * (t - 3.0) + 2.5);
}

// R(t) = ∫₀ᵗ P = t⁷/7 − t⁶/2 + t⁵/2 on [0, 1] (R(1) = 1/7), 1/7 + (t² − t)/2 beyond.
double smootherstep_second_integral(double t) {
  if (t >= 1.0) return 1.0 / 7.0 + 0.5 * (t * t - t);
  const double t2 = t * t;
  return t2 * t2 * t * (t * (t / 7.0 - 0.5) + 0.5);
}

}  // namespace

double damping_ratio_for_restitution(double restitution) {
  if (restitution <= 0.0) return 1.0;
  if (restitution >= 1.0) return 0.0;
  const double log_e = std::log(restitution);
  return -log_e / std::sqrt(std::numbers::pi * std::numbers::pi + log_e * log_e);
}

SmoothResponse resolve_smooth_response(const SmoothContact& c, const ContactMaterial& material) {
  const double omega = 1.0 / c.time_constant_s;
  const double zeta = c.damping_ratio >= 0.0 ? c.damping_ratio : damping_ratio_for_restitution(material.restitution);
  return SmoothResponse{omega * omega, 2.0 * zeta * omega, material.friction, c.slip_speed_m_per_s, c.smoothing_m};
}

SmoothFloor resolve_smooth_floor(const Floor& floor) {
  SmoothFloor resolved;
  static_cast<SmoothResponse&>(resolved) = resolve_smooth_response(floor.smooth, floor.material);
  resolved.height_m = floor.height_m;
  return resolved;
}

double smooth_elastic_per_mass(const SmoothResponse& contact, double depth_m) {
  return contact.omega2 * contact.smoothing_m * smootherstep_integral(depth_m / contact.smoothing_m);
}

double smooth_dashpot_weight(const SmoothResponse& contact, double depth_m) {
  return smootherstep(depth_m / contact.smoothing_m);
}

double smooth_energy_per_mass(const SmoothResponse& contact, double depth_m) {
  const double delta = contact.smoothing_m;
  return contact.omega2 * delta * delta * smootherstep_second_integral(depth_m / delta);
}

void add_smooth_floor_forces(const SmoothFloor& floor, std::span<const double> mass_kg, std::span<const Vec3> x,
                             std::span<const Vec3> v, std::span<Vec3> force) {
  const double eps2 = floor.slip_speed_m_per_s * floor.slip_speed_m_per_s;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double depth = floor.height_m - x[i].y();
    if (depth <= 0.0) continue;
    const double elastic = mass_kg[i] * smooth_elastic_per_mass(floor, depth);  // m ω² δ P [N]
    const double dashpot =
        -mass_kg[i] * floor.damping_rate * v[i].y() * smooth_dashpot_weight(floor, depth);  // −m 2ζω v_n s [N]
    force[i].y() += elastic + dashpot;
    if (floor.friction == 0.0) continue;
    const double vx = v[i].x(), vz = v[i].z();
    const double per_slip = floor.friction * elastic / std::sqrt(vx * vx + vz * vz + eps2);  // μ N / √(v_t² + ε²)
    force[i].x() -= per_slip * vx;
    force[i].z() -= per_slip * vz;
  }
}

double smooth_floor_energy(const SmoothFloor& floor, std::span<const double> mass_kg, std::span<const Vec3> x) {
  const double delta = floor.smoothing_m;
  double energy = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double depth = floor.height_m - x[i].y();
    if (depth <= 0.0) continue;
    energy += mass_kg[i] * floor.omega2 * delta * delta * smootherstep_second_integral(depth / delta);
  }
  return energy;
}

}  // namespace sim
