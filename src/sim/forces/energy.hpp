// Sums over one body's vertices and edges that several parts need (the CSV's diagnostics, the divergence
// guard, intent): centre of mass, momentum, kinetic, spring and gas energy. Each sums in vertex or edge
// order, so every caller gets the same bits.
#pragma once

#include <span>

#include "sim/model/body.hpp"

namespace sim {

// Σ m_i x_i / M [m].
Vec3 centre_of_mass(const Body& body, std::span<const Vec3> x);
// Σ m_i v_i [kg·m/s].
Vec3 momentum(const Body& body, std::span<const Vec3> v);
// Σ ½ m_i |v_i|² [J].
double kinetic_energy(const Body& body, std::span<const Vec3> v);
// Σ_e ½ k (|d_e| − L0_e)² over the edges, plus the bending links' ½ k_b (|d| − ℓ0)² (sim/forces/bending.hpp) [J].
double spring_energy(const Body& body, std::span<const Vec3> x);
// Σ ½ k (|x_i − x_j| − L0)² over constraints [begin, end) of the set [J].
double constraint_energy(const DistanceConstraints& constraints, std::size_t begin, std::size_t end,
                         std::span<const Vec3> x);
// −nRT ln(V / V0) at the enclosed volume V [m³], V held at guarded_volume() [J]; 0 without gas.
double gas_energy(const Body& body, double volume_m3);

}  // namespace sim
