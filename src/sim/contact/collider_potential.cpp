// The smooth colliders' spring, dashpot and friction as incremental-potential terms for newton.
#include "sim/contact/collider_potential.hpp"

namespace sim {

void ColliderPotential::build(const Model& model) {
  colliders_.clear();
  for (const Collider& collider : model.colliders) {
    if (collider.contact == FloorContact::Smooth) colliders_.push_back(resolve_smooth_collider(collider));
  }
  lags_.assign(colliders_.size() * model.mass_kg.size(), ColliderLag{});
}

void ColliderPotential::begin_step(const Model& model, double end_time_s, double h) {
  h_ = h;
  std::size_t c = 0;
  for (const Collider& collider : model.colliders) {
    if (collider.contact != FloorContact::Smooth) continue;
    if (collider.motion.moving()) colliders_[c] = resolve_smooth_collider(collider, end_time_s);
    ++c;
  }
}

void ColliderPotential::lag(const Model& model, std::span<const Vec3> x) {
  const std::size_t n = x.size();
  for (std::size_t c = 0; c < colliders_.size(); ++c) {
    for (std::size_t i = 0; i < n; ++i) lags_[c * n + i] = lag_smooth_collider(colliders_[c], model.mass_kg[i], x[i]);
  }
}

double ColliderPotential::energy(const Model& model, std::span<const Vec3> x, std::span<const Vec3> start,
                                 double& scale) const {
  const std::size_t n = x.size();
  double energy = 0.0;
  for (std::size_t c = 0; c < colliders_.size(); ++c) {
    for (std::size_t i = 0; i < n; ++i) {
      energy += smooth_collider_terms(colliders_[c], lags_[c * n + i], model.mass_kg[i], x[i], start[i], h_);
    }
  }
  scale += energy;  // every term is >= 0
  return energy;
}

void ColliderPotential::add_derivatives(const Model& model, std::span<const Vec3> x, std::span<const Vec3> start,
                                        BlockSystem& hessian, Eigen::VectorXd& gradient) const {
  const std::size_t n = x.size();
  for (std::size_t c = 0; c < colliders_.size(); ++c) {
    for (std::size_t i = 0; i < n; ++i) {
      Vec3 g = Vec3::Zero();
      Mat3 block = Mat3::Zero();
      add_smooth_collider_derivatives(colliders_[c], lags_[c * n + i], model.mass_kg[i], x[i], start[i], h_, g, block);
      if (g.isZero(0.0) && block.isZero(0.0)) continue;
      const int vertex = static_cast<int>(i);
      gradient.segment<3>(hessian.dof(vertex)) += g;
      hessian.add_diagonal(vertex, block);
    }
  }
}

}  // namespace sim
