// Writing the colliders' surfaces for export.
#include "output/collider_export.hpp"

#include <algorithm>
#include <optional>

#include "frames/collider_tessellation.hpp"
#include "output/mesh_file_writer.hpp"

namespace output {

std::filesystem::path collider_path(const std::filesystem::path& dir, std::size_t index, const std::string& extension) {
  return dir / ("collider_" + std::to_string(index) + extension);
}

namespace {

// The N of a file named collider_<N><extension> as collider_path() writes it (no sign, no leading zero).
std::optional<std::size_t> collider_index_of(const std::string& name, const std::string& extension) {
  const std::string prefix = "collider_";
  if (name.compare(0, prefix.size(), prefix) != 0) return std::nullopt;
  std::size_t end = prefix.size();
  while (end < name.size() && end - prefix.size() < 9 && name[end] >= '0' && name[end] <= '9') ++end;
  if (end == prefix.size()) return std::nullopt;
  const std::size_t index = std::stoul(name.substr(prefix.size(), end - prefix.size()));
  if (collider_path({}, index, extension).string() != name) return std::nullopt;
  return index;
}

}  // namespace

int remove_collider_files(const std::filesystem::path& dir, std::span<const std::string> extensions,
                          const std::vector<InputFile>& inputs) {
  std::error_code ec;
  std::vector<std::filesystem::path> earlier;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    const bool ours = std::any_of(extensions.begin(), extensions.end(), [&](const std::string& extension) {
      return collider_index_of(name, extension).has_value();
    });
    if (ours && entry.is_regular_file(ec) && !is_input(entry.path(), inputs)) earlier.push_back(entry.path());
  }
  int removed = 0;
  for (const std::filesystem::path& file : earlier) removed += std::filesystem::remove(file, ec) ? 1 : 0;
  return removed;
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
