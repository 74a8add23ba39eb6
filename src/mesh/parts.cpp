// Union-find over triangles (parts) and over the triangles around each vertex (fans).
#include "mesh/parts.hpp"

#include <algorithm>
#include <numeric>
#include <unordered_map>

namespace mesh {
namespace {

struct DisjointSets {
  std::vector<int> parent;
  explicit DisjointSets(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int i) {
    while (parent[static_cast<std::size_t>(i)] != i) {
      parent[static_cast<std::size_t>(i)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(i)])];
      i = parent[static_cast<std::size_t>(i)];
    }
    return i;
  }
  void join(int a, int b) { parent[static_cast<std::size_t>(find(a))] = find(b); }
};

std::uint64_t edge_key(int a, int b) {
  return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | static_cast<std::uint32_t>(std::max(a, b));
}

}  // namespace

MeshParts edge_connected_parts(const TriMesh& mesh) {
  DisjointSets sets(mesh.triangles.size());
  std::unordered_map<std::uint64_t, int> first_user;  // edge -> a triangle that uses it
  first_user.reserve(mesh.triangles.size() * 3 / 2 + 1);
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Triangle& t = mesh.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const auto [it, fresh] = first_user.emplace(edge_key(t[k], t[(k + 1) % 3]), static_cast<int>(f));
      if (!fresh) sets.join(static_cast<int>(f), it->second);
    }
  }
  MeshParts parts;
  parts.part_of_triangle.resize(mesh.triangles.size());
  std::unordered_map<int, int> number;  // root -> part
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const auto [it, fresh] = number.emplace(sets.find(static_cast<int>(f)), parts.count);
    if (fresh) ++parts.count;
    parts.part_of_triangle[f] = it->second;
  }
  return parts;
}

std::vector<int> pinched_vertices(const TriMesh& mesh) {
  std::vector<std::vector<int>> around(mesh.vertices.size());  // triangles at each vertex
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    for (int v : mesh.triangles[f]) around[static_cast<std::size_t>(v)].push_back(static_cast<int>(f));
  }
  std::vector<int> pinched;
  for (std::size_t v = 0; v < around.size(); ++v) {
    const std::vector<int>& fan = around[v];
    if (fan.size() < 2) continue;
    // Two triangles at v are in one fan when they share an edge at v: a second vertex in common.
    DisjointSets sets(fan.size());
    std::unordered_map<int, int> other_vertex_user;
    for (std::size_t i = 0; i < fan.size(); ++i) {
      for (int w : mesh.triangles[static_cast<std::size_t>(fan[i])]) {
        if (w == static_cast<int>(v)) continue;
        const auto [it, fresh] = other_vertex_user.emplace(w, static_cast<int>(i));
        if (!fresh) sets.join(static_cast<int>(i), it->second);
      }
    }
    int fans = 0;
    for (std::size_t i = 0; i < fan.size(); ++i) fans += sets.find(static_cast<int>(i)) == static_cast<int>(i) ? 1 : 0;
    if (fans > 1) pinched.push_back(static_cast<int>(v));
  }
  return pinched;
}

std::vector<TriMesh> split_parts(const TriMesh& mesh, const MeshParts& parts) {
  std::vector<TriMesh> meshes(static_cast<std::size_t>(parts.count));
  std::vector<std::unordered_map<int, int>> renumber(meshes.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const auto p = static_cast<std::size_t>(parts.part_of_triangle[f]);
    Triangle t = mesh.triangles[f];
    for (int& v : t) {
      const auto [it, fresh] = renumber[p].emplace(v, static_cast<int>(meshes[p].vertices.size()));
      if (fresh) meshes[p].vertices.push_back(mesh.vertices[static_cast<std::size_t>(v)]);
      v = it->second;
    }
    meshes[p].triangles.push_back(t);
    if (mesh.has_uvs()) meshes[p].corner_uvs.push_back(mesh.corner_uvs[f]);
  }
  return meshes;
}

}  // namespace mesh
