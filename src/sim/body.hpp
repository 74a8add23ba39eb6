// A soft body as the solver sees it: topology and rest data, parameters, and where its state lives.
#pragma once

#include <array>
#include <span>
#include <string>
#include <vector>

#include "core/vec.hpp"

namespace mesh {
struct TriMesh;
}
namespace scene {
struct Body;
}

namespace sim {

using softbody::Triangle;
using softbody::Vec3;

// Built once from the mesh; indices are local to the body (0 .. vertex count - 1).
struct Topology {
  std::vector<std::array<int, 2>> edges;  // each unique mesh edge, one spring-damper
  std::vector<double> rest_length_m;      // per edge, from the initial (scaled) shape
  std::vector<Triangle> faces;            // counter-clockwise seen from outside
  std::vector<double> mass_kg;            // per vertex: a third of each adjacent face's share of the body mass
  std::vector<double> inverse_mass;       // per vertex, 1 / mass_kg
  double rest_volume_m3 = 0.0;            // V0, the gas energy's reference: E_gas = -nRT ln(V / V0)
  double total_mass_kg = 0.0;
};

// Per-body constants of the force model.
struct Params {
  double stiffness_N_per_m = 0.0;   // k: Hooke spring, F = -k (|d| - L0) d̂
  double damping_N_s_per_m = 0.0;   // c: damper along the spring, F = -c ((v_i - v_j)·d̂) d̂
  double pressure_J = 0.0;          // nRT: ideal gas, P = nRT / V  [Pa = J/m³]
};

struct Body {
  Topology topology;
  Params params;
  int first_vertex = 0;  // where this body's vertices start in the world's state arrays
  int vertex_count = 0;
};

// Positions and velocities of every vertex of every body, bodies one after another.
struct State {
  std::vector<Vec3> x;  // m
  std::vector<Vec3> v;  // m/s
};

// Lumped vertex masses: each triangle gives a third of its area share of `total_mass` to each corner.
std::vector<double> lump_masses_by_area(const std::vector<Vec3>& x, const std::vector<Triangle>& faces, double total_mass);

// Builds the body's topology from the placed mesh `x` (world coordinates) and its triangles.
Topology build_topology(const std::vector<Vec3>& x, const std::vector<Triangle>& faces, double total_mass);

// The mesh placed in the world: scale, then translate by the body's position.
std::vector<Vec3> place_mesh(const mesh::TriMesh& mesh, const scene::Body& spec);

}  // namespace sim
