// Reference springs, dampers and gas for the force tests.
#include "reference_forces.hpp"

#include "sim/forces/forces.hpp"

namespace reference {

void add_springs(std::span<const std::array<int, 2>> edges, std::span<const double> rest_length_m, double k,
                 std::span<const Vec3> x, std::span<Vec3> force) {
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const auto [i, j] = edges[e];
    const Vec3 d = x[i] - x[j];
    const double length = d.norm();
    if (length == 0.0) continue;                                     // coincident endpoints: no direction to push along
    const Vec3 f = (-k * (length - rest_length_m[e]) / length) * d;  // -k (|d| - L0) d̂
    force[i] += f;
    force[j] -= f;
  }
}

void add_dampers(std::span<const std::array<int, 2>> edges, double c, std::span<const Vec3> x, std::span<const Vec3> v,
                 std::span<Vec3> force) {
  for (const auto& [i, j] : edges) {
    const Vec3 d = x[i] - x[j];
    const double length_squared = d.squaredNorm();
    if (length_squared == 0.0) continue;
    const Vec3 f = (-c * (v[i] - v[j]).dot(d) / length_squared) * d;  // -c ((v_i - v_j)·d̂) d̂
    force[i] += f;
    force[j] -= f;
  }
}

double add_gas(std::span<const Triangle> faces, double nRT_J, double rest_volume_m3, std::span<const Vec3> x,
               std::span<Vec3> force) {
  std::vector<Vec3> area_sums;
  const double volume = sim::volume_and_area_sums(faces, x, area_sums);
  const double per_area_sum = sim::gas_force_per_area_sum(nRT_J, volume, rest_volume_m3);
  for (std::size_t i = 0; i < x.size(); ++i) force[i] += per_area_sum * area_sums[i];
  return volume;
}

}  // namespace reference
