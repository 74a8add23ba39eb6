// Force loops: one pass each over vertices (gravity), edges (springs, dampers) and faces (pressure).
#include "sim/forces.hpp"

#include <algorithm>
#include <cmath>

namespace sim {

void add_gravity(std::span<const double> mass_kg, const Vec3& g, std::span<Vec3> force) {
  for (std::size_t i = 0; i < force.size(); ++i) force[i] += mass_kg[i] * g;
}

void add_springs(std::span<const std::array<int, 2>> edges, std::span<const double> rest_length_m, double k,
                 std::span<const Vec3> x, std::span<Vec3> force) {
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const auto [i, j] = edges[e];
    const Vec3 d = x[i] - x[j];
    const double length = d.norm();
    if (length == 0.0) continue;  // coincident endpoints: no direction to push along
    const Vec3 f = (-k * (length - rest_length_m[e]) / length) * d;  // -k (|d| - L0) d̂
    force[i] += f;
    force[j] -= f;
  }
}

void add_dampers(std::span<const std::array<int, 2>> edges, double c, std::span<const Vec3> x,
                 std::span<const Vec3> v, std::span<Vec3> force) {
  for (const auto& [i, j] : edges) {
    const Vec3 d = x[i] - x[j];
    const double length_squared = d.squaredNorm();
    if (length_squared == 0.0) continue;
    const Vec3 f = (-c * (v[i] - v[j]).dot(d) / length_squared) * d;  // -c ((v_i - v_j)·d̂) d̂
    force[i] += f;
    force[j] -= f;
  }
}

double enclosed_volume(std::span<const Triangle> faces, std::span<const Vec3> x) {
  const Vec3 origin = x[0];
  double six_volume = 0.0;
  for (const Triangle& f : faces) {
    const Vec3 a = x[f[0]] - origin, b = x[f[1]] - origin, c = x[f[2]] - origin;
    six_volume += a.dot(b.cross(c));
  }
  return six_volume / 6.0;
}

double guarded_volume(double volume_m3, double rest_volume_m3) {
  constexpr double kMinimumVolumeFraction = 1e-3;  // of V0: the gas then pushes 1000× its rest pressure
  return std::max(volume_m3, kMinimumVolumeFraction * rest_volume_m3);
}

double add_pressure(std::span<const Triangle> faces, double nRT_J, double rest_volume_m3, std::span<const Vec3> x,
                    std::vector<Vec3>& area_vectors, std::span<Vec3> force) {
  // Pass 1: twice the area vector of each face, 2A·n̂ = (x_b − x_a)×(x_c − x_a); it also gives the volume,
  // since x_a·(x_b × x_c) = x_a·((x_b − x_a)×(x_c − x_a)).
  area_vectors.resize(faces.size());
  const Vec3 origin = x[0];
  double six_volume = 0.0;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const Vec3 a = x[faces[f][0]] - origin;
    area_vectors[f] = (x[faces[f][1]] - x[faces[f][0]]).cross(x[faces[f][2]] - x[faces[f][0]]);
    six_volume += a.dot(area_vectors[f]);
  }
  const double volume = six_volume / 6.0;
  // Pass 2: P·A·n̂ split over three corners = (nRT / V) · (2A·n̂) / 6 per corner.
  const double per_corner = nRT_J / guarded_volume(volume, rest_volume_m3) / 6.0;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const Vec3 push = per_corner * area_vectors[f];
    for (int corner : faces[f]) force[corner] += push;
  }
  return volume;
}

}  // namespace sim
