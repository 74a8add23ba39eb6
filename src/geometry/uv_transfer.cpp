// UVs from one triangulation of a surface onto another, by the nearest source triangle.
#include "geometry/uv_transfer.hpp"

#include <algorithm>

#include "geometry/nearest_triangle.hpp"

namespace geometry {
namespace {

using mesh::Vec3;

// Barycentric weights of p's projection onto the plane of (a, b, c), clamped to the triangle (negative
// weights set to 0, the rest scaled to sum 1): w_b = ((d·d)(e·f) − (d·e)(d·f)) / D, w_c = ((e·e)(d·f) −
// (d·e)(e·f)) / D with e = b − a, d = c − a, f = p − a, D = (e·e)(d·d) − (d·e)² (Ericson, Real-Time
// Collision Detection, 3.4). A triangle without area gives its first corner.
std::array<double, 3> clamped_barycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e = b - a, d = c - a, f = p - a;
  const double ee = e.dot(e), dd = d.dot(d), de = e.dot(d), ef = e.dot(f), df = d.dot(f);
  const double denominator = ee * dd - de * de;
  if (!(denominator > 0.0)) return {1.0, 0.0, 0.0};
  std::array<double, 3> w{0.0, (dd * ef - de * df) / denominator, (ee * df - de * ef) / denominator};
  w[0] = 1.0 - w[1] - w[2];
  for (double& x : w) x = std::max(x, 0.0);
  const double sum = w[0] + w[1] + w[2];
  for (double& x : w) x /= sum;
  return w;
}

// The UV at corner point `p` on source triangle `source` (of `from`).
mesh::Uv uv_at(const Vec3& p, const mesh::TriMesh& from, std::size_t source) {
  const mesh::Triangle& t = from.triangles[source];
  const mesh::CornerUvs& uvs = from.corner_uvs[source];
  for (int k = 0; k < 3; ++k) {
    if (from.vertices[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])] == p)
      return uvs[static_cast<std::size_t>(k)];
  }
  const std::array<double, 3> w =
      clamped_barycentric(p, from.vertices[static_cast<std::size_t>(t[0])],
                          from.vertices[static_cast<std::size_t>(t[1])], from.vertices[static_cast<std::size_t>(t[2])]);
  return {w[0] * uvs[0][0] + w[1] * uvs[1][0] + w[2] * uvs[2][0],
          w[0] * uvs[0][1] + w[1] * uvs[1][1] + w[2] * uvs[2][1]};
}

}  // namespace

std::vector<mesh::CornerUvs> transfer_corner_uvs(const mesh::TriMesh& from, const mesh::TriMesh& to) {
  if (!from.has_uvs() || from.triangles.empty() || to.triangles.empty()) return {};
  // Each corner is looked up a thousandth of the way from it toward its triangle's centroid: a point inside the
  // triangle, so that the source triangle found is the one on this triangle's side of a UV seam, and near
  // enough to the corner that the corner lies on that source triangle (to round-off) where the two share a
  // plane.
  std::vector<Vec3> nudged;
  nudged.reserve(3 * to.triangles.size());
  const auto corner = [&](const mesh::Triangle& t, std::size_t k) -> const Vec3& {
    return to.vertices[static_cast<std::size_t>(t[k])];
  };
  for (const mesh::Triangle& t : to.triangles) {
    const Vec3 centroid = (corner(t, 0) + corner(t, 1) + corner(t, 2)) / 3.0;
    for (std::size_t k = 0; k < 3; ++k) nudged.push_back(corner(t, k) + 1e-3 * (centroid - corner(t, k)));
  }
  const std::vector<int> nearest = nearest_triangles(from, nudged);
  std::vector<mesh::CornerUvs> uvs(to.triangles.size());
  for (std::size_t f = 0; f < to.triangles.size(); ++f) {
    for (std::size_t k = 0; k < 3; ++k)
      uvs[f][k] = uv_at(corner(to.triangles[f], k), from, static_cast<std::size_t>(nearest[3 * f + k]));
  }
  return uvs;
}

}  // namespace geometry
