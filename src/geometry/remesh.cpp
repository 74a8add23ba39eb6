// Isotropic remeshing on CGAL's Polygon Mesh Processing.
#include "geometry/remesh.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/boost/graph/helpers.h>

#include "geometry/cgal_surface.hpp"

namespace geometry {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;

constexpr double kShortestSharpEdge = 0.5;  // sharp edges below this fraction of the target are not kept
constexpr int kRemeshIterations = 5;        // CGAL's split / collapse / flip / relax rounds per remesh
constexpr int kMaxCountCorrections = 4;     // remeshes to land near the asked vertex count
constexpr double kCountTolerance = 0.05;    // stop correcting within 5 % of the asked count

// The closed input as a Surface_mesh. Through CGAL's soup functions rather than face by face: a vertex where two
// fans of triangles touch (a pinch, allowed by mesh::validate_closed, which checks edges) cannot be one vertex of
// a halfedge mesh, so orient_polygon_soup gives each fan its own copy at the same place.
SurfaceMesh closed_surface(const mesh::TriMesh& closed) {
  std::vector<Point> points;
  points.reserve(closed.vertices.size());
  for (const mesh::Vec3& x : closed.vertices) points.emplace_back(x.x(), x.y(), x.z());
  std::vector<std::array<std::size_t, 3>> polygons;
  polygons.reserve(closed.triangles.size());
  for (const mesh::Triangle& t : closed.triangles) {
    polygons.push_back(
        {static_cast<std::size_t>(t[0]), static_cast<std::size_t>(t[1]), static_cast<std::size_t>(t[2])});
  }
  PMP::orient_polygon_soup(points, polygons);
  SurfaceMesh surface;
  if (PMP::is_polygon_soup_a_polygon_mesh(polygons)) PMP::polygon_soup_to_polygon_mesh(points, polygons, surface);
  if (surface.number_of_faces() != closed.triangles.size() || !CGAL::is_closed(surface) ||
      !CGAL::is_triangle_mesh(surface)) {
    throw std::invalid_argument("remesh: the input is not a closed, manifold triangle surface");
  }
  // orient_polygon_soup keeps a consistent winding but may choose the other one: keep the input's.
  if ((PMP::volume(surface) > 0.0) != (mesh::signed_volume(closed) > 0.0)) PMP::reverse_face_orientations(surface);
  return surface;
}

mesh::TriMesh remeshed(SurfaceMesh surface, double target_edge_length, double sharp_edge_angle_deg) {
  if (!(target_edge_length > 0.0) || !std::isfinite(target_edge_length)) {
    throw std::invalid_argument("remesh: the target edge length must be positive and finite");
  }
  auto sharp = surface.add_property_map<SurfaceMesh::Edge_index, bool>("e:sharp", false).first;
  if (sharp_edge_angle_deg > 0.0) PMP::detect_sharp_edges(surface, sharp_edge_angle_deg, sharp);
  // A sharp edge far shorter than the target is a crease's detail below the proxy's resolution; kept, it
  // could never be collapsed (its ends are feature corners) and its length would set the stable step.
  for (SurfaceMesh::Edge_index e : surface.edges()) {
    if (sharp[e] && PMP::edge_length(e, surface) < kShortestSharpEdge * target_edge_length) sharp[e] = false;
  }
  PMP::isotropic_remeshing(faces(surface), target_edge_length, surface,
                           CGAL::parameters::number_of_iterations(kRemeshIterations).edge_is_constrained_map(sharp));
  surface.collect_garbage();
  if (!CGAL::is_closed(surface)) throw std::logic_error("remesh: the remeshed surface is not closed");
  return to_trimesh(surface);
}

}  // namespace

mesh::TriMesh remesh_to_edge_length(const mesh::TriMesh& closed, double target_edge_length,
                                    double sharp_edge_angle_deg) {
  return remeshed(closed_surface(closed), target_edge_length, sharp_edge_angle_deg);
}

mesh::TriMesh remesh_to_vertex_count(const mesh::TriMesh& closed, int target_vertices, double sharp_edge_angle_deg) {
  if (target_vertices < 4) throw std::invalid_argument("remesh: a closed surface needs at least 4 vertices");
  const SurfaceMesh input = closed_surface(closed);
  const double area = PMP::area(input);
  const double target = static_cast<double>(target_vertices);
  double edge_length = std::sqrt(2.0 * area / (std::sqrt(3.0) * target));  // L ≈ sqrt(2A / (√3 V))
  mesh::TriMesh best;
  double best_error = INFINITY;
  for (int attempt = 0; attempt < kMaxCountCorrections; ++attempt) {
    mesh::TriMesh result = remeshed(input, edge_length, sharp_edge_angle_deg);
    const double got = static_cast<double>(result.vertices.size());
    const double error = std::abs(got - target) / target;
    if (error < best_error) {
      best_error = error;
      best = std::move(result);
    }
    if (best_error <= kCountTolerance) break;
    edge_length *= std::sqrt(got / target);  // vertices ∝ 1/L²
  }
  return best;
}

}  // namespace geometry
