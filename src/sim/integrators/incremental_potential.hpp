// Backward Euler's incremental potential for the model's forces: its value, gradient and (made definite) Hessian.
#pragma once

#include <array>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "sim/contact/body_contact_potential.hpp"
#include "sim/contact/collider_potential.hpp"
#include "sim/contact/floor_potential.hpp"
#include "sim/model/model.hpp"
#include "sim/model/state.hpp"
#include "sim/solvers/block_system.hpp"

namespace sim {

// A backward Euler step x' = x + h v', M v' = M v + h f(x', v') is the stationary point of (Gast, Schroeder,
// Stomakhin, Jiang & Teran, "Optimization integrators for large time steps", TVCG 2015, Eq. 4)
//   E(x) = |x − x̂|²_M / (2h²) + U(x) + D(x),   x̂ = x_n + h v_n,  v' = (x − x_n) / h,
// with the model's potential U and a dissipation potential D for the dampers [J]:
//   gravity   U = −Σ m_i g·(x_i − x_n,i)                     (the constant m g·x_n dropped)
//   springs   U = Σ_e ½ k (|d_e| − L0_e)²,  d_e = x_i − x_j
//             (and the bending links, sim/forces/bending.hpp: the same with k_b, ℓ0; no gas curvature term)
//   gas       U = −nRT ln(V / V0) per body, V at guarded_volume()
//   dampers   D = Σ_e c/(2h) ((Δx_i − Δx_j)·d̂_e)²,  Δx = x − x_n,  d̂_e = d_e / |d_e| at x_n
//   smooth floor: its spring, dashpot and friction (sim/contact/floor_potential.hpp; the dashpot's weight and
//             the friction's normal force lagged: taken at x̂ by begin_step(), then wherever update_lags() says)
//   smooth colliders: the floor's three terms against each collider's surface (sim/contact/collider_potential.hpp;
//             the normal lagged too)
//   smooth body contact: the same three per vertex near another body's surface (sim/contact/
//             body_contact_potential.hpp; the contact frames lagged too); its Hessian is rank-one terms
// ∇D = c ((v'_i − v'_j)·d̂_e) d̂_e is the model's damper force along the spring with its direction taken at
// the start of the step (an O(h) change of direction, within backward Euler's O(h) error), which makes the
// damper a potential, so that E can be minimised with a line search; its Hessian (c/h) d̂d̂ᵀ is the exact
// ∂f/∂v of that force, divided by h.
//
// The Hessian ∇²E = M/h² + Σ_e K_e + (c/h) Σ_e d̂d̂ᵀ + ∇²U_gas, assembled exactly or made positive definite:
//   - springs: −∂f/∂x = k [d̂d̂ᵀ + (1 − L0/|d|)(I − d̂d̂ᵀ)] (sim/forces/spring_jacobian.hpp); definite:
//     a compressed spring's negative geometric term clamped at zero (Choi & Ko 2002), as in `implicit`;
//   - gas: ∇²(−nRT ln V) = nRT (∇V∇Vᵀ / V² − ∇²V / V). The first term is rank one, u uᵀ with u = √nRT ∇V / V,
//     returned as gas_terms() and applied as u (uᵀp) by the solver, never as a dense matrix. The second is, per
//     edge (i, j) with the vertices c and d across it, the indefinite 6×6 [[0, W], [Wᵀ, 0]], W = [w]×,
//     w = −(nRT/V)(x_d − x_c)/6 [N/m]; definite: its projection on the positive semi-definite cone, ½(|H| + H).
//     The projection stiffens the body's rigid motion, which is why the exact form is tried first.
//     Derivation: docs/notes/2026-12-05-header-derivations.md.
// The line search uses E itself, so the clamps change only the Newton direction, never the solution.
class IncrementalPotential {
 public:
  // The rank-one part of one body's gas Hessian, u uᵀ (u zero outside the body).
  struct GasTerm {
    int body = 0;
    std::vector<Vec3> direction;  // u_i = √nRT ∇V_i / V for the body's vertices [√J / m]
  };

  // For `model`: its edges, the vertices across each edge, the bodies with gas.
  void build(const Model& model);
  // The coupled vertex pairs (every edge of every body, world indices), as the Hessian's pattern.
  std::span<const std::array<int, 2>> pairs() const { return pairs_; }

  // The step from `start` of size h: x̂ and the dampers' directions.
  void begin_step(const Model& model, const State& start, double h);
  // E(x) [J] (relative to the constant terms dropped above); `scale`: the sum of its terms' magnitudes, which
  // sets its round-off.
  double energy(const Model& model, std::span<const Vec3> x, double& scale);
  // How the Hessian is assembled (see above).
  enum class Hessian { Exact, Definite };
  // ∇E(x) into `gradient` (the system's order, sized by the caller), ∇²E without the gas's rank-one parts
  // into `hessian` (overwritten), and those parts into gas_terms().
  void assemble(const Model& model, std::span<const Vec3> x, Hessian form, BlockSystem& hessian,
                Eigen::VectorXd& gradient);
  std::span<const GasTerm> gas_terms() const { return gas_; }
  // The smooth body contact's Hessian as rank-one terms over four vertices each, at the last assemble().
  std::span<const BodyContactPotential::Term> contact_terms() const { return contact_.terms(); }
  // True when E has lagged terms (the smooth floor or body contact); update_lags() takes them at x, which changes E.
  bool has_lagged_terms() const { return floor_.active() || colliders_.active() || contact_.active(); }
  void update_lags(const Model& model, std::span<const Vec3> x);

 private:
  struct Edge {
    int body = 0;
    int across_ij = 0, across_ji = 0;  // world index of the vertex opposite the directed edge i→j (and j→i)
    double stiffness_N_per_m = 0.0, damping_N_s_per_m = 0.0;  // the body's k, c (a bending link: k_b, c_b)
  };

  // Gas term `gas`: the area sums at x into area_sums_; returns the body's volume there, guarded [m³].
  double gas_face_pass(const Model& model, std::size_t gas, std::span<const Vec3> x);

  std::vector<std::array<int, 2>> pairs_;  // world vertex indices per edge, bodies one after another
  std::vector<double> rest_length_m_;      // per edge
  std::vector<Edge> edges_;
  std::vector<GasTerm> gas_;
  std::vector<double> gas_curvature_;         // per body: nRT / V at the last assemble(), 0 without gas
  std::vector<std::vector<Vec3>> area_sums_;  // per gas term: Σ 2A n̂ around each vertex (sim/forces/forces.hpp)

  double h_ = 0.0;
  std::vector<Vec3> start_x_;      // x_n
  std::vector<Vec3> predicted_x_;  // x̂ = x_n + h v_n
  std::vector<Vec3> damper_axis_;  // per edge: d̂ at x_n
  FloorPotential floor_;
  ColliderPotential colliders_;
  BodyContactPotential contact_;
};

}  // namespace sim
