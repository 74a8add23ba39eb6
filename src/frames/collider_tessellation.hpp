// The colliders as triangles in world coordinates, which both the renderer (render/collider_surface.hpp) and the
// exporter (output/collider_export.hpp) take: a box's faces, a sphere's and a capsule's tessellation with smooth
// normals, a mesh's own triangles with flat ones, and a plane as a square around a point of it.
#pragma once

#include <vector>

#include "core/vec.hpp"
#include "sim/contact/collider_shape.hpp"

namespace frames {

struct ColliderTriangles {
  std::vector<softbody::Vec3> positions;      // m, world
  std::vector<softbody::Vec3> normals;        // unit, outward (a mesh: its face's, each triangle with its own corners)
  std::vector<softbody::Triangle> triangles;  // counter-clockwise seen from outside
};

// The surface of a bounded collider (box, sphere, capsule, mesh); a plane has none here (plane_square).
ColliderTriangles bounded_collider_triangles(const sim::ColliderGeometry& geometry);

// A square of side 2 half_size_m on the plane, centred at the point of the plane nearest `near`.
ColliderTriangles plane_square(const sim::ColliderGeometry& plane, const softbody::Vec3& near, double half_size_m);

// A mesh collider's own vertices (placed in the world) and triangles, shared between triangles as in its file.
ColliderTriangles placed_mesh(const sim::ColliderGeometry& mesh);

}  // namespace frames
