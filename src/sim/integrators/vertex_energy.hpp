// One vertex's part of vbd's step energy (sim/integrators/vertex_block_descent.hpp): its gradient and 3×3 Hessian
// block at the vertex's position, and the energy's change along a move of that vertex alone, with the dampers' and
// the smooth floor's directions and weights lagged at the visit's start.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <vector>

#include "core/vec.hpp"
#include "sim/contact/smooth_collider.hpp"
#include "sim/contact/smooth_contact.hpp"
#include "sim/integrators/vertex_blocks.hpp"
#include "sim/step/part_runner.hpp"

namespace sim {

using softbody::Vec3;

class VertexContacts;

// A line search accepts a move with sufficient decrease ΔE ≤ kArmijo α ∇E·Δ (Nocedal & Wright, Sect. 3.1).
inline constexpr double kArmijo = 1e-4;

// The gas of one body as a function of its volume: E = −nRT ln V, held to the force model's guard below
// V_g (sim::guarded_volume): there the pressure stays nRT/V_g and E continues linearly, so E stays convex in V.
struct GasLaw {
  double nRT_J = 0.0;
  double guard_m3 = 0.0;  // V_g [m³]

  double pressure(double V) const { return nRT_J / std::max(V, guard_m3); }          // −dE/dV [Pa]
  double stiffness(double V) const { return V > guard_m3 ? nRT_J / (V * V) : 0.0; }  // d²E/dV² [J/m⁶]
  double energy(double V) const {                                                    // E [J]
    return V >= guard_m3 ? -nRT_J * std::log(V) : -nRT_J * (std::log(guard_m3) + (V - guard_m3) / guard_m3);
  }
  // E(V + dV) − E(V) [J], without the cancellation of two logarithms where both are above the guard.
  double energy_change(double V, double dV) const {
    if (V >= guard_m3 && V + dV >= guard_m3) return -nRT_J * std::log1p(dV / V);
    return energy(V + dV) - energy(V);
  }
};

// A symmetric 3×3 block, its upper triangle.
struct Block3 {
  double xx = 0.0, xy = 0.0, xz = 0.0, yy = 0.0, yz = 0.0, zz = 0.0;

