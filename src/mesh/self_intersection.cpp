// Triangle pairs whose edges pierce each other, candidates from a hashed uniform grid.
#include "mesh/self_intersection.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>

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

// A grid cell a triangle's bounding box touches, and the triangle: sorted, equal cells lie together.
struct CellEntry {
  std::array<long long, 3> cell;
  int triangle;
  bool operator<(const CellEntry& other) const {
    return cell != other.cell ? cell < other.cell : triangle < other.triangle;
  }
};

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
  // Every (cell, triangle) pair, sorted: the triangles of one cell lie together, in ascending order. (A sort
  // rather than a hash map of growing lists and a set of tested pairs: those made the check take 80 % of
  // `prepare`'s time on the 124k-triangle ogre, most of it in malloc.)
  std::vector<std::array<long long, 3>> first_cell(boxes.size());
  std::vector<CellEntry> entries;
  entries.reserve(2 * boxes.size());
  for (std::size_t f = 0; f < boxes.size(); ++f) {
    const auto& [lo, hi] = boxes[f];
    long long a[3], b[3];
    for (int axis = 0; axis < 3; ++axis) {
      a[axis] = cell_of(lo[axis], origin[axis]);
      b[axis] = std::min(cell_of(hi[axis], origin[axis]), a[axis] + kMaxSpan - 1);
    }
    first_cell[f] = {a[0], a[1], a[2]};
    for (long long i = a[0]; i <= b[0]; ++i) {
      for (long long j = a[1]; j <= b[1]; ++j) {
        for (long long k = a[2]; k <= b[2]; ++k) entries.push_back({{i, j, k}, static_cast<int>(f)});
      }
    }
  }
  std::sort(entries.begin(), entries.end());
  // Each pair is tested once, in the first cell the two share (per axis the larger of their first cells: the
  // lowest corner of the box of cells they have in common). The pair reported first is the one with the
  // smallest (later triangle, that cell, earlier triangle), as a scan over the triangles in order finds it.
  struct Candidate {
    int later = -1;
    std::array<long long, 3> cell{};
    int earlier = -1;
  } best;
  for (std::size_t run = 0; run < entries.size();) {
    std::size_t end = run + 1;
    while (end < entries.size() && entries[end].cell == entries[run].cell) ++end;
    const std::array<long long, 3>& here = entries[run].cell;
    for (std::size_t p = run; p < end; ++p) {
      const int other = entries[p].triangle;
      const auto& [olo, ohi] = boxes[static_cast<std::size_t>(other)];
      for (std::size_t q = p + 1; q < end; ++q) {
        const int f = entries[q].triangle;
        const auto& [lo, hi] = boxes[static_cast<std::size_t>(f)];
        if ((olo.array() > hi.array()).any() || (lo.array() > ohi.array()).any()) continue;
        const std::array<long long, 3>& a = first_cell[static_cast<std::size_t>(other)];
        const std::array<long long, 3>& b = first_cell[static_cast<std::size_t>(f)];
        if (std::array<long long, 3>{std::max(a[0], b[0]), std::max(a[1], b[1]), std::max(a[2], b[2])} != here)
          continue;
        const Triangle& s = mesh.triangles[static_cast<std::size_t>(other)];
        const Triangle& t = mesh.triangles[static_cast<std::size_t>(f)];
        if (share_a_vertex(s, t) || !triangles_cross(mesh, s, t)) continue;
        ++found.pairs;
        const bool earlier_found =
            best.later >= 0 && std::tie(best.later, best.cell, best.earlier) < std::tie(f, here, other);
        if (!earlier_found) best = {f, here, other};
      }
    }
    run = end;
  }
  if (found.pairs > 0) found.first = {best.earlier, best.later};
  return found;
}

}  // namespace mesh
