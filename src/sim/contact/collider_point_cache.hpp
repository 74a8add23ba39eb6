// A mesh collider moved by a point cache (a PC2 file, or a numbered mesh sequence): its vertices' positions at
// given times, linear in time between them, so that each vertex moves at a constant velocity from one sample to the
// next. Each pose is the rest mesh refitted (sim/contact/collider_mesh.hpp: the same triangles and tree, the boxes and
// normals recomputed); the surface velocity at a point is its triangle's corners' velocities, weighted by the
// point's barycentric coordinates. Before the first sample and after the last, the mesh holds that sample's pose,
// at rest.
#pragma once

#include <memory>
#include <mutex>
#include <vector>

#include "sim/contact/collider_shape.hpp"

namespace sim {

struct ColliderPointCache {
  std::shared_ptr<const ColliderMesh> rest;   // the triangles and the tree (the first sample's pose)
  std::vector<double> times_s;                // increasing, one per sample
  std::vector<std::vector<Vec3>> samples_m;   // per sample, each vertex of `rest` (local, scaled) [m]
  double fastest_vertex_speed_m_per_s = 0.0;  // the largest |Δx| / Δt of any vertex between samples [m/s]
  // The last poses made (a pose is asked for at the same time by every body and phase of a step): the time and
  // the mesh. Guarded, so that threads may ask at once; what it returns depends only on the time.
  mutable std::mutex memo_guard;
  mutable std::vector<std::pair<double, std::shared_ptr<const ColliderMesh>>> memo;
};

// The cache of `rest`'s vertices at `times_s` (increasing, at least one). Throws std::invalid_argument when a
// sample does not hold one position per vertex of `rest` or the times do not increase.
std::shared_ptr<const ColliderPointCache> make_collider_point_cache(std::shared_ptr<const ColliderMesh> rest,
                                                                    std::vector<double> times_s,
                                                                    std::vector<std::vector<Vec3>> samples_m);

// The mesh at time t, with its vertices' velocities.
std::shared_ptr<const ColliderMesh> mesh_at(const ColliderPointCache& cache, double time_s);

// The time of the first sample [s].
inline double cache_start_s(const ColliderPointCache& cache) { return cache.times_s.front(); }

// The velocity of the cached mesh's surface nearest x [m/s] (world), for surface_velocity().
Vec3 cached_surface_velocity(const ColliderGeometry& geometry, const Vec3& x);

// The farthest any vertex of a cached mesh moves from pose `from` to pose `to` [m] (0 for any other collider).
double largest_vertex_travel(const ColliderGeometry& from, const ColliderGeometry& to);

// x carried from pose `from` to pose `to` of a cached mesh with the nearest surface point's motion: x + (p_to −
// p_from), p the point of the same triangle at the same barycentric weights (sim/contact/collider_sweep.hpp).
Vec3 carried_with_cached_mesh(const ColliderGeometry& from, const ColliderGeometry& to, const Vec3& x);

}  // namespace sim
