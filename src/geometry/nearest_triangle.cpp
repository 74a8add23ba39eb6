// Nearest-triangle queries on CGAL's AABB tree.
#include "geometry/nearest_triangle.hpp"

#include <stdexcept>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>

#include "geometry/cgal_surface.hpp"

namespace geometry {

std::vector<int> nearest_triangles(const mesh::TriMesh& surface, std::span<const mesh::Vec3> points) {
  if (surface.triangles.empty()) throw std::invalid_argument("nearest_triangles: the surface has no triangle");
  using Triangle3 = Kernel::Triangle_3;
  using Iterator = std::vector<Triangle3>::const_iterator;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_triangle_primitive<Kernel, Iterator>>>;
  std::vector<Triangle3> triangles;
  triangles.reserve(surface.triangles.size());
  const auto point = [&](int v) {
    const mesh::Vec3& x = surface.vertices[static_cast<std::size_t>(v)];
    return Point(x.x(), x.y(), x.z());
  };
  for (const mesh::Triangle& t : surface.triangles) triangles.emplace_back(point(t[0]), point(t[1]), point(t[2]));
  Tree tree(triangles.cbegin(), triangles.cend());
  tree.accelerate_distance_queries();
  std::vector<int> nearest;
  nearest.reserve(points.size());
  for (const mesh::Vec3& p : points) {
    const Iterator hit = tree.closest_point_and_primitive(Point(p.x(), p.y(), p.z())).second;
    nearest.push_back(static_cast<int>(hit - triangles.cbegin()));
  }
  return nearest;
}

}  // namespace geometry
