// Tessellating the collider shapes.
#include "frames/collider_tessellation.hpp"

#include <cmath>
#include <numbers>

#include "sim/contact/collider_mesh.hpp"

namespace frames {
namespace {

using softbody::Vec3;

constexpr int kAround = 48;  // segments around a sphere's or capsule's axis
constexpr int kRings = 24;   // rings from pole to pole (a capsule: split at the equator, the cylinder between)

// Appends a vertex at local point q with local normal n, placed by the collider's pose.
void add_vertex(ColliderTriangles& s, const sim::ColliderGeometry& g, const Vec3& q, const Vec3& n) {
  s.positions.push_back(g.position_m + g.rotation * q);
  s.normals.push_back(g.rotation * n);
}

int next_index(const ColliderTriangles& s) { return static_cast<int>(s.positions.size()); }

// Six faces of four vertices each (flat normals), two triangles a face, counter-clockwise seen from outside.
void add_box(ColliderTriangles& s, const sim::ColliderGeometry& g) {
  const Vec3& b = g.half_size_m;
  for (int axis = 0; axis < 3; ++axis) {
    for (const double side : {-1.0, 1.0}) {
      Vec3 n = Vec3::Zero();
      n[axis] = side;
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      const int first = next_index(s);
      for (const auto& [su, sv] : {std::pair{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}}) {
        Vec3 q = n.cwiseProduct(b);
        q[u] = su * b[u];
        q[v] = sv * b[v];
        add_vertex(s, g, q, n);
      }
      // (u, v, axis) is right-handed, so u → v turns counter-clockwise seen from +axis.
      if (side > 0.0) {
        s.triangles.push_back({first, first + 1, first + 2});
        s.triangles.push_back({first, first + 2, first + 3});
      } else {
        s.triangles.push_back({first, first + 2, first + 1});
        s.triangles.push_back({first, first + 3, first + 2});
      }
    }
  }
}

// A sphere of radius r about the local y axis, its two hemispheres pulled apart by ±half_length (a capsule; 0: a
// sphere), as rings of kAround vertices with smooth normals.
void add_round(ColliderTriangles& s, const sim::ColliderGeometry& g, double radius, double half_length) {
  const int first = next_index(s);
  int rings = 0;
  for (int ring = 0; ring <= kRings; ++ring) {
    const double polar = std::numbers::pi * ring / kRings;  // from +y
    const double y = std::cos(polar), across = std::sin(polar);
    // The equator ring is doubled on a capsule: once for each hemisphere, the cylinder between them.
    const int copies = (half_length > 0.0 && 2 * ring == kRings) ? 2 : 1;
    for (int copy = 0; copy < copies; ++copy) {
      const double shift = (2 * ring < kRings || (2 * ring == kRings && copy == 0)) ? half_length : -half_length;
      for (int k = 0; k < kAround; ++k) {
        const double azimuth = 2.0 * std::numbers::pi * k / kAround;
        const Vec3 n(across * std::cos(azimuth), y, across * std::sin(azimuth));
        add_vertex(s, g, radius * n + Vec3(0.0, shift, 0.0), n);
      }
      ++rings;
    }
  }
  for (int ring = 0; ring + 1 < rings; ++ring) {
    for (int k = 0; k < kAround; ++k) {
      const int a = first + ring * kAround + k;
      const int b = first + ring * kAround + (k + 1) % kAround;
      const int c = a + kAround, d = b + kAround;  // the next ring down
      s.triangles.push_back({a, b, c});
      s.triangles.push_back({b, d, c});
    }
  }
}

// Each triangle of a mesh with its own three corners and its face's normal: the flat shading of a hard-edged mesh.
void add_flat_mesh(ColliderTriangles& s, const sim::ColliderGeometry& g) {
  const sim::ColliderMesh& m = *g.mesh;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const int first = next_index(s);
    for (int corner : m.triangles[t])
      add_vertex(s, g, m.vertices_m[static_cast<std::size_t>(corner)], m.face_normals[t]);
    s.triangles.push_back({first, first + 1, first + 2});
  }
}

}  // namespace

ColliderTriangles bounded_collider_triangles(const sim::ColliderGeometry& g) {
  ColliderTriangles s;
  switch (g.shape) {
    case sim::ColliderShape::Plane: break;
    case sim::ColliderShape::Box: add_box(s, g); break;
    case sim::ColliderShape::Sphere: add_round(s, g, g.radius_m, 0.0); break;
    case sim::ColliderShape::Capsule: add_round(s, g, g.radius_m, g.half_length_m); break;
    case sim::ColliderShape::Mesh: add_flat_mesh(s, g); break;
  }
  return s;
}

ColliderTriangles plane_square(const sim::ColliderGeometry& plane, const Vec3& near, double half_size_m) {
  const sim::SurfacePoint centre = sim::nearest_surface(plane, near);
  const Vec3 n = centre.normal;
  // Two directions along the plane: any vector not parallel to n, crossed with it.
  const Vec3 helper = std::abs(n.y()) < 0.9 ? Vec3::UnitY() : Vec3::UnitX();
  const Vec3 u = n.cross(helper).normalized(), v = n.cross(u);
  ColliderTriangles s;
  for (const auto& [su, sv] : {std::pair{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}}) {
    s.positions.push_back(centre.closest_m + half_size_m * (su * u + sv * v));
    s.normals.push_back(n);
  }
  // (u, v, n) is right-handed (v = n × u), so u → v turns counter-clockwise seen from the normal's side.
  s.triangles = {{0, 1, 2}, {0, 2, 3}};
  return s;
}

ColliderTriangles placed_mesh(const sim::ColliderGeometry& g) {
  ColliderTriangles s;
  const sim::ColliderMesh& m = *g.mesh;
  s.positions.reserve(m.vertices_m.size());
  for (const Vec3& p : m.vertices_m) s.positions.push_back(g.position_m + g.rotation * p);
  s.triangles = m.triangles;
  return s;
}

}  // namespace frames
