// Mesh repair on CGAL's Polygon Mesh Processing, behind a header without CGAL: what turns a downloaded
// model (holes, duplicate or zero-area faces, non-manifold edges, mixed winding) into a closed surface.
#pragma once

#include <string>
#include <vector>

#include "mesh/repair_options.hpp"
#include "mesh/repair_step.hpp"
#include "mesh/trimesh.hpp"

namespace geometry {

using mesh::RepairedMesh;

// Repairs a welded mesh in this order (each step where `options` asks for it):
//  1. polygon soup: faces with a repeated vertex and duplicate faces removed (PMP::repair_polygon_soup);
//  2. non-manifold vertices and edges split, winding made consistent (PMP::orient_polygon_soup);
//  3. the soup made a Surface_mesh, borders with matching vertices stitched (PMP::stitch_borders);
//  4. zero-area faces removed by edge collapses and flips (PMP::remove_degenerate_faces);
//  5. holes filled (PMP::triangulate_refine_and_fair_hole; a hole whose fairing fails keeps the refined
//     triangulation), 6. flat parts (two-sided sheets, no volume) removed, every part kept or only the largest,
//  7. each closed part turned outward (6V > 0), 8. with "parts": "union" (the default) the parts that
//     overlap, touch or nest joined into one closed surface (PMP::corefine_and_compute_union).
// UVs, where the mesh has them, are carried over (geometry::transfer_corner_uvs).
// Deterministic: the same mesh gives the same bits. Never throws on a bad mesh; validation judges the result.
RepairedMesh repair_mesh(const mesh::TriMesh& welded, const mesh::RepairOptions& options);

}  // namespace geometry
