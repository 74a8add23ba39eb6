// The nearest triangle of a surface to each of many points, by an AABB tree: how a detailed mesh finds
// where on the simulation proxy each of its vertices sits.
#pragma once

#include <span>
#include <vector>

#include "mesh/trimesh.hpp"

namespace geometry {

// For each point, the index of a triangle of `surface` at the smallest Euclidean distance (CGAL's AABB tree
// over the triangles: about log(T) per query, so 100k points on a few thousand triangles take well under a
// second). Deterministic. Throws std::invalid_argument if `surface` has no triangle.
std::vector<int> nearest_triangles(const mesh::TriMesh& surface, std::span<const mesh::Vec3> points);

}  // namespace geometry
