// The detailed mesh anchored on the proxy.
#include "setup/bind_skin.hpp"

#include <algorithm>

#include "geometry/nearest_triangle.hpp"
#include "mesh/parts.hpp"

namespace setup {
namespace {

// The part of each vertex (the part of a triangle that uses it; -1 for a vertex no triangle uses).
std::vector<int> part_of_vertex(std::size_t vertex_count, const std::vector<softbody::Triangle>& faces,
                                const mesh::MeshParts& parts) {
  std::vector<int> part(vertex_count, -1);
  for (std::size_t t = 0; t < faces.size(); ++t) {
    for (int v : faces[t]) part[static_cast<std::size_t>(v)] = parts.part_of_triangle[t];
  }
  return part;
}

// For each detailed part, the proxy part that most of its vertices are nearest to (ties: the lower index).
std::vector<int> matching_proxy_parts(const std::vector<int>& detailed_part, int detailed_count,
                                      const std::vector<int>& nearest, const mesh::MeshParts& proxy_parts) {
  std::vector<std::vector<int>> votes(static_cast<std::size_t>(detailed_count),
                                      std::vector<int>(static_cast<std::size_t>(proxy_parts.count), 0));
  for (std::size_t i = 0; i < detailed_part.size(); ++i) {
    if (detailed_part[i] < 0) continue;
    ++votes[static_cast<std::size_t>(detailed_part[i])]
           [static_cast<std::size_t>(proxy_parts.part_of_triangle[static_cast<std::size_t>(nearest[i])])];
  }
  std::vector<int> match;
  for (const std::vector<int>& v : votes)
    match.push_back(static_cast<int>(std::max_element(v.begin(), v.end()) - v.begin()));
  return match;
}

// Where the proxy has several parts (a teapot's body, spout, handle and lid passing into each other), a
// detailed vertex of one part can lie nearest to another part's surface; anchored there, it would be torn
// off with that part. Each detailed part is anchored on the proxy part that most of its vertices are nearest
// to, and the vertices nearest to another part are anchored on the nearest triangle of their own.
void keep_parts_apart(const std::vector<softbody::Vec3>& detailed_x,
                      const std::vector<softbody::Triangle>& detailed_faces, const std::vector<softbody::Vec3>& proxy_x,
                      const std::vector<softbody::Triangle>& proxy_faces, std::vector<int>& nearest) {
  const mesh::MeshParts proxy_parts = mesh::edge_connected_parts(mesh::TriMesh{proxy_x, proxy_faces, {}});
  if (proxy_parts.count < 2) return;
  const mesh::MeshParts detailed_parts = mesh::edge_connected_parts(mesh::TriMesh{detailed_x, detailed_faces, {}});
  const std::vector<int> detailed_part = part_of_vertex(detailed_x.size(), detailed_faces, detailed_parts);
  const std::vector<int> match = matching_proxy_parts(detailed_part, detailed_parts.count, nearest, proxy_parts);
  for (int p = 0; p < proxy_parts.count; ++p) {
    std::vector<int> stray;  // detailed vertices that belong on proxy part p but are nearest to another part
    for (std::size_t i = 0; i < detailed_x.size(); ++i) {
      if (detailed_part[i] < 0 || match[static_cast<std::size_t>(detailed_part[i])] != p) continue;
      if (proxy_parts.part_of_triangle[static_cast<std::size_t>(nearest[i])] != p) stray.push_back(static_cast<int>(i));
    }
    if (stray.empty()) continue;
    mesh::TriMesh own{proxy_x, {}, {}};
    std::vector<int> face_index;  // own.triangles[k] is proxy face face_index[k]
    for (std::size_t t = 0; t < proxy_faces.size(); ++t) {
      if (proxy_parts.part_of_triangle[t] != p) continue;
      own.triangles.push_back(proxy_faces[t]);
      face_index.push_back(static_cast<int>(t));
    }
    std::vector<softbody::Vec3> points;
    for (int i : stray) points.push_back(detailed_x[static_cast<std::size_t>(i)]);
    const std::vector<int> own_nearest = geometry::nearest_triangles(own, points);
    for (std::size_t k = 0; k < stray.size(); ++k) {
      nearest[static_cast<std::size_t>(stray[k])] = face_index[static_cast<std::size_t>(own_nearest[k])];
    }
  }
}

}  // namespace

sim::Skin bind_skin(const std::vector<softbody::Vec3>& detailed_x,
                    const std::vector<softbody::Triangle>& detailed_faces, const std::vector<softbody::Vec3>& proxy_x,
                    const std::vector<softbody::Triangle>& proxy_faces, int body) {
  std::vector<int> nearest = geometry::nearest_triangles(mesh::TriMesh{proxy_x, proxy_faces, {}}, detailed_x);
  keep_parts_apart(detailed_x, detailed_faces, proxy_x, proxy_faces, nearest);
  std::vector<softbody::Vec3> normals;
  sim::vertex_normals(proxy_x, proxy_faces, normals);
  sim::Skin skin{body, detailed_faces, {}, {}};
  skin.anchors.reserve(detailed_x.size());
  for (std::size_t i = 0; i < detailed_x.size(); ++i) {
    skin.anchors.push_back(sim::anchor_point(detailed_x[i], nearest[i], proxy_x, proxy_faces, normals));
  }
  return skin;
}

}  // namespace setup
