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

double constraint_energy(const DistanceConstraints& constraints, std::size_t begin, std::size_t end,
                         std::span<const Vec3> x) {
  double energy = 0.0;
  for (std::size_t e = begin; e < end; ++e) {
    const auto [i, j] = constraints.ends[e];
    const double stretch = (x[i] - x[j]).norm() - constraints.rest_length_m[e];
    energy += 0.5 * constraints.stiffness_N_per_m[e] * stretch * stretch;  // ½ k (|d| − L0)²
  }
  return energy;
}

double spring_energy(const Body& body, std::span<const Vec3> x) {
  const DistanceConstraints& constraints = body.constraints;
  // The edges' sum, then the bending links' (bending_energy) added to it.
  return constraint_energy(constraints, 0, constraints.edge_count, x) + bending_energy(body, x);
}

double gas_energy(const Body& body, double volume_m3) {
  if (body.params.pressure_J == 0.0) return 0.0;
  const double effective = guarded_volume(volume_m3, body.rest.volume_m3);
  return -body.params.pressure_J * std::log(effective / body.rest.volume_m3);
}

}  // namespace sim
