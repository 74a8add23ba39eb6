// Triangle pairs whose edges pierce each other, candidates from a hashed uniform grid.
#include "mesh/self_intersection.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <unordered_set>

namespace mesh {
namespace {

// True when the segment p→q passes through the interior of triangle (a, b, c): Möller & Trumbore 1997,
// ray–triangle intersection, restricted to the segment (0 < t < 1) and to barycentric u, v > 0, u + v < 1.
bool segment_crosses_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 d = q - p, e1 = b - a, e2 = c - a;
  const Vec3 h = d.cross(e2);
  const double det = e1.dot(h);
  const double scale = d.norm() * e1.norm() * e2.norm();
  if (!(std::abs(det) > 1e-12 * scale)) return false;  // parallel (or degenerate): no single crossing point
  const Vec3 s = p - a;
  const double u = s.dot(h) / det;
  if (!(u > 0.0 && u < 1.0)) return false;
  const Vec3 k = s.cross(e1);
  const double v = d.dot(k) / det;
  if (!(v > 0.0 && u + v < 1.0)) return false;
  const double t = e2.dot(k) / det;
  return t > 0.0 && t < 1.0;
}

bool triangles_cross(const TriMesh& mesh, const Triangle& s, const Triangle& t) {
  auto x = [&](int i) -> const Vec3& { return mesh.vertices[static_cast<std::size_t>(i)]; };
  for (int k = 0; k < 3; ++k) {
    if (segment_crosses_triangle(x(s[k]), x(s[(k + 1) % 3]), x(t[0]), x(t[1]), x(t[2]))) return true;
    if (segment_crosses_triangle(x(t[k]), x(t[(k + 1) % 3]), x(s[0]), x(s[1]), x(s[2]))) return true;
  }
  return false;
}

bool share_a_vertex(const Triangle& s, const Triangle& t) {
  for (int a : s) {
    for (int b : t) {
      if (a == b) return true;
    }
  }
  return false;
}

}  // namespace

SelfIntersections find_self_intersections(const TriMesh& mesh) {
  SelfIntersections found;
  if (mesh.triangles.size() > kMaxTrianglesChecked || mesh.triangles.empty()) return found;
  found.checked = true;
  // Cells as wide as twice the mean triangle extent: most triangles fall in 1-8 cells.
  std::vector<std::pair<Vec3, Vec3>> boxes;
  boxes.reserve(mesh.triangles.size());
  double extent = 0.0;
  for (const Triangle& t : mesh.triangles) {
    Vec3 lo = mesh.vertices[static_cast<std::size_t>(t[0])], hi = lo;
    for (int v : t) {
      lo = lo.cwiseMin(mesh.vertices[static_cast<std::size_t>(v)]);
      hi = hi.cwiseMax(mesh.vertices[static_cast<std::size_t>(v)]);
    }
    extent += (hi - lo).maxCoeff();
    boxes.emplace_back(lo, hi);
  }
  const double cell = std::max(2.0 * extent / static_cast<double>(mesh.triangles.size()), 1e-300);
  Vec3 origin = boxes.front().first;
  for (const auto& box : boxes) origin = origin.cwiseMin(box.first);
  // A cell index per axis; a triangle spanning more than kMaxSpan cells per axis goes in the first kMaxSpan.
  constexpr long long kMaxSpan = 64;
  auto cell_of = [&](double x, double o) { return static_cast<long long>(std::min(std::floor((x - o) / cell), 1e15)); };
  std::unordered_map<std::uint64_t, std::vector<int>> grid;
  auto key = [](long long i, long long j, long long k) {
    return (static_cast<std::uint64_t>(i) * 73856093ULL) ^ (static_cast<std::uint64_t>(j) * 19349663ULL) ^
           (static_cast<std::uint64_t>(k) * 83492791ULL);
  };
  std::unordered_set<std::uint64_t> tested;
  for (std::size_t f = 0; f < boxes.size(); ++f) {
    const auto& [lo, hi] = boxes[f];
    long long a[3], b[3];
    for (int axis = 0; axis < 3; ++axis) {
      a[axis] = cell_of(lo[axis], origin[axis]);
      b[axis] = std::min(cell_of(hi[axis], origin[axis]), a[axis] + kMaxSpan - 1);
    }
    const Triangle& t = mesh.triangles[f];
    for (long long i = a[0]; i <= b[0]; ++i) {
      for (long long j = a[1]; j <= b[1]; ++j) {
        for (long long k = a[2]; k <= b[2]; ++k) {
          std::vector<int>& members = grid[key(i, j, k)];
          for (int other : members) {
            const std::uint64_t pair = (static_cast<std::uint64_t>(other) << 32) | f;
            const Triangle& s = mesh.triangles[static_cast<std::size_t>(other)];
            if (share_a_vertex(s, t) || !tested.insert(pair).second) continue;
            const auto& [olo, ohi] = boxes[static_cast<std::size_t>(other)];
            if ((olo.array() > hi.array()).any() || (lo.array() > ohi.array()).any()) continue;
            if (!triangles_cross(mesh, s, t)) continue;
            if (found.pairs++ == 0) found.first = {other, static_cast<int>(f)};
          }
          members.push_back(static_cast<int>(f));
        }
      }
    }
  }
  return found;
}

}  // namespace mesh
