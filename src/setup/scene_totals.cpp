// Scene-wide totals of vertices and triangles, known before the meshes are built where they can be.
#include "setup/scene_totals.hpp"

#include "core/errors.hpp"

namespace setup {
namespace {

// The integer arguments after the colon of a valid generator spec ("torus:48,16": 48, 16).
std::vector<long long> arguments_of(const std::string& spec) {
  std::vector<long long> arguments;
  const std::string text = spec.substr(spec.find(':') + 1) + ",";
  for (std::size_t start = 0, comma; (comma = text.find(',', start)) != std::string::npos; start = comma + 1) {
    arguments.push_back(std::stoll(text.substr(start, comma - start)));
  }
  return arguments;
}

MeshSize sum(const std::vector<MeshSize>& sizes) {
  MeshSize total;
  for (const MeshSize& size : sizes) {
    total.vertices += size.vertices;
    total.triangles += size.triangles;
  }
  return total;
}

// A closed surface of genus 0 with T triangles has V = T/2 + 2 vertices (Euler: V − E + F = 2, E = 3F/2).
MeshSize sphere_like(long long triangles) { return {triangles / 2 + 2, triangles}; }

}  // namespace

MeshSize generator_size(const std::string& spec) {
  const std::string name = spec.substr(0, spec.find(':'));
  const std::vector<long long> a = arguments_of(spec);
  if (name == "icosphere") return sphere_like(20LL << (2 * a[0]));  // 20 faces, each split in 4 per level
  if (name == "cube") return sphere_like(12 * a[0] * a[0]);         // 6 faces of N × N quads
  if (name == "torus") return {a[0] * a[1], 2 * a[0] * a[1]};       // genus 1: V = T/2
  if (name == "capsule") {
    const long long rings = 2 * std::max(2LL, a[0] / 4);  // mesh/generators.cpp: latitude steps per hemisphere
    return sphere_like(2 * a[0] * rings);                 // N triangles per cap and 2N per band between rings
  }
  return {};
}

SceneTotals::SceneTotals(const scene::Scene& scene) : scene_(scene) {
  for (const scene::Body& body : scene.bodies) {
    MeshSize known = body.mesh_file.empty() ? generator_size(body.mesh) : MeshSize{};
    known.vertices += body.resolution_vertices;       // a proxy of about N vertices
    known.triangles += 2 * body.resolution_vertices;  // and twice as many triangles
    bodies_.push_back(known);
  }
  for (const scene::ColliderMeshSource& collider : scene.collider_meshes)
    colliders_.push_back(collider.mesh_file.empty() ? generator_size(collider.mesh) : MeshSize{});
}

void SceneTotals::count(std::size_t index, MeshSize size) { bodies_.at(index) = size; }

void SceneTotals::count_collider(std::size_t source, MeshSize size) { colliders_.at(source) = size; }

void SceneTotals::check() const {
  const MeshSize bodies = sum(bodies_), colliders = sum(colliders_);
  // "the scene's bodies hold 1280 triangles (meshes and simulation proxies)", with the collider meshes' share and the
  // largest of them where they hold any.
  const auto held = [&](const char* what, long long MeshSize::*count) {
    const long long total = bodies.*count + colliders.*count;
    if (colliders.*count == 0)
      return "the scene's bodies hold " + std::to_string(total) + " " + what + " (meshes and simulation proxies)";
    std::size_t largest = 0;
    for (std::size_t c = 1; c < colliders_.size(); ++c) {
      if (colliders_[c].*count > colliders_[largest].*count) largest = c;
    }
    return "the scene's bodies and collider meshes hold " + std::to_string(total) + " " + what + " (bodies " +
           std::to_string(bodies.*count) + ", collider meshes " + std::to_string(colliders.*count) +
           ", the largest colliders." + std::to_string(scene_.collider_meshes.at(largest).collider) + ".mesh with " +
           std::to_string(colliders_[largest].*count) + ")";
  };
  const auto refuse = [&](const char* what, long long MeshSize::*count, long long limit, const char* key) {
    throw softbody::InputError(scene_.source.string() + ": limits." + key + ": " + held(what, count) +
                               ", more than the limit of " + std::to_string(limit) +
                               ": expected fewer or smaller bodies or collider meshes, or a larger limits." + key);
  };
  if (bodies.vertices + colliders.vertices > scene_.totals.max_vertices)
    refuse("vertices", &MeshSize::vertices, scene_.totals.max_vertices, "max_total_vertices");
  if (bodies.triangles + colliders.triangles > scene_.totals.max_triangles)
    refuse("triangles", &MeshSize::triangles, scene_.totals.max_triangles, "max_total_triangles");
}

}  // namespace setup
