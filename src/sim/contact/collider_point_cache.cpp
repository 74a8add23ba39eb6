// A point-cached mesh collider's pose, surface velocity and the continuous check's carried start.
#include "sim/contact/collider_point_cache.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sim/contact/collider_mesh.hpp"

namespace sim {
namespace {

constexpr std::size_t kMemoPoses = 4;  // a step's start and end and an integrator's stage times

// The pose at t: linear between the samples around it (each vertex at constant velocity), held outside them.
std::shared_ptr<const ColliderMesh> pose_at_time(const ColliderPointCache& cache, double time_s) {
  const std::vector<double>& times = cache.times_s;
  const std::size_t vertices = cache.rest->vertices_m.size();
  std::vector<Vec3> velocities(vertices, Vec3::Zero());
  if (time_s <= times.front()) return refit_collider_mesh(*cache.rest, cache.samples_m.front(), velocities);
  if (time_s >= times.back()) return refit_collider_mesh(*cache.rest, cache.samples_m.back(), velocities);
  const auto after = std::upper_bound(times.begin(), times.end(), time_s);
  const auto i = static_cast<std::size_t>(after - times.begin()) - 1;
  const double span = times[i + 1] - times[i], u = (time_s - times[i]) / span;
  const std::vector<Vec3>&a = cache.samples_m[i], &b = cache.samples_m[i + 1];
  std::vector<Vec3> positions(vertices);
  for (std::size_t v = 0; v < vertices; ++v) {
    positions[v] = a[v] + u * (b[v] - a[v]);  // x(t) = x_i + (t − t_i)/(t_{i+1} − t_i) (x_{i+1} − x_i)
    velocities[v] = (b[v] - a[v]) / span;     // dx/dt on the segment [m/s]
  }
  return refit_collider_mesh(*cache.rest, std::move(positions), std::move(velocities));
}

}  // namespace

std::shared_ptr<const ColliderPointCache> make_collider_point_cache(std::shared_ptr<const ColliderMesh> rest,
                                                                    std::vector<double> times_s,
                                                                    std::vector<std::vector<Vec3>> samples_m) {
  if (times_s.empty() || times_s.size() != samples_m.size())
    throw std::invalid_argument("a point cache needs one time per sample, and at least one sample");
  auto cache = std::make_shared<ColliderPointCache>();
  for (std::size_t s = 0; s < samples_m.size(); ++s) {
    if (samples_m[s].size() != rest->vertices_m.size()) {
      throw std::invalid_argument("sample " + std::to_string(s) + " holds " + std::to_string(samples_m[s].size()) +
                                  " positions, the mesh has " + std::to_string(rest->vertices_m.size()) + " vertices");
    }
    if (s > 0 && !(times_s[s] > times_s[s - 1])) throw std::invalid_argument("the samples' times must increase");
  }
  for (std::size_t s = 0; s + 1 < samples_m.size(); ++s) {
    const double span = times_s[s + 1] - times_s[s];
    for (std::size_t v = 0; v < samples_m[s].size(); ++v) {
      const double speed = (samples_m[s + 1][v] - samples_m[s][v]).norm() / span;
      cache->fastest_vertex_speed_m_per_s = std::max(cache->fastest_vertex_speed_m_per_s, speed);
    }
  }
  cache->rest = refit_collider_mesh(*rest, samples_m.front(), std::vector<Vec3>(rest->vertices_m.size()));
  cache->times_s = std::move(times_s);
  cache->samples_m = std::move(samples_m);
  return cache;
}

std::shared_ptr<const ColliderMesh> mesh_at(const ColliderPointCache& cache, double time_s) {
  {
    const std::lock_guard<std::mutex> lock(cache.memo_guard);
    for (const auto& [time, mesh] : cache.memo) {
      if (time == time_s) return mesh;
    }
  }
  std::shared_ptr<const ColliderMesh> mesh = pose_at_time(cache, time_s);
  const std::lock_guard<std::mutex> lock(cache.memo_guard);
  if (cache.memo.size() >= kMemoPoses) cache.memo.erase(cache.memo.begin());
  cache.memo.emplace_back(time_s, mesh);
  return mesh;
}

Vec3 cached_surface_velocity(const ColliderGeometry& g, const Vec3& x) {
  const ColliderMesh& m = *g.mesh;
  const MeshPoint point = mesh_nearest_point_local(m, g.rotation.transpose() * (x - g.position_m));
  return g.rotation * at_mesh_point(m, point, m.vertex_velocities);
}

double largest_vertex_travel(const ColliderGeometry& from, const ColliderGeometry& to) {
  if (!from.velocity.per_vertex || !to.velocity.per_vertex) return 0.0;
  double farthest2 = 0.0;  // the placement is the same in both poses: local displacements are world ones, turned
  for (std::size_t v = 0; v < to.mesh->vertices_m.size(); ++v)
    farthest2 = std::max(farthest2, (to.mesh->vertices_m[v] - from.mesh->vertices_m[v]).squaredNorm());
  return std::sqrt(farthest2);
}

Vec3 carried_with_cached_mesh(const ColliderGeometry& from, const ColliderGeometry& to, const Vec3& x) {
  const MeshPoint point = mesh_nearest_point_local(*from.mesh, from.rotation.transpose() * (x - from.position_m));
  const Vec3 travel = mesh_point_position(*to.mesh, point) - mesh_point_position(*from.mesh, point);  // local
  return x + to.rotation * travel;
}

}  // namespace sim
