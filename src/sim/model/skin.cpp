// Binding a detailed surface to a proxy and rebuilding it from the proxy's positions.
#include "sim/model/skin.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

namespace sim {
namespace {

constexpr int kNewtonIterations = 30;
// The interpolated-normal solution is kept while every barycentric weight is at least this (a little outside
// the nearest triangle is fine: the weights still interpolate that triangle's corners smoothly).
constexpr double kMostOutside = -0.25;

struct Corners {
  Vec3 x0, x1, x2;  // positions
  Vec3 n0, n1, n2;  // unit vertex normals
};

Corners corners_of(int triangle, std::span<const Vec3> x, std::span<const Triangle> faces,
                   std::span<const Vec3> normals) {
  const Triangle& t = faces[static_cast<std::size_t>(triangle)];
  const auto at = [](std::span<const Vec3> a, int i) { return a[static_cast<std::size_t>(i)]; };
  return {at(x, t[0]), at(x, t[1]), at(x, t[2]), at(normals, t[0]), at(normals, t[1]), at(normals, t[2])};
}

Vec3 face_unit_normal(const Corners& c) { return (c.x1 - c.x0).cross(c.x2 - c.x0).normalized(); }

Vec3 interpolated_normal(const Corners& c, double b1, double b2) {
  return (1.0 - b1 - b2) * c.n0 + b1 * c.n1 + b2 * c.n2;
}

// q projected along the face normal: d = (q − x0)·n̂; (b1, b2) solve the 2×2 normal equations of
// x0 + b1 e1 + b2 e2 = q − d n̂ (e1 = x1 − x0, e2 = x2 − x0), which hold exactly since that point is in the plane.
SkinAnchor face_projection(const Vec3& q, int triangle, const Corners& c) {
  const Vec3 e1 = c.x1 - c.x0, e2 = c.x2 - c.x0, n = face_unit_normal(c);
  const Vec3 r = q - c.x0;
  const double d = r.dot(n);
  const Vec3 in_plane = r - d * n;
  const double a11 = e1.dot(e1), a12 = e1.dot(e2), a22 = e2.dot(e2);
  const double r1 = e1.dot(in_plane), r2 = e2.dot(in_plane);
  const double det = a11 * a22 - a12 * a12;
  return {triangle, (r1 * a22 - r2 * a12) / det, (a11 * r2 - a12 * r1) / det, d, true};
}

}  // namespace

void vertex_normals(std::span<const Vec3> x, std::span<const Triangle> faces, std::vector<Vec3>& normals) {
  normals.assign(x.size(), Vec3::Zero());
  for (const Triangle& t : faces) {
    const Vec3& a = x[static_cast<std::size_t>(t[0])];
    const Vec3 twice_area = (x[static_cast<std::size_t>(t[1])] - a).cross(x[static_cast<std::size_t>(t[2])] - a);
    for (int corner : t) normals[static_cast<std::size_t>(corner)] += twice_area;
  }
  for (Vec3& n : normals) {
    const double length = n.norm();
    n = length > 0.0 ? Vec3(n / length) : Vec3::Zero();
  }
}

SkinAnchor anchor_point(const Vec3& q, int triangle, std::span<const Vec3> x, std::span<const Triangle> faces,
                        std::span<const Vec3> normals) {
  const Corners c = corners_of(triangle, x, faces, normals);
  const SkinAnchor projected = face_projection(q, triangle, c);
  // Newton on F(b1, b2, d) = x0 + b1 e1 + b2 e2 + d n(b) − q, n(b) = n0 + b1 (n1 − n0) + b2 (n2 − n0):
  // J = [e1 + d (n1 − n0), e2 + d (n2 − n0), n(b)].
  const Vec3 e1 = c.x1 - c.x0, e2 = c.x2 - c.x0, m1 = c.n1 - c.n0, m2 = c.n2 - c.n0;
  const double size = std::max({e1.norm(), e2.norm(), std::abs(projected.offset_m)});
  Eigen::Vector3d u(projected.b1, projected.b2, projected.offset_m);
  bool converged = false;
  for (int iteration = 0; iteration < kNewtonIterations && !converged; ++iteration) {
    const Vec3 n = c.n0 + u[0] * m1 + u[1] * m2;
    const Vec3 residual = c.x0 + u[0] * e1 + u[1] * e2 + u[2] * n - q;
    if (residual.norm() <= 1e-14 * size) {
      converged = true;
      break;
    }
    Eigen::Matrix3d jacobian;
    jacobian << e1 + u[2] * m1, e2 + u[2] * m2, n;
    const Eigen::Vector3d step = jacobian.partialPivLu().solve(residual);
    if (!step.allFinite()) break;
    u -= step;
  }
  const double b0 = 1.0 - u[0] - u[1];
  const bool near_projection = std::abs(u[2]) <= 2.0 * std::abs(projected.offset_m) + size;
  if (!converged || !u.allFinite() || std::min({b0, u[0], u[1]}) < kMostOutside || !near_projection) return projected;
  return {triangle, u[0], u[1], u[2], false};
}

void skin_positions(const Skin& skin, std::span<const Vec3> x, std::span<const Triangle> faces,
                    std::vector<Vec3>& normals, std::vector<Vec3>& detailed) {
  vertex_normals(x, faces, normals);
  detailed.resize(skin.anchors.size());
  for (std::size_t i = 0; i < skin.anchors.size(); ++i) {
    const SkinAnchor& a = skin.anchors[i];
    const Corners c = corners_of(a.triangle, x, faces, normals);
    const Vec3 n = a.face_normal ? face_unit_normal(c) : interpolated_normal(c, a.b1, a.b2);
    detailed[i] = c.x0 + a.b1 * (c.x1 - c.x0) + a.b2 * (c.x2 - c.x0) + a.offset_m * n;
  }
}

}  // namespace sim
