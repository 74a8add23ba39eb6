// An indexed triangle mesh: the shape a body starts from, before it becomes particles and springs.
#pragma once

#include <vector>

#include "core/vec.hpp"

namespace mesh {

using softbody::CornerUvs;
using softbody::Triangle;
using softbody::Uv;
using softbody::Vec3;

struct TriMesh {
  std::vector<Vec3> vertices;
  std::vector<Triangle> triangles;  // counter-clockwise seen from outside once validated
  // Per triangle, its corners' texture coordinates (per corner: a seam's vertex has one per side); empty when
  // the file has none. Whatever reorders or rewinds triangles keeps these in step.
  std::vector<CornerUvs> corner_uvs;
  bool has_uvs() const { return !corner_uvs.empty(); }
};

// Signed enclosed volume by the divergence theorem: V = Σ x_a·(x_b × x_c) / 6  [m³].
double signed_volume(const TriMesh& mesh);

// Surface area: A = Σ ½ |(x_b − x_a) × (x_c − x_a)|  [mesh units²].
double surface_area(const TriMesh& mesh);

}  // namespace mesh
