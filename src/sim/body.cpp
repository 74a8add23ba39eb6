// Building a body from a closed mesh: unique edges as springs, rest lengths, area-lumped masses.
#include "sim/body.hpp"

#include <algorithm>

#include "mesh/trimesh.hpp"
#include "scene/scene.hpp"
#include "sim/forces.hpp"

namespace sim {

std::vector<double> lump_masses_by_area(const std::vector<Vec3>& x, const std::vector<Triangle>& faces, double total_mass) {
  std::vector<double> area_share(x.size(), 0.0);
  double total_area = 0.0;
  for (const Triangle& f : faces) {
    const double area = 0.5 * (x[f[1]] - x[f[0]]).cross(x[f[2]] - x[f[0]]).norm();
    for (int i : f) area_share[i] += area / 3.0;
    total_area += area;
  }
  std::vector<double> mass(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) mass[i] = total_mass * area_share[i] / total_area;
  return mass;
}

Topology build_topology(const std::vector<Vec3>& x, const std::vector<Triangle>& faces, double total_mass) {
  Topology topology;
  topology.faces = faces;
  for (const Triangle& f : faces) {
    for (int k = 0; k < 3; ++k) {
      const int a = f[k], b = f[(k + 1) % 3];
      // A closed, consistently wound mesh uses each edge once in each direction: keep the a < b use.
      if (a < b) topology.edges.push_back({a, b});
    }
  }
  std::sort(topology.edges.begin(), topology.edges.end());  // memory order for the edge loop
  topology.rest_length_m.reserve(topology.edges.size());
  for (const auto& [a, b] : topology.edges) topology.rest_length_m.push_back((x[a] - x[b]).norm());
  topology.mass_kg = lump_masses_by_area(x, faces, total_mass);
  topology.inverse_mass.reserve(x.size());
  for (double m : topology.mass_kg) topology.inverse_mass.push_back(1.0 / m);
  topology.rest_volume_m3 = enclosed_volume(topology.faces, x);
  topology.total_mass_kg = total_mass;
  return topology;
}

std::vector<Vec3> place_mesh(const mesh::TriMesh& mesh, const scene::Body& spec) {
  std::vector<Vec3> x;
  x.reserve(mesh.vertices.size());
  for (const Vec3& p : mesh.vertices) x.push_back(spec.position_m + spec.scale * p);
  return x;
}

}  // namespace sim
