// Closed-surface validation: edge use counts, winding consistency, degenerate faces, orientation.
#include "mesh/check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <unordered_map>

#include "core/errors.hpp"

namespace mesh {
namespace {

[[noreturn]] void fail(MeshDefect defect, const std::string& what) { throw MeshDefectError(defect, what); }

std::uint64_t edge_key(int a, int b) {
  return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | static_cast<std::uint32_t>(std::max(a, b));
}

double bounding_diagonal(const TriMesh& mesh) {
  Vec3 lo = mesh.vertices[0], hi = mesh.vertices[0];
  for (const Vec3& v : mesh.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  return (hi - lo).norm();
}

// A mesh with triangles enough whose vertices lie at fewer than 4 distinct points (after the weld): all at one
// point, or the rest so close together beside a far one that the weld's tolerance, relative to the bounding box,
// joined them.
std::string too_few_points_words(const TriMesh& mesh) {
  const std::string head = "has " + std::to_string(mesh.triangles.size()) + " triangles but ";
  char where[200];
  if (mesh.vertices.size() <= 1) {
    const Vec3 p = mesh.vertices.empty() ? Vec3::Zero() : mesh.vertices[0];
    std::snprintf(where, sizeof where, "all its vertices at one point (%.6g, %.6g, %.6g)", p.x(), p.y(), p.z());
    return head + where + ": every triangle is degenerate (zero area)";
  }
  Vec3 lo = mesh.vertices[0], hi = mesh.vertices[0];
  for (const Vec3& v : mesh.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  std::snprintf(where, sizeof where, "%zu distinct points within a box from (%.6g, %.6g, %.6g) to (%.6g, %.6g, %.6g)",
                mesh.vertices.size(), lo.x(), lo.y(), lo.z(), hi.x(), hi.y(), hi.z());
  return head + "its vertices at only " + where +
         " (vertices closer than 1e-7 of the box's diagonal are one point): every triangle is degenerate (zero "
         "area); is one vertex far from the others?";
}

void check_degenerate_faces(const TriMesh& mesh) {
  const double diagonal = bounding_diagonal(mesh);
  const double min_area = 1e-14 * diagonal * diagonal;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Triangle& t = mesh.triangles[f];
    const double area =
        0.5 * (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]).norm();
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0] || !(area > min_area)) {
      fail(MeshDefect::Degenerate, "triangle " + std::to_string(f) + " is degenerate (zero area" +
                                       (t[0] == t[1] || t[1] == t[2] || t[2] == t[0] ? ", repeated vertex" : "") +
                                       "): every face must span an area to carry pressure");
    }
  }
}

}  // namespace

double signed_volume(const TriMesh& mesh) {
  double six_volume = 0.0;
  for (const Triangle& t : mesh.triangles) {
    six_volume += mesh.vertices[t[0]].dot(mesh.vertices[t[1]].cross(mesh.vertices[t[2]]));
  }
  return six_volume / 6.0;
}

double surface_area(const TriMesh& mesh) {
  double area = 0.0;
  for (const Triangle& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[t[0]];
    area += 0.5 * (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a).norm();
  }
  return area;
}

EdgeCounts count_edges(const TriMesh& mesh) {
  struct Use {
    int count = 0;
    int forward = 0;  // uses as (min -> max)
  };
  std::unordered_map<std::uint64_t, Use> uses;
  uses.reserve(mesh.triangles.size() * 3 / 2 + 1);
  for (const Triangle& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      Use& use = uses[edge_key(a, b)];
      ++use.count;
      if (a < b) ++use.forward;
    }
  }
  EdgeCounts counts;
  counts.edges = uses.size();
  for (const auto& [key, use] : uses) {
    if (use.count == 1) ++counts.boundary;
    if (use.count > 2) ++counts.non_manifold;
    if (use.count == 2 && use.forward != 1) ++counts.misoriented;
  }
  return counts;
}

void validate_closed(TriMesh& mesh, std::vector<std::string>& notes) {
  if (mesh.triangles.size() < 4) {
    fail(MeshDefect::TooSmall,
         "has " + std::to_string(mesh.triangles.size()) + " triangles; a closed surface needs at least 4");
  }
  if (mesh.vertices.size() < 4) fail(MeshDefect::TooSmall, too_few_points_words(mesh));
  check_degenerate_faces(mesh);
  const EdgeCounts counts = count_edges(mesh);
  if (counts.boundary > 0) {
    fail(MeshDefect::Open, "is not closed: " + std::to_string(counts.boundary) + " boundary edges (of " +
                               std::to_string(counts.edges) + "); pressure needs a closed surface");
  }
  if (counts.non_manifold > 0) {
    fail(MeshDefect::NonManifold,
         "is not manifold: " + std::to_string(counts.non_manifold) + " edges are shared by more than two triangles");
  }
  if (counts.misoriented > 0) {
    fail(MeshDefect::Winding, "has inconsistent winding: " + std::to_string(counts.misoriented) +
                                  " edges are traversed in the same direction by both of their triangles");
  }
  const double volume = signed_volume(mesh);
  const double diagonal = bounding_diagonal(mesh);
  if (!(std::abs(volume) > 1e-12 * diagonal * diagonal * diagonal))
    fail(MeshDefect::NoVolume, "encloses no volume (flat or self-cancelling surface)");
  if (volume < 0.0) {
    for (Triangle& t : mesh.triangles) std::swap(t[1], t[2]);
    for (CornerUvs& uv : mesh.corner_uvs) std::swap(uv[1], uv[2]);
    notes.push_back("the winding was inverted (normals pointing inward); flipped every triangle");
  }
}

}  // namespace mesh
