// Texture coordinates carried across a change of triangulation (repair renumbers, cuts and adds triangles):
// what keeps a repaired mesh's UVs those of the file it came from.
#pragma once

#include <vector>

#include "mesh/trimesh.hpp"

namespace geometry {

// Per triangle of `to`, its corners' UVs taken from `from` (which has them): each corner looks up the triangle
// of `from` nearest to a point just inside its own triangle next to it (nearest_triangles; the side of a UV
// seam that its triangle is on); a corner at exactly one of that triangle's corners takes that corner's UV
// (bit for bit: an unchanged triangle keeps its UVs), any other corner the UVs interpolated at its
// projection onto that triangle (barycentric, clamped to the triangle).
// Empty when `from` has no UVs or `to` no triangles.
std::vector<mesh::CornerUvs> transfer_corner_uvs(const mesh::TriMesh& from, const mesh::TriMesh& to);

}  // namespace geometry
