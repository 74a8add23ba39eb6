// The smooth contact against a static collider: force, energy, and its incremental-potential terms.
#include "sim/contact/smooth_collider.hpp"

#include <cmath>

namespace sim {
namespace {

// The tangential part of a velocity for the unit normal n.
Vec3 tangential_part(const Vec3& v, const Vec3& n) { return v - v.dot(n) * n; }

// The travel Δx = x − start of a step of h relative to the surface's: Δx − h u(start) (Δx for a static collider).
Vec3 relative_travel(const ColliderGeometry& g, const Vec3& x, const Vec3& start, double h) {
  if (!g.velocity.moving) return x - start;
  return x - start - h * surface_velocity(g, start);
}

}  // namespace

SmoothCollider resolve_smooth_collider(const Collider& collider, double time_s) {
  SmoothCollider resolved;
  static_cast<SmoothResponse&>(resolved) = resolve_smooth_response(collider.smooth, collider.material);
  resolved.geometry = collider_at(collider, time_s);
  return resolved;
}

void add_smooth_collider_forces(const SmoothCollider& c, std::span<const double> mass_kg, std::span<const Vec3> x,
                                std::span<const Vec3> v, std::span<Vec3> force) {
  const double eps2 = c.slip_speed_m_per_s * c.slip_speed_m_per_s;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!is_inside(c.geometry, x[i])) continue;
    const SurfacePoint s = nearest_surface(c.geometry, x[i]);
    if (s.distance_m >= 0.0) continue;
    const double depth = -s.distance_m;
    const Vec3& n = s.normal;
    const Vec3 relative = c.geometry.velocity.moving ? Vec3(v[i] - surface_velocity(c.geometry, x[i])) : v[i];
    const double normal_speed = relative.dot(n);
    const double elastic = mass_kg[i] * smooth_elastic_per_mass(c, depth);                                 // [N]
    const double dashpot = -mass_kg[i] * c.damping_rate * normal_speed * smooth_dashpot_weight(c, depth);  // [N]
    force[i] += (elastic + dashpot) * n;
    if (c.friction == 0.0) continue;
    const Vec3 slip = tangential_part(relative, n);
    force[i] -= (c.friction * elastic / std::sqrt(slip.squaredNorm() + eps2)) * slip;  // μ N v_t / √(v_t² + ε²)
  }
}

double smooth_collider_energy(const SmoothCollider& c, std::span<const double> mass_kg, std::span<const Vec3> x) {
  double energy = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!is_inside(c.geometry, x[i])) continue;
    const double distance = nearest_surface(c.geometry, x[i]).distance_m;
    if (distance < 0.0) energy += mass_kg[i] * smooth_energy_per_mass(c, -distance);
  }
  return energy;
}

ColliderLag lag_smooth_collider(const SmoothCollider& c, double m, const Vec3& x) {
  if (!is_inside(c.geometry, x)) return {};
  const SurfacePoint s = nearest_surface(c.geometry, x);
  if (s.distance_m >= 0.0) return {};
  const double depth = -s.distance_m;
  return {s.normal, m * c.damping_rate * smooth_dashpot_weight(c, depth),
          c.friction * m * smooth_elastic_per_mass(c, depth)};
}

double smooth_collider_terms(const SmoothCollider& c, const ColliderLag& lag, double m, const Vec3& x,
                             const Vec3& start, double h) {
  const double distance = is_inside(c.geometry, x) ? nearest_surface(c.geometry, x).distance_m : 0.0;
  double energy = distance < 0.0 ? m * smooth_energy_per_mass(c, -distance) : 0.0;  // U
  const Vec3 dx = relative_travel(c.geometry, x, start, h);
  const double along = dx.dot(lag.normal);
  energy += lag.dashpot_kg_s * along * along / (2.0 * h);  // D_n
  if (lag.friction_N > 0.0) {
    const Vec3 slip = tangential_part(dx, lag.normal) / h;
    energy += lag.friction_N * h * std::sqrt(slip.squaredNorm() + c.slip_speed_m_per_s * c.slip_speed_m_per_s);
  }
  return energy;
}

void add_smooth_collider_derivatives(const SmoothCollider& c, const ColliderLag& lag, double m, const Vec3& x,
                                     const Vec3& start, double h, Vec3& gradient, Mat3& hessian) {
  const SurfacePoint s = is_inside(c.geometry, x) ? nearest_surface(c.geometry, x) : SurfacePoint{};
  if (s.distance_m < 0.0) {
    const double depth = -s.distance_m;
    gradient -= m * smooth_elastic_per_mass(c, depth) * s.normal;  // −m ω² δ P n
    hessian += (m * c.omega2 * smooth_dashpot_weight(c, depth)) * (s.normal * s.normal.transpose());  // m ω² s n nᵀ
  }
  if (lag.dashpot_kg_s == 0.0 && lag.friction_N == 0.0) return;
  const Vec3& n = lag.normal;
  const Vec3 dx = relative_travel(c.geometry, x, start, h);
  gradient += (lag.dashpot_kg_s * dx.dot(n) / h) * n;  // m b w (Δx·n̄)/h n̄
  hessian += (lag.dashpot_kg_s / h) * (n * n.transpose());
  if (lag.friction_N > 0.0) {
    const Vec3 slip = tangential_part(dx, n) / h;
    const double r = std::sqrt(slip.squaredNorm() + c.slip_speed_m_per_s * c.slip_speed_m_per_s);
    gradient += (lag.friction_N / r) * slip;  // N v_t / r
    const Mat3 tangent_projector = Mat3::Identity() - n * n.transpose();
    hessian += (lag.friction_N / (h * r)) * (tangent_projector - slip * slip.transpose() / (r * r));
  }
}

}  // namespace sim
