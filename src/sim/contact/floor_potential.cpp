// The smooth floor contact's spring, dashpot and friction as incremental-potential terms (lagged w and N).
#include "sim/contact/floor_potential.hpp"

#include <cmath>

namespace sim {

namespace {

using Mat3 = Eigen::Matrix3d;

// The tangential part (x, z) of Δx / h [m/s].
Eigen::Vector2d tangential_velocity(const Vec3& x, const Vec3& start, double h) {
  return Eigen::Vector2d(x.x() - start.x(), x.z() - start.z()) / h;
}

}  // namespace

void FloorPotential::build(const Model& model) {
  active_ = model.floor && model.floor->contact == FloorContact::Smooth;
  if (!active_) return;
  floor_ = resolve_smooth_floor(*model.floor);
  dashpot_weight_.assign(model.mass_kg.size(), 0.0);
  friction_normal_.assign(model.mass_kg.size(), 0.0);
}

void FloorPotential::lag(const Model& model, std::span<const Vec3> x) {
  if (!active_) return;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double depth = floor_.height_m - x[i].y();
    const bool touching = depth > 0.0;
    dashpot_weight_[i] = touching ? smooth_dashpot_weight(floor_, depth) : 0.0;
    friction_normal_[i] = touching ? floor_.friction * model.mass_kg[i] * smooth_elastic_per_mass(floor_, depth) : 0.0;
  }
}

double FloorPotential::energy(const Model& model, std::span<const Vec3> x, std::span<const Vec3> start,
                              double& scale) const {
  if (!active_) return 0.0;
  const double spring = smooth_floor_energy(floor_, model.mass_kg, x);  // Σ m ω² δ² R(d/δ)
  const double eps2 = floor_.slip_speed_m_per_s * floor_.slip_speed_m_per_s;
  double dashpot = 0.0, friction = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (dashpot_weight_[i] == 0.0 && friction_normal_[i] == 0.0) continue;
    const double dy = x[i].y() - start[i].y();
    dashpot += model.mass_kg[i] * floor_.damping_rate * dashpot_weight_[i] * dy * dy;  // Σ m b w Δy², over 2h below
    friction += friction_normal_[i] * std::sqrt(tangential_velocity(x[i], start[i], h_).squaredNorm() + eps2);  // Σ N r
  }
  const double dashpot_J = dashpot / (2.0 * h_), friction_J = h_ * friction;
  scale += spring + dashpot_J + friction_J;
  return spring + dashpot_J + friction_J;
}

void FloorPotential::add_derivatives(const Model& model, std::span<const Vec3> x, std::span<const Vec3> start,
                                     BlockSystem& hessian, Eigen::VectorXd& gradient) const {
  if (!active_) return;
  const double eps2 = floor_.slip_speed_m_per_s * floor_.slip_speed_m_per_s;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double depth = floor_.height_m - x[i].y();
    if (depth <= 0.0 && dashpot_weight_[i] == 0.0 && friction_normal_[i] == 0.0) continue;
    const double m = model.mass_kg[i];
    const int vertex = static_cast<int>(i);
    const Eigen::Index dof = hessian.dof(vertex);
    Mat3 block = Mat3::Zero();
    if (depth > 0.0) {
      gradient[dof + 1] -= m * smooth_elastic_per_mass(floor_, depth);          // −m ω² δ P(d/δ)
      block(1, 1) += m * floor_.omega2 * smooth_dashpot_weight(floor_, depth);  // m ω² s(d/δ)
    }
    const double dashpot = m * floor_.damping_rate * dashpot_weight_[i];  // m b w [kg/s]
    gradient[dof + 1] += dashpot * (x[i].y() - start[i].y()) / h_;        // m b w v'_y
    block(1, 1) += dashpot / h_;
    if (friction_normal_[i] > 0.0) {
      const Eigen::Vector2d v = tangential_velocity(x[i], start[i], h_);
      const double r = std::sqrt(v.squaredNorm() + eps2);
      const Eigen::Vector2d g = (friction_normal_[i] / r) * v;  // N v'_t / r
      gradient[dof + 0] += g.x();
      gradient[dof + 2] += g.y();
      const Eigen::Matrix2d t =
          (friction_normal_[i] / (h_ * r)) * (Eigen::Matrix2d::Identity() - v * v.transpose() / (r * r));
      block(0, 0) += t(0, 0);
      block(0, 2) += t(0, 1);
      block(2, 0) += t(1, 0);
      block(2, 2) += t(1, 1);
    }
    hessian.add_diagonal(vertex, block);
  }
}

}  // namespace sim
