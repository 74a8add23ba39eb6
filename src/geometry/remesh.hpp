// Isotropic remeshing of a closed surface for the simulation proxy: well-shaped triangles of one edge length.
#pragma once

#include "mesh/trimesh.hpp"

namespace geometry {

// `closed` remeshed by CGAL's isotropic remeshing (split long edges, collapse short ones, flip towards
// valence 6, tangential relaxation, projection back onto the input) to edges of about `target_edge_length`
// (the input's units). The result is closed, manifold and wound like the input; the same input gives the
// same bits. Throws std::invalid_argument if `closed` is not a closed triangle surface or the length is not
// positive.
//
// `sharp_edge_angle_deg` > 0 keeps the edges whose dihedral angle exceeds it (PMP::detect_sharp_edges) as
// constrained polylines, those at least half the target long (shorter ones are detail below the resolution).
// Off (0) by default: on organic meshes the feature corners pin short edges and high-valence vertices that
// set the stable step (measured, verlet's stable dt at a 2,000-vertex proxy: the cow 1.35e-5 s with 60°,
// 4.47e-5 s without; the closed bunny 2.0e-6 s against 5.19e-5 s), and the detailed mesh carried along shows
// the features anyway. A CAD shape (the cube) keeps its edges and volume with 60°.
mesh::TriMesh remesh_to_edge_length(const mesh::TriMesh& closed, double target_edge_length,
                                    double sharp_edge_angle_deg = 0.0);

// `closed` remeshed isotropically to about `target_vertices` vertices (within 10 % on the shapes tested).
// The first edge length comes from the area: V vertices of equilateral triangles of side L tile a closed
// surface of area A with 2V triangles (Euler, genus 0), so A ≈ 2V·(√3/4)L², that is L ≈ sqrt(2A / (√3 V));
// then L is corrected by sqrt(V_got / V_target) (vertices ∝ 1/L²) and the input remeshed again, at most a
// few times, keeping the closest result.
mesh::TriMesh remesh_to_vertex_count(const mesh::TriMesh& closed, int target_vertices,
                                     double sharp_edge_angle_deg = 0.0);

}  // namespace geometry
