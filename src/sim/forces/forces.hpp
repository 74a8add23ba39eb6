// The force model of Matyka & Ollila (2003), one function per force: gravity, spring-dampers along edges
// (springs and dampers in one fused pass), ideal-gas pressure. Indices are local to one body; forces in N.
// sim::Dynamics assembles them; tests/reference_forces.hpp holds the unfused springs and dampers to check
// the fused pass against.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "core/vec.hpp"
#include "sim/model/body.hpp"

namespace sim {

using softbody::Triangle;
using softbody::Vec3;

// Gravity as the first term of the sum: f_i = m_i g (overwrites `force`, so no separate zeroing pass).
void start_with_gravity(std::span<const double> mass_kg, const Vec3& g, std::span<Vec3> force);

// Hooke springs, f_i += -k (|d| - L0) d̂ with d = x_i - x_j, and dampers along them, f_i += -c ((v_i - v_j)·d̂) d̂,
// the opposite on j, in one fused pass over a body's distance constraints (its edges, then its bending links): with
// L = |d|,
//   f_i = -k (L - L0) d/L - c ((v_i - v_j)·d) d/L²  =  [(-k (L - L0) L - c (v_i - v_j)·d) / L²] d,
// one square root and one division per edge (the two forces one at a time agree to round-off). The
// constraints go in blocks: gather the differences, compute the coefficients in a loop without indirection
// (which the compiler vectorises), then scatter, so results do not depend on the vector width. A block whose
// constraints have no damping skips the dampers' terms; one with neither springs nor dampers is skipped.
void add_spring_dampers(const DistanceConstraints& constraints, std::span<const Vec3> x, std::span<const Vec3> v,
                        std::span<Vec3> force);

// six_volume + Σ x_a·(x_b × x_c) over faces [first, last), positions relative to `origin`, each face's term added in
// face order [m³]: the face loop of enclosed_volume (and of its chunked form on threads and lanes,
// sim/integrators/correction_lanes.hpp's enclosed_volume_in_lanes).
double six_volume_of(std::span<const Triangle> faces, std::span<const Vec3> x, const Vec3& origin, std::size_t first,
                     std::size_t last, double six_volume = 0.0);

// Signed enclosed volume V = Σ_f x_a·(x_b × x_c) / 6 (divergence theorem) [m³]. Positions are taken
// relative to the first vertex, which leaves V unchanged on a closed mesh but keeps round-off small.
double enclosed_volume(std::span<const Triangle> faces, std::span<const Vec3> x);

// dV/dt = Σ_i ∂V/∂x_i · v_i = Σ_f [v_a·(x_b × x_c) + v_b·(x_c × x_a) + v_c·(x_a × x_b)] / 6 [m³/s], positions
// relative to the first vertex as enclosed_volume's.
double volume_rate(std::span<const Triangle> faces, std::span<const Vec3> x, std::span<const Vec3> v);

// ∂V/∂x_i = Σ_{f ∋ i} A_f n̂_f / 3 for every vertex [m²] (sized here): the reference form that intent and the
// stability estimate use. The gas's face pass below computes the same gradient fused with the volume, as
// area sums g_i = 6 ∂V/∂x_i (equal to round-off; tests/forces_test.cpp).
void volume_gradient(std::span<const Triangle> faces, std::span<const Vec3> x, std::vector<Vec3>& gradient);

// The volume below which the gas law is evaluated at this floor instead (V → 0 would give P → ∞).
double guarded_volume(double volume_m3, double rest_volume_m3);

// The gas's face pass: area_sums_i = Σ_{f ∋ i} 2A_f·n̂_f, twice the area vectors of the faces around each
// vertex (sized here, no allocation once sized), and the enclosed volume from the same sums,
// V = Σ_i x_i·g_i / 18 [m³], which it returns. ∂V/∂x_i = g_i / 6.
double volume_and_area_sums(std::span<const Triangle> faces, std::span<const Vec3> x, std::vector<Vec3>& area_sums);

// Ideal gas: P = nRT / V; each face pushes with P·A·n̂ = P·½(x_b − x_a)×(x_c − x_a), a third on each corner,
// f_i = (nRT / V) g_i / 6 with g the area sums above: exactly +nRT ∂(ln V)/∂x_i, the negative gradient of
// E_gas = −nRT ln V, so the forces on a closed mesh sum to zero. Returns that factor, the gas force on a
// vertex per unit of its area sum [N/m²]; V is held at guarded_volume().
double gas_force_per_area_sum(double nRT_J, double volume_m3, double rest_volume_m3);

}  // namespace sim
