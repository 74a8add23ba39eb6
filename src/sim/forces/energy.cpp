// Centre of mass, momentum and the energies of one body.
#include "sim/forces/energy.hpp"

#include <cmath>

#include "sim/forces/bending.hpp"
#include "sim/forces/forces.hpp"

namespace sim {

Vec3 centre_of_mass(const Body& body, std::span<const Vec3> x) {
  Vec3 weighted = Vec3::Zero();
  for (std::size_t i = 0; i < x.size(); ++i) weighted += body.masses.kg[i] * x[i];
  return weighted / body.masses.total_kg;
}

Vec3 momentum(const Body& body, std::span<const Vec3> v) {
  Vec3 p = Vec3::Zero();
  for (std::size_t i = 0; i < v.size(); ++i) p += body.masses.kg[i] * v[i];
  return p;
}

double kinetic_energy(const Body& body, std::span<const Vec3> v) {
  double kinetic = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i) kinetic += 0.5 * body.masses.kg[i] * v[i].squaredNorm();
  return kinetic;
}

double spring_energy(const Body& body, std::span<const Vec3> x) {
  double energy = 0.0;
  for (std::size_t e = 0; e < body.topology.edges.size(); ++e) {
    const auto [i, j] = body.topology.edges[e];
    const double stretch = (x[i] - x[j]).norm() - body.rest.edge_length_m[e];
    energy += 0.5 * body.params.stiffness_N_per_m * stretch * stretch;  // ½ k (|d| − L0)²
  }
  if (!body.topology.bending_links.empty()) energy += bending_energy(body, x);  // the links are springs too
  return energy;
}

double gas_energy(const Body& body, double volume_m3) {
  if (body.params.pressure_J == 0.0) return 0.0;
  const double effective = guarded_volume(volume_m3, body.rest.volume_m3);
  return -body.params.pressure_J * std::log(effective / body.rest.volume_m3);
}

}  // namespace sim
