// Writing the colliders' surfaces for export.
#include "output/collider_export.hpp"

#include "frames/collider_tessellation.hpp"
#include "output/mesh_file_writer.hpp"

namespace output {

std::filesystem::path collider_path(const std::filesystem::path& dir, std::size_t index, const std::string& extension) {
  return dir / ("collider_" + std::to_string(index) + extension);
}

mesh::TriMesh collider_surface(const sim::ColliderGeometry& geometry, double plane_half_size_m) {
  frames::ColliderTriangles surface;
  switch (geometry.shape) {
    case sim::ColliderShape::Plane:
      surface = frames::plane_square(geometry, softbody::Vec3::Zero(), plane_half_size_m);
      break;
    case sim::ColliderShape::Mesh: surface = frames::placed_mesh(geometry); break;
    case sim::ColliderShape::Box:
    case sim::ColliderShape::Sphere:
    case sim::ColliderShape::Capsule: surface = frames::bounded_collider_triangles(geometry); break;
  }
  mesh::TriMesh m;
  m.vertices = std::move(surface.positions);
  m.triangles = std::move(surface.triangles);
  return m;
}

std::vector<std::filesystem::path> write_colliders(const std::filesystem::path& dir,
                                                   std::span<const sim::Collider> colliders,
                                                   const std::string& extension, double plane_half_size_m) {
  std::vector<std::filesystem::path> written;
  for (std::size_t i = 0; i < colliders.size(); ++i) {
    if (colliders[i].motion.moving()) continue;
    written.push_back(collider_path(dir, i, extension));
    write_mesh_file(written.back(), collider_surface(colliders[i].geometry, plane_half_size_m),
                    "softbody collider " + std::to_string(i) + " (static, world coordinates, m)");
  }
  return written;
}

}  // namespace output
