// Spring and damper Jacobian blocks.
#include "sim/forces/spring_jacobian.hpp"

#include <algorithm>

namespace sim {

Eigen::Matrix3d spring_stiffness_block(const Vec3& d, double rest_length_m, double k) {
  const double length = d.norm();
  if (length == 0.0 || k == 0.0) return Eigen::Matrix3d::Zero();
  const Vec3 u = d / length;
  const Eigen::Matrix3d along = u * u.transpose();
  const double geometric = std::max(0.0, 1.0 - rest_length_m / length);  // clamped: compressed springs give 0
  return k * (along + geometric * (Eigen::Matrix3d::Identity() - along));
}

Eigen::Matrix3d spring_hessian_block(const Vec3& d, double rest_length_m, double k) {
  const double length = d.norm();
  if (length == 0.0 || k == 0.0) return Eigen::Matrix3d::Zero();
  const Vec3 u = d / length;
  const Eigen::Matrix3d along = u * u.transpose();
  return k * (along + (1.0 - rest_length_m / length) * (Eigen::Matrix3d::Identity() - along));
}

Eigen::Matrix3d damper_block(const Vec3& d, double c) {
  const double length_squared = d.squaredNorm();
  if (length_squared == 0.0 || c == 0.0) return Eigen::Matrix3d::Zero();
  return (c / length_squared) * (d * d.transpose());
}

}  // namespace sim
