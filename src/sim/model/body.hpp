// A soft body as the solver sees it: topology and rest data, parameters, and where its state lives.
#pragma once

#include <array>
#include <span>
#include <string>
#include <vector>

#include "core/vec.hpp"

namespace sim {

using softbody::Triangle;
using softbody::Vec3;

// A body's mesh connectivity; indices are local to the body (0 .. vertex count - 1).
struct Topology {
  std::vector<std::array<int, 2>> edges;  // each unique mesh edge, one spring-damper (a < b, sorted)
  std::vector<Triangle> faces;            // counter-clockwise seen from outside
  // Bending links (sim/forces/bending.hpp): per interior edge, the two vertices opposite it in its two triangles
  // (a < b, sorted, each pair once). Empty unless the body has bending stiffness.
  std::vector<std::array<int, 2>> bending_links;
};

// The shape the springs and the gas rest at (the initial, placed shape unless intent changed it).
struct RestShape {
  std::vector<double> edge_length_m;     // per edge: L0 of its spring
  double volume_m3 = 0.0;                // V0, the gas energy's reference: E_gas = -nRT ln(V / V0)
  double mean_edge_m = 0.0;              // the mean of edge_length_m: sets body contact's search distance
  std::vector<double> bending_length_m;  // per bending link: its length in the placed mesh [m]
  std::vector<Vec3> position_m;          // the placed mesh [m]: where render paints the body's pattern
};

// Lumped vertex masses: each face gives a third of its area share of the body's mass to each corner.
struct VertexMasses {
  std::vector<double> kg;       // per vertex
  std::vector<double> inverse;  // per vertex, 1 / kg [1/kg]
  double total_kg = 0.0;
};

// Per-body constants of the force model.
struct Params {
  double stiffness_N_per_m = 0.0;          // k: Hooke spring, F = -k (|d| - L0) d̂
  double damping_N_s_per_m = 0.0;          // c: damper along the spring, F = -c ((v_i - v_j)·d̂) d̂
  double pressure_J = 0.0;                 // nRT: ideal gas, P = nRT / V  [Pa = J/m³]
  double bending_N_per_m = 0.0;            // k_b: Hooke spring along each bending link (0: no links, no cost)
  double bending_damping_N_s_per_m = 0.0;  // c_b = c k_b / k: the links' dampers, the edges' damping time c/k
};

// The body's springs as one set of distance constraints C = |x_i − x_j| − L0 (as Jolt's edge constraints): the
// mesh edges (k, c) first, then the bending links (k_b, c_b), both in their topology's order, each constraint with
// its own rest length, stiffness and damping. Built once by add_body() from the topology, rest shape and params;
// every spring loop (forces, energy, the integrators' Jacobians and passes, the stability estimate) runs over it.
struct DistanceConstraints {
  std::vector<std::array<int, 2>> ends;   // the two vertices (local indices, a < b)
  std::vector<double> rest_length_m;      // L0 [m]
  std::vector<double> stiffness_N_per_m;  // k [N/m]: F = -k (|d| - L0) d̂
  std::vector<double> damping_N_s_per_m;  // c [N·s/m]: F = -c ((v_i - v_j)·d̂) d̂
  std::size_t edge_count = 0;             // constraints [0, edge_count) are the mesh edges, the rest bending links
  std::size_t size() const { return ends.size(); }
};

struct Body {
  Topology topology;
  RestShape rest;
  VertexMasses masses;
  Params params;
  DistanceConstraints constraints;  // from the above, by add_body()
  int first_vertex = 0;             // where this body's vertices start in the state's arrays (State::x, v)
  int vertex_count = 0;
  bool self_collision = false;  // its vertices also touch its own triangles (sim/contact/body_collision.hpp)
};

// Lumped vertex masses: each triangle gives a third of its area share of `total_mass` to each corner.
std::vector<double> lump_masses_by_area(const std::vector<Vec3>& x, const std::vector<Triangle>& faces,
                                        double total_mass);

// The body of the placed mesh `x` (world coordinates) and its triangles: unique edges as springs resting at
// their present lengths, area-lumped masses of `total_mass` [kg], the rest volume. Params are left zero and
// first_vertex to the caller.
Body build_body(const std::vector<Vec3>& x, const std::vector<Triangle>& faces, double total_mass);

// The body's edges and bending links as one constraint set, with its params' stiffness and damping.
DistanceConstraints distance_constraints(const Body& body);

// The mean rest edge length [m] (updates rest.mean_edge_m after the rest lengths changed).
double mean_edge_length(const RestShape& rest);

}  // namespace sim
