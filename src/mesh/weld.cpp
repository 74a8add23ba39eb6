// Vertex welding with a uniform hash grid whose cells are as wide as the tolerance.
#include "mesh/weld.hpp"

#include <cmath>
#include <unordered_map>

namespace mesh {
namespace {

struct CellHash {
  std::size_t operator()(const std::array<long long, 3>& c) const {
    return std::hash<long long>()(c[0] * 73856093LL ^ c[1] * 19349663LL ^ c[2] * 83492791LL);
  }
};

}  // namespace

TriMesh weld(const TriMesh& mesh, double relative_tolerance) {
  if (mesh.vertices.empty()) return mesh;
  Vec3 lo = mesh.vertices[0], hi = mesh.vertices[0];
  for (const Vec3& v : mesh.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  const double tolerance = std::max(relative_tolerance * (hi - lo).norm(), 1e-300);

  std::vector<bool> used(mesh.vertices.size(), false);
  for (const Triangle& t : mesh.triangles) {
    for (int i : t) used[i] = true;
  }

  std::unordered_map<std::array<long long, 3>, std::vector<int>, CellHash> grid;
  auto cell_of = [&](const Vec3& p) {
    return std::array<long long, 3>{std::llround(std::floor((p.x() - lo.x()) / tolerance)),
                                    std::llround(std::floor((p.y() - lo.y()) / tolerance)),
                                    std::llround(std::floor((p.z() - lo.z()) / tolerance))};
  };

  TriMesh out;
  std::vector<int> remap(mesh.vertices.size(), -1);
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    if (!used[i]) continue;
    const Vec3& p = mesh.vertices[i];
    const auto cell = cell_of(p);
    int found = -1;
    for (long long dx = -1; dx <= 1 && found < 0; ++dx) {
      for (long long dy = -1; dy <= 1 && found < 0; ++dy) {
        for (long long dz = -1; dz <= 1 && found < 0; ++dz) {
          auto it = grid.find({cell[0] + dx, cell[1] + dy, cell[2] + dz});
          if (it == grid.end()) continue;
          for (int candidate : it->second) {
            if ((out.vertices[candidate] - p).norm() <= tolerance) {
              found = candidate;
              break;
            }
          }
        }
      }
    }
    if (found < 0) {
      found = static_cast<int>(out.vertices.size());
      out.vertices.push_back(p);
      grid[cell].push_back(found);
    }
    remap[i] = found;
  }
  out.triangles.reserve(mesh.triangles.size());
  for (const Triangle& t : mesh.triangles) out.triangles.push_back({remap[t[0]], remap[t[1]], remap[t[2]]});
  return out;
}

}  // namespace mesh
