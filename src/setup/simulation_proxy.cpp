// Remeshing a body's mesh into its simulation proxy.
#include "setup/simulation_proxy.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "core/errors.hpp"
#include "geometry/remesh.hpp"
#include "mesh/check.hpp"

namespace setup {
namespace {

constexpr double kMostProxyVertices = 1e6;  // as "resolution": N allows

mesh::TriMesh remesh_for(const mesh::TriMesh& detailed, const scene::Body& spec, const std::string& key) {
  if (spec.resolution_vertices > 0) return geometry::remesh_to_vertex_count(detailed, spec.resolution_vertices);
  const double edge = spec.resolution_edge_length_m / spec.scale;  // mesh units
  // V ≈ 2A / (√3 L²): V vertices of equilateral triangles of side L tile area A (2V triangles).
  const double expected_vertices = 2.0 * mesh::surface_area(detailed) / (std::sqrt(3.0) * edge * edge);
  if (!(expected_vertices <= kMostProxyVertices)) {
    char text[256];
    std::snprintf(text, sizeof text,
                  "%s.edge_length: expected an edge length giving at most %.0f vertices, got %g m "
                  "(about %.3g vertices on this surface)",
                  key.c_str(), kMostProxyVertices, spec.resolution_edge_length_m, expected_vertices);
    throw softbody::InputError(text);
  }
  return geometry::remesh_to_edge_length(detailed, edge);
}

}  // namespace

bool wants_proxy(const scene::Body& spec) {
  return spec.resolution_vertices > 0 || spec.resolution_edge_length_m > 0.0;
}

mesh::TriMesh simulation_proxy(const mesh::TriMesh& detailed, const scene::Body& spec, const std::string& key_path,
                               std::vector<std::string>& notes) {
  const std::string key = key_path + ".resolution";
  mesh::TriMesh proxy;
  try {
    proxy = remesh_for(detailed, spec, key);
  } catch (const std::invalid_argument& e) {
    throw softbody::InputError(key + ": expected a closed surface to remesh: " + e.what());
  } catch (const std::logic_error& e) {
    throw softbody::InputError(key + ": the isotropic remesh failed: " + e.what());
  }
  std::vector<std::string> proxy_notes;
  try {
    mesh::validate_closed(proxy, proxy_notes);
  } catch (const softbody::InputError& e) {
    throw softbody::InputError(key + ": the remeshed proxy is not a valid closed surface: " + e.what());
  }
  const double volume_change = mesh::signed_volume(proxy) / mesh::signed_volume(detailed) - 1.0;
  char text[320];
  std::snprintf(text, sizeof text,
                "%s: simulated on an isotropic remesh of %zu vertices and %zu triangles (volume %+.2f %%); "
                "the mesh's %zu vertices follow it for render and export",
                key.c_str(), proxy.vertices.size(), proxy.triangles.size(), 100.0 * volume_change,
                detailed.vertices.size());
  notes.push_back(text);
  return proxy;
}

}  // namespace setup
