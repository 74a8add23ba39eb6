// The bridge between softbody's TriMesh and CGAL's Surface_mesh: the one place that converts between them.
#pragma once

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include "mesh/trimesh.hpp"

namespace geometry {

// Exact predicates (orientation, intersection tests) with double coordinates: what CGAL's Polygon Mesh
// Processing recommends for repair and remeshing.
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;

// Every vertex and triangle of `mesh`, in order (vertex i of the TriMesh is vertex i of the result).
SurfaceMesh to_surface_mesh(const mesh::TriMesh& mesh);

// The surface's vertices and triangular faces, compacted (removed elements skipped) and renumbered in
// CGAL's iteration order. Throws std::invalid_argument if a face is not a triangle.
mesh::TriMesh to_trimesh(const SurfaceMesh& surface);

}  // namespace geometry
