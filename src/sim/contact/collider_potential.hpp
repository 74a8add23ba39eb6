// The smooth contact against the model's colliders as terms of backward Euler's incremental potential, for newton
// (the terms and their lags are sim/contact/smooth_collider.hpp's; floor_potential.hpp is the floor's counterpart).
#pragma once

#include <span>
#include <vector>

#include <Eigen/Core>

#include "sim/contact/smooth_collider.hpp"
#include "sim/model/model.hpp"
#include "sim/solvers/block_system.hpp"

namespace sim {

class ColliderPotential {
 public:
  // Active when a collider has the smooth contact; otherwise every call adds nothing.
  void build(const Model& model);
  bool active() const { return !colliders_.empty(); }
  // A step of h that ends at end_time_s: the keyframed colliders take their pose then (backward Euler's x_{n+1}).
  void begin_step(const Model& model, double end_time_s, double h);
  // Takes every vertex's lagged normal, dashpot weight and friction normal force at x (world vertices).
  void lag(const Model& model, std::span<const Vec3> x);
  // Σ (U + D_n + D_t) at x, with x_n = start [J]; `scale` += the magnitudes of its terms.
  double energy(const Model& model, std::span<const Vec3> x, std::span<const Vec3> start, double& scale) const;
  // gradient += ∇, the Hessian's diagonal blocks += ∇².
  void add_derivatives(const Model& model, std::span<const Vec3> x, std::span<const Vec3> start, BlockSystem& hessian,
                       Eigen::VectorXd& gradient) const;

 private:
  std::vector<SmoothCollider> colliders_;  // the smooth ones
  std::vector<ColliderLag> lags_;          // per smooth collider, per vertex: collider c's at [c n + i]
  double h_ = 0.0;
};

}  // namespace sim
