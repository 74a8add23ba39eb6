// Vertex welding with a uniform hash grid whose cells are as wide as the tolerance.
#include "mesh/weld.hpp"

#include <cmath>
#include <string>
#include <unordered_map>

#include "core/errors.hpp"

namespace mesh {
namespace {

struct CellHash {
  std::size_t operator()(const std::array<long long, 3>& c) const {
    // Unsigned: the same bits as before for small cells, and no signed overflow for far ones.
    using U = unsigned long long;
    return std::hash<U>()(static_cast<U>(c[0]) * 73856093ULL ^ static_cast<U>(c[1]) * 19349663ULL ^
                          static_cast<U>(c[2]) * 83492791ULL);
  }
};

// A grid coordinate that llround can take: NaN, infinite and huge quotients are clamped to a far cell
// (only the hash bucket changes; candidates are still compared by distance, and NaN matches nothing).
long long cell_coordinate(double quotient) {
  constexpr double kFarCell = 4.0e18;  // below 2^63 - 1, and +-1 from it stays in range
  const double q = std::floor(quotient);
  if (!(q > -kFarCell && q < kFarCell))
    return q < 0.0 ? -static_cast<long long>(kFarCell) : static_cast<long long>(kFarCell);
  return std::llround(q);
}

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
    for (int i : t) {
      if (i < 0 || static_cast<std::size_t>(i) >= mesh.vertices.size()) {
        throw softbody::InputError("has a face whose vertex index " + std::to_string(i) + " is outside its " +
                                   std::to_string(mesh.vertices.size()) + " vertices");
      }
      used[static_cast<std::size_t>(i)] = true;
    }
  }

  std::unordered_map<std::array<long long, 3>, std::vector<int>, CellHash> grid;
  auto cell_of = [&](const Vec3& p) {
    return std::array<long long, 3>{cell_coordinate((p.x() - lo.x()) / tolerance),
                                    cell_coordinate((p.y() - lo.y()) / tolerance),
                                    cell_coordinate((p.z() - lo.z()) / tolerance)};
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
  out.corner_uvs = mesh.corner_uvs;  // per corner: a seam's sides keep their own
  return out;
}

}  // namespace mesh