  void add_diagonal(double a) {
    xx += a;
    yy += a;
    zz += a;
  }
  void add_scaled(double a, const Block3& b) {  // += a b
    xx += a * b.xx;
    xy += a * b.xy;
    xz += a * b.xz;
    yy += a * b.yy;
    yz += a * b.yz;
    zz += a * b.zz;
  }
  void add(const Mat3& m) {  // += m's upper triangle (m symmetric)
    xx += m(0, 0);
    xy += m(0, 1);
    xz += m(0, 2);
    yy += m(1, 1);
    yz += m(1, 2);
    zz += m(2, 2);
  }
  void add_outer(double a, const Vec3& u) {  // += a u uᵀ
    xx += a * u.x() * u.x();
    xy += a * u.x() * u.y();
    xz += a * u.x() * u.z();
    yy += a * u.y() * u.y();
    yz += a * u.y() * u.z();
    zz += a * u.z() * u.z();
  }
  // H⁻¹ r by the adjugate (H positive definite here: its determinant is positive).
  Vec3 solve(const Vec3& r) const {
    const double c_xx = yy * zz - yz * yz, c_xy = xz * yz - xy * zz, c_xz = xy * yz - xz * yy;
    const double c_yy = xx * zz - xz * xz, c_yz = xy * xz - xx * yz, c_zz = xx * yy - xy * xy;
    const double inverse_det = 1.0 / (xx * c_xx + xy * c_xy + xz * c_xz);
    return inverse_det * Vec3(c_xx * r.x() + c_xy * r.y() + c_xz * r.z(), c_xy * r.x() + c_yy * r.y() + c_yz * r.z(),
                              c_xz * r.x() + c_yz * r.y() + c_zz * r.z());
  }
};

// What the local solves of one body read during a step.
struct BodySolve {
  const VertexBlocks& blocks;
  std::span<const double> mass_kg;
  std::span<const Vec3> target;    // y
  std::span<const Vec3> base;      // x̃
  double h_hat = 0.0;              // ĥ [s]
  double negligible_step_m = 0.0;  // a Newton step shorter than this is taken without a line search [m]
  double inverse_h2 = 0.0;         // 1/ĥ² [1/s²]
  std::optional<GasLaw> gas;
  const SmoothFloor* floor = nullptr;
  std::span<const SmoothCollider> colliders;  // the colliders whose contact is smooth
  // The smooth contact between bodies (sim/integrators/vertex_contacts.hpp), lagged for this sweep; none without.
  const VertexContacts* contacts = nullptr;
  int first_vertex = 0;  // the body's first vertex in the model (the contacts' vertices are the model's)
  // Threads for the whole-body loops (the coarse corrections' sums and searches, sim/step/chunked_sum.hpp); none: the
  // caller's. The result is the same bits either way.
  PartRunner* runner = nullptr;
};

// The smooth floor's terms of one vertex, with the dashpot's weight w and friction's normal force N lagged at the
// visit's start (as IPC lags its friction: Li et al. 2020, §5).
struct FloorLag {
  double depth_m = 0.0;       // floor − y at the visit's start
  double dashpot_kg_s = 0.0;  // m b w [kg/s]
  double friction_N = 0.0;    // N = μ m ω² δ P(d/δ)
  double slip_speed2 = 0.0;   // ε² [m²/s²]
};

// Adds the smooth floor's gradient and Hessian at x (a vertex of mass m) and returns its lags.
FloorLag add_floor_terms(const SmoothFloor& floor, double m, const Vec3& x, const Vec3& base, double h_hat,
                         Vec3& gradient, Block3& hessian);
// The floor terms' change of E when the vertex moves from x by step [J].
double floor_energy_change(const SmoothFloor& floor, const FloorLag& lag, double m, const Vec3& x, const Vec3& step,
                           const Vec3& base, double h_hat);
// A smooth collider's terms of one vertex at x (sim/contact/smooth_collider.hpp): its gradient and
// Hessian added, and its normal, dashpot weight and friction force lagged at x returned.
ColliderLag add_collider_terms(const SmoothCollider& collider, double m, const Vec3& x, const Vec3& base, double h_hat,
                               Vec3& gradient, Block3& hessian);
// That collider's terms' change of E when the vertex moves from x by step, with the lags taken at x [J].
double collider_energy_change(const SmoothCollider& collider, const ColliderLag& lag, double m, const Vec3& x,
                              const Vec3& step, const Vec3& base, double h_hat);

// One vertex's constraints as its visit found them: direction n̂, length l [m] and ĥ × approach speed [m].
struct ConstraintLags {
  std::vector<Vec3> offset;  // x_i − x_j [m]
  std::vector<Vec3> axis;
  std::vector<double> length_m, rate_m;
  std::vector<ColliderLag> colliders;  // per smooth collider (sized by the integrator once)
  void resize(std::size_t most_constraints) {
    offset.resize(most_constraints);
    axis.resize(most_constraints);
    length_m.resize(most_constraints);
    rate_m.resize(most_constraints);
  }
};

// Σ_{f ∋ i} (x_b − x_i) × (x_c − x_i) = 6 ∂V/∂x_i [m²], with the edge vectors x_i − x_j that vertex_terms left in
// lags.offset where the corners are among the vertex's constraints.
Vec3 six_volume_gradient(const VertexBlocks& blocks, int i, std::span<const Vec3> x, const ConstraintLags& lags);
// The same from the positions alone (for passes that keep no edge vectors).
Vec3 six_volume_gradient(const VertexBlocks& blocks, std::size_t i, std::span<const Vec3> x);

// ∇_i E and H_i of vertex i at x, with what its line search reuses.
struct VertexTerms {
  Vec3 gradient = Vec3::Zero();         // ∇_i E [N]
  Block3 hessian;                       // H_i, positive definite [N/m]
  Vec3 volume_gradient = Vec3::Zero();  // g_i = ∂V/∂x_i [m²]
  FloorLag floor;
  double spring_variation = 0.0;  // Σ_e k L0 / l² over the vertex's constraints [N/m²]
  double shortest_m = 0.0;        // the shortest of its constraints' lengths l (0 where it has none) [m]
};

// The terms of vertex i at x: inertia, its constraints (lagging each direction and approach into `lags`), the gas at
// volume V (V of x), the smooth floor, the smooth colliders (their lags into lags.colliders) and the smooth contacts
// with bodies. A compressed spring's
// transverse curvature is clamped at zero.
VertexTerms vertex_terms(const BodySolve& s, int i, std::span<const Vec3> x, double volume, ConstraintLags& lags);

// Whether the Newton step `step` (= −H_i⁻¹ ∇_i E, with slope = ∇_i E·step) is sure to lower E by more than the line
// search asks (kArmijo), so that the search may be skipped: the same move it would make at α = 1. Along the step
//   E(x + Δ) − E(x) = ∇E·Δ + ∫₀¹ (1 − t) Δᵀ H(x + tΔ) Δ dt ≤ ½ ∇E·Δ + ½ B |Δ|²,
// as ∇E·Δ = −Δᵀ H_i Δ and H(x + tΔ) ≤ H_i + B I: the true Hessian at x is at most H_i (H_i only clamps), a spring's
// ½k(l − L0)² has a Hessian k I − k L0 (I − n̂n̂ᵀ)/l whose change is at most (2/√3) k L0 |Δ| / l_min² (l_min ≥ l − |Δ|
// along the step), the gas's nRT g gᵀ/V² grows by at most nRT |g|² (1/V₁² − 1/V²) where V falls to V₁, and the dampers
// and the inertia are quadratic. B |Δ|² ≤ ½ |∇E·Δ| leaves E falling by at least ¼ |∇E·Δ|, far beyond kArmijo and
// round-off. Not where a smooth contact is near (the floor's terms at either end, or any smooth collider): those always
// search.
// β: the derivative of (I − n̂n̂ᵀ)/l along a unit vector at cosine c to n̂ has the norm (|c| + √(4 − 3c²))/(2l²), at
// most 2/(√3 l²) (at c² = 1/3); rounded up.
inline constexpr double kSpringHessianVariation = 1.1547006;
bool sure_descent(const BodySolve& s, const VertexTerms& terms, const Vec3& x, double volume, const Vec3& step,
                  double slope);

// E(x with x_i moved by step) − E(x) [J], with the lags vertex_terms took at x (exact for the springs, the gas and the
// inertia; the dampers and the floor's dashpot and friction with their lagged directions and weights).
double vertex_energy_change(const BodySolve& s, int i, std::span<const Vec3> x, double volume, const VertexTerms& terms,
                            const ConstraintLags& lags, const Vec3& step);

}  // namespace sim
