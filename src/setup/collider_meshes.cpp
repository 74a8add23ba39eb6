// Reading the mesh colliders' files.
#include "setup/collider_meshes.hpp"

#include <cstdio>
#include <stdexcept>

#include "core/errors.hpp"
#include "core/one_line.hpp"
#include "mesh/generators.hpp"
#include "mesh/import.hpp"
#include "mesh/weld.hpp"
#include "setup/collider_point_caches.hpp"
#include "sim/contact/collider_mesh.hpp"

namespace setup {
namespace {

// The mesh as written (a generator, or a file read within the limits and welded), scaled.
mesh::TriMesh read_scaled(const scene::ColliderMeshSource& source, const mesh::MeshLimits& limits) {
  mesh::TriMesh m = source.mesh_file.empty() ? mesh::generate(source.mesh)
                                             : mesh::weld(mesh::import_mesh_file(source.mesh_file, limits));
  for (softbody::Vec3& p : m.vertices) p *= source.scale;
  return m;
}

}  // namespace

void load_collider_meshes(const scene::Scene& scene, std::vector<sim::Collider>& colliders,
                          std::vector<std::string>& notes, SceneTotals& totals) {
  for (std::size_t s = 0; s < scene.collider_meshes.size(); ++s) {
    const scene::ColliderMeshSource& source = scene.collider_meshes[s];
    const std::string key = scene.source.string() + ": colliders." + std::to_string(source.collider) + ".mesh";
    const std::string what = softbody::one_line(source.mesh_file.empty() ? source.mesh : source.mesh_file.string());
    sim::ColliderGeometry& geometry = colliders.at(source.collider).geometry;
    if (!source.cache_file.empty()) {
      load_collider_point_cache(scene, source, colliders.at(source.collider));
      totals.count_collider(s, {static_cast<long long>(geometry.mesh->vertices_m.size()),
                                static_cast<long long>(geometry.mesh->triangles.size())});
      totals.check();
    } else {
      mesh::TriMesh m;
      try {
        m = read_scaled(source, scene.limits);
      } catch (const softbody::InputError& e) {
        throw softbody::InputError(key + ": mesh " + what + " " + e.what());
      }
      totals.count_collider(s, {static_cast<long long>(m.vertices.size()), static_cast<long long>(m.triangles.size())});
      totals.check();  // as each mesh file is read
      try {
        geometry.mesh = sim::make_collider_mesh(std::move(m.vertices), std::move(m.triangles), source.thickness_m);
      } catch (const std::invalid_argument& e) {
        throw softbody::InputError(key + ": mesh " + what + ": " + e.what() + " (expected a triangle mesh)");
      }
      geometry.world_reach_m = sim::world_reach(geometry);
    }
    if (!geometry.mesh->closed) {
      const std::string why = geometry.mesh->boundary_edges > 0
                                  ? "open (" + std::to_string(geometry.mesh->boundary_edges) + " edges of one triangle)"
                                  : "not a closed solid (edges of three triangles, mis-wound edges or no volume)";
      char sheet[64];
      std::snprintf(sheet, sizeof sheet, ": a two-sided sheet %.3g m thick", 2.0 * geometry.mesh->half_thickness_m);
      notes.push_back(key + ": " + what + ": " + why + sheet);
    }
  }
}

}  // namespace setup
