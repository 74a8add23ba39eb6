// The smooth floor contact (sim/contact/smooth_contact.hpp) as terms of backward Euler's incremental potential, for
// newton.
#pragma once

#include <span>
#include <vector>

#include <Eigen/Core>

#include "sim/contact/smooth_contact.hpp"
#include "sim/model/model.hpp"
#include "sim/solvers/block_system.hpp"

namespace sim {

// For a vertex of mass m at depth d = floor − y (> 0) and Δx = x − x_n over a step of h, v' = Δx / h, the
// smooth contact's force (smooth_contact.hpp: ω² = 1/τ², b = 2ζω, δ, μ, ε) is −∇ of
//   spring    U_c = m ω² δ² R(d/δ)                                    [J]   (exact: its own potential)
//   dashpot   D_n = m b w Δy² / (2h),        w = s(d/δ) lagged         [J]   ∇_y = m b w v'_y
//   friction  D_t = N h √(|v'_t|² + ε²),     N = μ m ω² δ P(d/δ) lagged [J]   ∇_t = N v'_t / √(|v'_t|² + ε²)
// The dashpot's weight w and friction's normal force N are taken at the last iterate (lag(x)), as IPC lags
// its friction (Li et al. 2020, "Incremental Potential Contact", §5): at a converged iterate they are the
// values at the end of the step, so the minimiser is backward Euler of the smooth contact exactly. With w and N
// fixed, every term is convex in x: the Hessian blocks (per vertex, diagonal)
//   ∂²/∂y²  = m ω² s(d/δ) + m b w / h,
//   ∂²/∂x_t² = (N/h) (I/r − v'_t v'_tᵀ / r³),  r = √(|v'_t|² + ε²)  (eigenvalues N/(h r) and N ε²/(h r³))
// are positive semi-definite, so nothing needs projecting.
class FloorPotential {
 public:
  // Active when the model's floor is the smooth contact; otherwise every call adds nothing.
  void build(const Model& model);
  bool active() const { return active_; }
  // The step's size h [s].
  void begin_step(double h) { h_ = h; }
  // Takes the dashpot weights and friction normal forces at x (world vertices).
  void lag(const Model& model, std::span<const Vec3> x);
  // Σ (U_c + D_n + D_t) at x, with x_n = start [J]; `scale` += the magnitudes of its terms.
  double energy(const Model& model, std::span<const Vec3> x, std::span<const Vec3> start, double& scale) const;
  // gradient += ∇, the Hessian's diagonal blocks += ∇² (see above).
  void add_derivatives(const Model& model, std::span<const Vec3> x, std::span<const Vec3> start, BlockSystem& hessian,
                       Eigen::VectorXd& gradient) const;

 private:
  bool active_ = false;
  SmoothFloor floor_;
  double h_ = 0.0;
  std::vector<double> dashpot_weight_;   // per vertex: w = s(d/δ) at the last lag()
  std::vector<double> friction_normal_;  // per vertex: N = μ m ω² δ P(d/δ) at the last lag() [N]
};

}  // namespace sim
