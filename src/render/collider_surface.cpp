// Tessellating the collider shapes for drawing.
#include "render/collider_surface.hpp"

#include <cmath>
#include <numbers>

namespace render {
namespace {

constexpr int kAround = 48;  // segments around a sphere's or capsule's axis
constexpr int kRings = 24;   // rings from pole to pole (a capsule: split at the equator, the cylinder between)

glm::vec3 to_glm(const softbody::Vec3& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}

// Appends a vertex at local point q with local normal n, placed by the collider's pose.
void add_vertex(ColliderSurface& s, const sim::ColliderGeometry& g, const softbody::Vec3& q, const softbody::Vec3& n) {
  s.positions.push_back(to_glm(g.position_m + g.rotation * q));
  s.normals.push_back(to_glm(g.rotation * n));
}

// Six faces of four vertices each (flat normals), two triangles a face, counter-clockwise seen from outside.
void add_box(ColliderSurface& s, const sim::ColliderGeometry& g) {
  const softbody::Vec3& b = g.half_size_m;
  for (int axis = 0; axis < 3; ++axis) {
    for (const double side : {-1.0, 1.0}) {
      softbody::Vec3 n = softbody::Vec3::Zero();
      n[axis] = side;
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      const auto first = static_cast<unsigned>(s.positions.size());
      for (const auto& [su, sv] : {std::pair{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}}) {
        softbody::Vec3 q = n.cwiseProduct(b);
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
void add_round(ColliderSurface& s, const sim::ColliderGeometry& g, double radius, double half_length) {
  const auto first = static_cast<unsigned>(s.positions.size());
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
        const softbody::Vec3 n(across * std::cos(azimuth), y, across * std::sin(azimuth));
        add_vertex(s, g, radius * n + softbody::Vec3(0.0, shift, 0.0), n);
      }
      ++rings;
    }
  }
  for (int ring = 0; ring + 1 < rings; ++ring) {
    for (int k = 0; k < kAround; ++k) {
      const unsigned a = first + static_cast<unsigned>(ring * kAround + k);
      const unsigned b = first + static_cast<unsigned>(ring * kAround + (k + 1) % kAround);
      const unsigned c = a + kAround, d = b + kAround;  // the next ring down
      s.triangles.push_back({a, b, c});
      s.triangles.push_back({b, d, c});
    }
  }
}

}  // namespace

ColliderSurface bounded_collider_surface(const sim::ColliderGeometry& g) {
  ColliderSurface s;
  switch (g.shape) {
    case sim::ColliderShape::Plane: break;
    case sim::ColliderShape::Box: add_box(s, g); break;
    case sim::ColliderShape::Sphere: add_round(s, g, g.radius_m, 0.0); break;
    case sim::ColliderShape::Capsule: add_round(s, g, g.radius_m, g.half_length_m); break;
  }
  return s;
}

ColliderSurface plane_square(const sim::ColliderGeometry& plane, const glm::vec3& near, float half_size_m) {
  const softbody::Vec3 near_d(near.x, near.y, near.z);
  const sim::SurfacePoint centre = sim::nearest_surface(plane, near_d);
  const softbody::Vec3 n = centre.normal;
  // Two directions along the plane: any vector not parallel to n, crossed with it.
  const softbody::Vec3 helper = std::abs(n.y()) < 0.9 ? softbody::Vec3::UnitY() : softbody::Vec3::UnitX();
  const softbody::Vec3 u = n.cross(helper).normalized(), v = n.cross(u);
  ColliderSurface s;
  for (const auto& [su, sv] : {std::pair{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}}) {
    s.positions.push_back(to_glm(centre.closest_m + half_size_m * (su * u + sv * v)));
    s.normals.push_back(to_glm(n));
  }
  // (u, v, n) is right-handed (v = n × u), so u → v turns counter-clockwise seen from the normal's side.
  s.triangles = {{0, 1, 2}, {0, 2, 3}};
  return s;
}

}  // namespace render
