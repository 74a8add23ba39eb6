// Conversion between TriMesh and CGAL's Surface_mesh.
#include "geometry/cgal_surface.hpp"

#include <stdexcept>
#include <vector>

namespace geometry {

SurfaceMesh to_surface_mesh(const mesh::TriMesh& mesh) {
  SurfaceMesh surface;
  surface.reserve(static_cast<SurfaceMesh::size_type>(mesh.vertices.size()),
                  static_cast<SurfaceMesh::size_type>(3 * mesh.triangles.size()),
                  static_cast<SurfaceMesh::size_type>(mesh.triangles.size()));
  std::vector<SurfaceMesh::Vertex_index> index;
  index.reserve(mesh.vertices.size());
  for (const mesh::Vec3& x : mesh.vertices) index.push_back(surface.add_vertex(Point(x.x(), x.y(), x.z())));
  for (const mesh::Triangle& t : mesh.triangles) {
    // add_face refuses (returns null_face) a face that would make the surface non-manifold; a caller
    // that needs every face (repair) orients and splits the soup first with CGAL's soup functions.
    surface.add_face(index[static_cast<std::size_t>(t[0])], index[static_cast<std::size_t>(t[1])],
                     index[static_cast<std::size_t>(t[2])]);
  }
  return surface;
}

mesh::TriMesh to_trimesh(const SurfaceMesh& surface) {
  mesh::TriMesh result;
  result.vertices.reserve(surface.number_of_vertices());
  result.triangles.reserve(surface.number_of_faces());
  std::vector<int> renumbered(surface.num_vertices(), -1);  // indexed by CGAL's vertex index
  for (SurfaceMesh::Vertex_index v : surface.vertices()) {
    renumbered[static_cast<std::size_t>(v)] = static_cast<int>(result.vertices.size());
    const Point& p = surface.point(v);
    result.vertices.emplace_back(p.x(), p.y(), p.z());
  }
  for (SurfaceMesh::Face_index f : surface.faces()) {
    mesh::Triangle triangle{};
    std::size_t corner = 0;
    for (SurfaceMesh::Vertex_index v : CGAL::vertices_around_face(surface.halfedge(f), surface)) {
      if (corner == 3) throw std::invalid_argument("to_trimesh: a face with more than three vertices");
      triangle[corner++] = renumbered[static_cast<std::size_t>(v)];
    }
    if (corner != 3) throw std::invalid_argument("to_trimesh: a face with fewer than three vertices");
    result.triangles.push_back(triangle);
  }
  return result;
}

}  // namespace geometry
