// A triangle mesh as a collider's shape, in the collider's own frame: its triangles in an AABB tree for the nearest
// point, and how a point's side is told. A closed mesh (every edge shared by two triangles wound opposite ways) is
// solid: the sign of the distance comes from the angle-weighted pseudo-normal of the nearest feature (vertex, edge or
// face), which is exact for any point (Bærentzen & Aanæs 2005, "Signed distance computation using the angle weighted
// pseudonormal", IEEE TVCG 11(3)). Any other mesh is a two-sided sheet of a thickness: inside means nearer the
// triangles than half of it.
#pragma once

#include <array>
#include <memory>
#include <span>
#include <vector>

#include "sim/contact/collider_shape.hpp"

namespace sim {

struct ColliderMesh {
  std::vector<Vec3> vertices_m;                   // local, scaled [m]
  std::vector<softbody::Triangle> triangles;      // counter-clockwise seen from outside when closed
  bool closed = false;                            // solid (signed distance) rather than a sheet
  double half_thickness_m = 0.0;                  // a sheet's: inside within this of the triangles [m]
  std::size_t boundary_edges = 0;                 // edges of one triangle only (a closed mesh has none)
  Vec3 lo_m = Vec3::Zero(), hi_m = Vec3::Zero();  // local box of the solid or the sheet with its thickness [m]
  std::vector<Vec3> face_normals;                 // unit, per triangle
  std::vector<Vec3> vertex_normals;               // closed: Σ corner angle × face normal (not normalised)
  std::vector<std::array<Vec3, 3>> edge_normals;  // closed: per triangle, edge k (corner k to k + 1): n₁ + n₂
  std::vector<std::array<int, 3>> edge_partners;  // closed: per triangle, the triangle across edge k (a refit's)
  std::vector<Vec3> vertex_velocities;            // a point-cached mesh's, local [m/s], per vertex; else empty
  // AABB tree: a leaf (count > 0) holds `count` triangles from `first` of `order`; an inner node its children at
  // `first` and −count.
  struct Node {
    Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();
    int first = 0, count = 0;
  };
  std::vector<Node> nodes;  // nodes[0]: the root
  std::vector<int> order;   // triangle indices, grouped by leaf
};

// The collider mesh of these local vertices (already scaled) and triangles: degenerate triangles (zero area) are
// dropped, a closed mesh wound inside out is turned, and the tree is built. `thickness_m` serves an open mesh.
// Throws std::invalid_argument when no triangle with an area remains.
std::shared_ptr<const ColliderMesh> make_collider_mesh(std::vector<Vec3> vertices_m,
                                                       std::vector<softbody::Triangle> triangles, double thickness_m);

// The signed distance, outward normal and nearest surface point of local point q (all local).
SurfacePoint mesh_nearest_local(const ColliderMesh& mesh, const Vec3& q);

// True when local point q is inside: the local box rejects most points before any triangle is looked at.
bool mesh_inside_local(const ColliderMesh& mesh, const Vec3& q);

// Where the local segment a → b first enters the mesh (continuous contact, sim/contact/collider_sweep.hpp): a closed
// mesh where it first crosses a triangle from its outer side, a sheet where it first crosses a triangle, moved back
// by half the thickness towards a. `point` and `normal` (unit, facing the side it came from) are local. False when
// it crosses none.
bool mesh_segment_entry_local(const ColliderMesh& mesh, const Vec3& a, const Vec3& b, Vec3& point, Vec3& normal);

// The same mesh (triangles, sides, the tree's grouping) with its vertices moved to `vertices_m` (a point cache's pose,
// sim/contact/collider_point_cache.hpp) and moving at `velocities` (local [m/s], per vertex): the face normals,
// pseudo-normals and the tree's boxes are recomputed (the tree refitted, not rebuilt). A triangle that has lost its
// area in this pose gets a zero normal (no side).
std::shared_ptr<const ColliderMesh> refit_collider_mesh(const ColliderMesh& mesh, std::vector<Vec3> vertices_m,
                                                        std::vector<Vec3> velocities);

// The nearest point of the mesh to local q, as its triangle and the barycentric weights of its corners.
struct MeshPoint {
  int triangle = 0;
  std::array<double, 3> weights{1.0, 0.0, 0.0};
};
MeshPoint mesh_nearest_point_local(const ColliderMesh& mesh, const Vec3& q);

// The local position of that point (Σ weight × corner).
// Σ_k w_k value_k over the point's triangle's corners, for any per-vertex value (positions, velocities).
Vec3 at_mesh_point(const ColliderMesh& mesh, const MeshPoint& point, std::span<const Vec3> per_vertex);
Vec3 mesh_point_position(const ColliderMesh& mesh, const MeshPoint& point);

}  // namespace sim
