// Building a body from a closed mesh: unique edges as springs, rest lengths, area-lumped masses.
#include "sim/model/body.hpp"

#include <algorithm>

#include "sim/forces/forces.hpp"

namespace sim {

std::vector<double> lump_masses_by_area(const std::vector<Vec3>& x, const std::vector<Triangle>& faces,
                                        double total_mass) {
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

Body build_body(const std::vector<Vec3>& x, const std::vector<Triangle>& faces, double total_mass) {
  Body body;
  body.vertex_count = static_cast<int>(x.size());
  Topology& topology = body.topology;
  topology.faces = faces;
  for (const Triangle& f : faces) {
    for (int k = 0; k < 3; ++k) {
      const int a = f[k], b = f[(k + 1) % 3];
      // A closed, consistently wound mesh uses each edge once in each direction: keep the a < b use.
      if (a < b) topology.edges.push_back({a, b});
    }
  }
  std::sort(topology.edges.begin(), topology.edges.end());  // memory order for the edge loop
  body.rest.edge_length_m.reserve(topology.edges.size());
  for (const auto& [a, b] : topology.edges) body.rest.edge_length_m.push_back((x[a] - x[b]).norm());
  body.rest.mean_edge_m = mean_edge_length(body.rest);
  body.rest.volume_m3 = enclosed_volume(topology.faces, x);
  body.rest.position_m = x;
  body.masses.kg = lump_masses_by_area(x, faces, total_mass);
  body.masses.inverse.reserve(x.size());
  for (double m : body.masses.kg) body.masses.inverse.push_back(1.0 / m);
  body.masses.total_kg = total_mass;
  return body;
}

DistanceConstraints distance_constraints(const Body& body) {
  DistanceConstraints set;
  const auto add = [&set](std::span<const std::array<int, 2>> ends, std::span<const double> rest, double k, double c) {
    for (std::size_t e = 0; e < ends.size(); ++e) {
      set.ends.push_back(ends[e]);
      set.rest_length_m.push_back(rest[e]);
      set.stiffness_N_per_m.push_back(k);
      set.damping_N_s_per_m.push_back(c);
    }
  };
  const Params& p = body.params;
  add(body.topology.edges, body.rest.edge_length_m, p.stiffness_N_per_m, p.damping_N_s_per_m);
  set.edge_count = set.size();
  add(body.topology.bending_links, body.rest.bending_length_m, p.bending_N_per_m, p.bending_damping_N_s_per_m);
  return set;
}

double mean_edge_length(const RestShape& rest) {
  double sum = 0.0;
  for (double length : rest.edge_length_m) sum += length;
  return sum / static_cast<double>(std::max<std::size_t>(1, rest.edge_length_m.size()));
}

}  // namespace sim
