// The smooth contact between bodies (sim/contact/body_collision.hpp) as terms of backward Euler's incremental
// potential, for newton.
#pragma once

#include <array>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "sim/contact/body_collision.hpp"
#include "sim/contact/smooth_contact.hpp"
#include "sim/model/model.hpp"

namespace sim {

// Design note. A contact is a vertex p near the nearest triangle (corners a, b, c, closest point q = Σ w_k x_k) of
// another body. Its relative position r = J X = x_p − Σ w_k x_k maps the four vertices' positions X to 3D, and
// Jᵀ spreads a 3D force as +F on p and −w_k F on the corners (momentum kept exactly, as in the force model).
// lag(x) takes each contact's frame at x: the triangle, the weights w, the unit direction n (outward, from q to
// p), and the dashpot weight w_d = s(d/δ) and friction normal force N = μ m ω² δ P(d/δ) at its depth d = δ − n·r
// there. With that frame held, the smooth contact's force (sim/contact/body_collision.hpp) is −∇ of
//   spring    U_c = m ω² δ² R(d/δ),   d = δ − n·J X                     [J]  −∇ = Jᵀ (m ω² δ P(d/δ) n)
//   dashpot   D_n = m b w_d (n·J ΔX)² / (2h),   ΔX = X − X_n            [J]  −∇ = Jᵀ (−m b w_d v'_n n)
//   friction  D_t = N h √(|v'_t|² + ε²),   v'_t = (I − n nᵀ) J ΔX / h   [J]  −∇ = Jᵀ (−N v'_t / r)
// (m the vertex's mass, b = 2ζω, r = √(|v'_t|² + ε²)): at x = the lag point, the very force of add_smooth_forces
// at v' = (x − x_n)/h. As for the floor (floor_potential.hpp) and IPC's friction (Li et al. 2020, §5), the lag
// follows the Newton iterate, so a converged iterate is backward Euler of the smooth contact; the frame is held
// like w_d and N (the signed distance is linearised about the lag point along n: exact to first order, and its
// curvature, O(d/distance to the triangle's edges), is what the lag leaves out). With the frame held each
// contact's Hessian is, in the relative coordinates,
//   K = (m ω² s(d/δ) + m b w_d / h) n nᵀ + (N / (h r)) [(ε²/r²) t̂ t̂ᵀ + ê ê ᵀ],   t̂ = v'_t/|v'_t|, ê = n × t̂
// (the friction block's eigenvalues, as for the floor), positive semi-definite, and ∇²E = Jᵀ K J, three
// rank-one terms u uᵀ with u = √κ Jᵀ e over the contact's four vertices: applied as products by the solver,
// never entering the sparse pattern (whose pairs are the bodies' edges).
// Contacts are every vertex within the collider's search (half the surface's mean edge) at the lag, touching or
// not: a vertex still outside the skin δ there has w_d = N = 0 and its spring is zero until n·J X < δ.
class BodyContactPotential {
 public:
  // A rank-one part u uᵀ of the Hessian, u non-zero on four vertices (world indices).
  struct Term {
    std::array<int, 4> vertex{};
    std::array<Vec3, 4> u{};
  };

  // Active when the model's bodies touch by the smooth contact and there are at least two of them.
  void build(const Model& model);
  bool active() const { return active_; }
  // The step's size h [s].
  void begin_step(double h) { h_ = h; }
  // Finds the contacts at x and takes their frames, dashpot weights and friction normal forces there.
  void lag(const Model& model, std::span<const Vec3> x);
  // Σ (U_c + D_n + D_t) at x, with x_n = start [J]; `scale` += the magnitudes of its terms.
  double energy(const Model& model, std::span<const Vec3> x, std::span<const Vec3> start, double& scale) const;
  // gradient += ∇ (vertex v's unknowns at 3v), and the Hessian's rank-one terms at x into terms().
  void add_derivatives(const Model& model, std::span<const Vec3> x, std::span<const Vec3> start,
                       Eigen::VectorXd& gradient);
  std::span<const Term> terms() const { return terms_; }
  std::size_t contacts() const { return frames_.size(); }

 private:
  struct Lagged {
    double dashpot_weight = 0.0;   // w_d = s(d/δ)
    double friction_normal = 0.0;  // N = μ m ω² δ P(d/δ) [N]
  };
  // r = J X of contact c [m].
  Vec3 relative(std::size_t c, std::span<const Vec3> x) const;
  void add_term(std::size_t c, double coefficient, const Vec3& axis);

  bool active_ = false;
  SmoothResponse response_;
  double h_ = 0.0;
  BodyCollider collider_;
  std::vector<BodyCollider::SmoothFrame> frames_;  // per contact, at the last lag()
  std::vector<Lagged> lagged_;                     // per contact
  std::vector<Term> terms_;                        // at the last add_derivatives()
};

}  // namespace sim
