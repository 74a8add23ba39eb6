// Reference forms of the force model for the tests: the springs and the dampers one at a time (the
// library has them only fused, sim::add_spring_dampers) and the gas force from the library's face pass.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "core/vec.hpp"

namespace reference {

using softbody::Triangle;
using softbody::Vec3;

// Hooke springs: f_i += -k (|d| - L0) d̂ with d = x_i - x_j, and the opposite on j.
void add_springs(std::span<const std::array<int, 2>> edges, std::span<const double> rest_length_m, double k,
                 std::span<const Vec3> x, std::span<Vec3> force);

// Dampers along the springs: f_i += -c ((v_i - v_j)·d̂) d̂, and the opposite on j.
void add_dampers(std::span<const std::array<int, 2>> edges, double c, std::span<const Vec3> x, std::span<const Vec3> v,
                 std::span<Vec3> force);

// The gas force on every vertex as sim::Dynamics assembles it (sim::volume_and_area_sums, then
// sim::gas_force_per_area_sum per area sum), added into `force`. Returns the volume V [m³].
double add_gas(std::span<const Triangle> faces, double nRT_J, double rest_volume_m3, std::span<const Vec3> x,
               std::span<Vec3> force);

}  // namespace reference
