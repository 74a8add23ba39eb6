// Energies and centre-of-mass quantities of one body.
#include "sim/diagnostics.hpp"

#include <cmath>
#include <limits>

#include "sim/forces.hpp"

namespace sim {

BodyDiagnostics diagnose(const Body& body, std::span<const Vec3> x, std::span<const Vec3> v, const Vec3& gravity) {
  const Topology& topology = body.topology;
  BodyDiagnostics d;
  d.min_y_m = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double m = topology.mass_kg[i];
    d.com_m += m * x[i];
    d.momentum_kg_m_per_s += m * v[i];
    d.kinetic_J += 0.5 * m * v[i].squaredNorm();
    d.gravitational_J -= m * gravity.dot(x[i]);
    d.min_y_m = std::min(d.min_y_m, x[i].y());
  }
  d.com_m /= topology.total_mass_kg;
  d.com_velocity_m_per_s = d.momentum_kg_m_per_s / topology.total_mass_kg;
  for (std::size_t e = 0; e < topology.edges.size(); ++e) {
    const auto [i, j] = topology.edges[e];
    const double stretch = (x[i] - x[j]).norm() - topology.rest_length_m[e];
    d.spring_J += 0.5 * body.params.stiffness_N_per_m * stretch * stretch;
  }
  d.volume_m3 = enclosed_volume(topology.faces, x);
  if (body.params.pressure_J != 0.0) {
    const double v_eff = guarded_volume(d.volume_m3, topology.rest_volume_m3);
    d.gas_J = -body.params.pressure_J * std::log(v_eff / topology.rest_volume_m3);
  }
  return d;
}

BodyDiagnostics diagnose(const World& world, std::size_t index) {
  const Body& body = world.bodies()[index];
  return diagnose(body, world.positions(body), world.velocities(body), world.gravity());
}

}  // namespace sim
