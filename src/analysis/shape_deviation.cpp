// Shape deviation after removing the best-fit rigid motion (Kabsch).
#include "analysis/shape_deviation.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/SVD>

namespace analysis {
namespace {

Vec3 weighted_centre(std::span<const Vec3> x, std::span<const double> mass_kg) {
  Vec3 sum = Vec3::Zero();
  double total = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sum += mass_kg[i] * x[i];
    total += mass_kg[i];
  }
  return sum / total;
}

double bounding_box_diagonal(std::span<const Vec3> x) {
  Vec3 low = x[0], high = x[0];
  for (const Vec3& p : x) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  return (high - low).norm();
}

}  // namespace

ShapeDeviation shape_deviation(std::span<const Vec3> rest, std::span<const Vec3> x, std::span<const double> mass_kg) {
  ShapeDeviation d;
  if (rest.empty()) return d;
  const Vec3 rest_centre = weighted_centre(rest, mass_kg), centre = weighted_centre(x, mass_kg);
  // H = Σ m (r − r̄)(x − x̄)ᵀ = U S Vᵀ; R = V diag(1, 1, sign det(V Uᵀ)) Uᵀ maximises tr(R H) (Kabsch 1976).
  Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < x.size(); ++i) H += mass_kg[i] * (rest[i] - rest_centre) * (x[i] - centre).transpose();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d flip = Eigen::Matrix3d::Identity();
  flip(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  const Eigen::Matrix3d R = svd.matrixV() * flip * svd.matrixU().transpose();
  double sum_squares = 0.0, total = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double distance = (R * (rest[i] - rest_centre) + centre - x[i]).norm();
    d.largest_m = std::max(d.largest_m, distance);
    sum_squares += mass_kg[i] * distance * distance;
    total += mass_kg[i];
  }
  d.rms_m = std::sqrt(sum_squares / total);
  d.body_size_m = bounding_box_diagonal(rest);
  return d;
}

}  // namespace analysis
