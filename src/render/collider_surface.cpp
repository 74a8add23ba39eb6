// The collider tessellation in the renderer's vectors.
#include "render/collider_surface.hpp"

#include "frames/collider_tessellation.hpp"

namespace render {
namespace {

glm::vec3 to_glm(const softbody::Vec3& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}

ColliderSurface to_surface(const frames::ColliderTriangles& t) {
  ColliderSurface s;
  s.positions.reserve(t.positions.size());
  for (const softbody::Vec3& p : t.positions) s.positions.push_back(to_glm(p));
  s.normals.reserve(t.normals.size());
  for (const softbody::Vec3& n : t.normals) s.normals.push_back(to_glm(n));
  s.triangles.reserve(t.triangles.size());
  for (const softbody::Triangle& f : t.triangles) {
    s.triangles.push_back({static_cast<unsigned>(f[0]), static_cast<unsigned>(f[1]), static_cast<unsigned>(f[2])});
  }
  return s;
}

}  // namespace

ColliderSurface bounded_collider_surface(const sim::ColliderGeometry& g) {
  return to_surface(frames::bounded_collider_triangles(g));
}

ColliderSurface plane_square(const sim::ColliderGeometry& plane, const glm::vec3& near, float half_size_m) {
  return to_surface(frames::plane_square(plane, softbody::Vec3(near.x, near.y, near.z), half_size_m));
}

}  // namespace render
