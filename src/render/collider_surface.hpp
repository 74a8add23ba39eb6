// A collider as triangles the renderer draws: the shared tessellation (frames/collider_tessellation.hpp) in the
// renderer's single-precision vectors.
#pragma once

#include <vector>

#include <glm/vec3.hpp>

#include "render/frame_mesh.hpp"
#include "sim/contact/collider_shape.hpp"

namespace render {

struct ColliderSurface {
  std::vector<glm::vec3> positions;  // m, world
  std::vector<glm::vec3> normals;    // unit, outward
  std::vector<glm::uvec3> triangles;
};

// The surface of a bounded collider (box, sphere, capsule, mesh); a plane has none here (plane_square).
ColliderSurface bounded_collider_surface(const sim::ColliderGeometry& geometry);

// A square of side 2 half_size_m on the plane, centred at the point of the plane nearest `near`.
ColliderSurface plane_square(const sim::ColliderGeometry& plane, const glm::vec3& near, float half_size_m);

}  // namespace render
