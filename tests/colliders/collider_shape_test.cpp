// The collider shapes' signed distance, outward normal and closest point against analytic values, the normal
// against the distance's gradient, and the rotation convention (X, then Y, then Z about the world's axes).
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "core/euler_rotation.hpp"
#include "sim/contact/collider_shape.hpp"

namespace {

using sim::ColliderGeometry;
using sim::ColliderShape;
using sim::nearest_surface;
using sim::SurfacePoint;
using softbody::Vec3;

constexpr double kTight = 1e-12;  // round-off of a few operations on numbers of order 1

void expect_near(const Vec3& actual, const Vec3& expected, double tolerance = kTight) {
  EXPECT_LT((actual - expected).norm(), tolerance)
      << "actual " << actual.transpose() << ", expected " << expected.transpose();
}

ColliderGeometry shape(ColliderShape kind, const Vec3& position = Vec3::Zero(),
                       const Vec3& rotation_deg = Vec3::Zero()) {
  ColliderGeometry g;
  g.shape = kind;
  g.position_m = position;
  g.rotation = softbody::rotation_xyz_degrees(rotation_deg);
  return g;
}

// A shape of `kind` off the origin, turned about all three axes, with sides, radius and length all different.
ColliderGeometry posed_shape(ColliderShape kind) {
  ColliderGeometry g = shape(kind, Vec3(0.1, 0.2, -0.3), Vec3(10, 20, 30));
  g.half_size_m = Vec3(0.5, 0.7, 0.9);
  g.radius_m = 0.6;
  g.half_length_m = 0.4;
  return g;
}

TEST(EulerRotation, AppliesXThenYThenZAboutTheWorldAxes) {
  // R = R_z R_y R_x: [90, 90, 0] takes y to z (about X), then z to x (about Y). The other order, R_x R_y, would leave
  // y at y and then take it to z.
  const softbody::Mat3 r = softbody::rotation_xyz_degrees(Vec3(90, 90, 0));
  expect_near(r * Vec3::UnitY(), Vec3::UnitX());
  expect_near(r * Vec3::UnitX(), -Vec3::UnitZ());
  // [0, 0, 90] takes x to y (a right-handed turn about Z); [0, 0, 0] is the identity exactly.
  expect_near(softbody::rotation_xyz_degrees(Vec3(0, 0, 90)) * Vec3::UnitX(), Vec3::UnitY());
  EXPECT_EQ(softbody::rotation_xyz_degrees(Vec3::Zero()), softbody::Mat3::Identity());
  // Blender's XYZ Euler (30°, 45°, 60°) = R_z(60) R_y(45) R_x(30), composed from single-axis matrices here.
  const double a = std::numbers::pi / 6, b = std::numbers::pi / 4, c = std::numbers::pi / 3;
  softbody::Mat3 rx, ry, rz;
  rx << 1, 0, 0, 0, std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a);
  ry << std::cos(b), 0, std::sin(b), 0, 1, 0, -std::sin(b), 0, std::cos(b);
  rz << std::cos(c), -std::sin(c), 0, std::sin(c), std::cos(c), 0, 0, 0, 1;
  EXPECT_LT((softbody::rotation_xyz_degrees(Vec3(30, 45, 60)) - rz * ry * rx).norm(), kTight);
}

TEST(ColliderShape, TiltedPlaneThroughItsPosition) {
  ColliderGeometry g = shape(ColliderShape::Plane, Vec3(1, 2, 3), Vec3(0, 0, 30));  // normal (−sin 30°, cos 30°, 0)
  const Vec3 n(-0.5, std::sqrt(3.0) / 2, 0);
  const Vec3 x = Vec3(1, 2, 3) + 0.7 * n + Vec3(0, 0, 5);  // 0.7 m above, 5 m along the plane
  const SurfacePoint s = nearest_surface(g, x);
  EXPECT_NEAR(s.distance_m, 0.7, kTight);
  expect_near(s.normal, n);
  expect_near(s.closest_m, Vec3(1, 2, 8));
  EXPECT_NEAR(nearest_surface(g, Vec3(1, 2, 3) - 0.2 * n).distance_m, -0.2, kTight);
}

TEST(ColliderShape, SphereOutsideInsideAndAtItsCentre) {
  ColliderGeometry g = shape(ColliderShape::Sphere, Vec3(0, 1, 0));
  g.radius_m = 0.5;
  SurfacePoint s = nearest_surface(g, Vec3(3, 1, 4));  // 5 m from the centre
  EXPECT_NEAR(s.distance_m, 4.5, kTight);
  expect_near(s.normal, Vec3(0.6, 0, 0.8));
  expect_near(s.closest_m, Vec3(0.3, 1, 0.4));
  EXPECT_NEAR(nearest_surface(g, Vec3(0, 1.2, 0)).distance_m, -0.3, kTight);
  s = nearest_surface(g, Vec3(0, 1, 0));
  EXPECT_NEAR(s.distance_m, -0.5, kTight);
  expect_near(s.normal, Vec3::UnitY());  // the fixed choice at the centre
}

TEST(ColliderShape, BoxFacesEdgesCornersAndInside) {
  ColliderGeometry g = shape(ColliderShape::Box);
  g.half_size_m = Vec3(1, 0.5, 2);
  SurfacePoint s = nearest_surface(g, Vec3(0.2, 1.5, 0.3));  // above the top face
  EXPECT_NEAR(s.distance_m, 1.0, kTight);
  expect_near(s.normal, Vec3::UnitY());
  expect_near(s.closest_m, Vec3(0.2, 0.5, 0.3));
  s = nearest_surface(g, Vec3(2, 1.5, 0));  // beyond the edge x = 1, y = 0.5
  EXPECT_NEAR(s.distance_m, std::sqrt(2.0), kTight);
  expect_near(s.normal, Vec3(1, 1, 0).normalized());
  s = nearest_surface(g, Vec3(2, 1.5, 4));  // beyond the corner
  EXPECT_NEAR(s.distance_m, std::sqrt(1.0 + 1.0 + 4.0), kTight);
  s = nearest_surface(g, Vec3(0.1, -0.3, 1.9));  // inside: 0.1 from the face z = 2, 0.2 from y = −0.5
  EXPECT_NEAR(s.distance_m, -0.1, kTight);
  expect_near(s.normal, Vec3::UnitZ());
  expect_near(s.closest_m, Vec3(0.1, -0.3, 2.0));
}

TEST(ColliderShape, RotatedBoxUsesItsOwnAxes) {
  ColliderGeometry g = shape(ColliderShape::Box, Vec3(0, 1, 0), Vec3(0, 0, 45));
  g.half_size_m = Vec3(1, 0.1, 1);
  const Vec3 up(-std::sqrt(0.5), std::sqrt(0.5), 0);  // the top face's normal, turned 45° about z
  const SurfacePoint s = nearest_surface(g, Vec3(0, 1, 0) + 0.6 * up);
  EXPECT_NEAR(s.distance_m, 0.5, kTight);
  expect_near(s.normal, up);
}

TEST(ColliderShape, CapsuleSideCapsAndAxis) {
  ColliderGeometry g = shape(ColliderShape::Capsule, Vec3::Zero(), Vec3(90, 0, 0));  // local y along world z
  g.radius_m = 0.25;
  g.half_length_m = 1.0;
  SurfacePoint s = nearest_surface(g, Vec3(1, 0, 0.5));  // beside the cylinder
  EXPECT_NEAR(s.distance_m, 0.75, kTight);
  expect_near(s.normal, Vec3::UnitX());
  expect_near(s.closest_m, Vec3(0.25, 0, 0.5));
  s = nearest_surface(g, Vec3(0, 0, 2));  // beyond the cap at z = 1
  EXPECT_NEAR(s.distance_m, 0.75, kTight);
  expect_near(s.normal, Vec3::UnitZ());
  s = nearest_surface(g, Vec3(0, 0.1, 0.3));  // inside, 0.1 off the axis
  EXPECT_NEAR(s.distance_m, -0.15, kTight);
  expect_near(s.normal, Vec3::UnitY());
}

// The normal is the gradient of the signed distance wherever that is smooth (checked by central differences at
// random points away from the medial surfaces' few kinks: a mismatch there is a wrong normal, not a kink).
TEST(ColliderShape, NormalIsTheGradientOfTheDistance) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-2.0, 2.0);
  for (const ColliderShape kind :
       {ColliderShape::Plane, ColliderShape::Box, ColliderShape::Sphere, ColliderShape::Capsule}) {
    ColliderGeometry g = posed_shape(kind);
    int checked = 0;
    for (int trial = 0; trial < 200; ++trial) {
      const Vec3 x(coordinate(random), coordinate(random), coordinate(random));
      const double h = 1e-6;
      Vec3 gradient;
      for (int k = 0; k < 3; ++k) {
        Vec3 step = Vec3::Zero();
        step[k] = h;
        gradient[k] = (nearest_surface(g, x + step).distance_m - nearest_surface(g, x - step).distance_m) / (2 * h);
      }
      if (std::abs(gradient.norm() - 1.0) > 1e-4) continue;  // on a kink of the distance (inside a box)
      const SurfacePoint s = nearest_surface(g, x);
      EXPECT_LT((s.normal - gradient).norm(), 1e-5) << static_cast<int>(kind) << " at " << x.transpose();
      EXPECT_NEAR(nearest_surface(g, s.closest_m).distance_m, 0.0, 1e-12);  // the closest point is on the surface
      expect_near(s.closest_m + s.distance_m * s.normal, x, 1e-12);
      ++checked;
    }
    EXPECT_GT(checked, 150);
  }
}

// The quick inside test the contact passes use agrees with the signed distance's sign (away from the surface
// itself, where the two may round differently).
TEST(ColliderShape, InsideTestAgreesWithTheSignedDistance) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> coordinate(-1.5, 1.5);
  for (const ColliderShape kind :
       {ColliderShape::Plane, ColliderShape::Box, ColliderShape::Sphere, ColliderShape::Capsule}) {
    ColliderGeometry g = posed_shape(kind);
    if (kind != ColliderShape::Plane) g.world_reach_m = sim::world_reach(g);  // the quick rejection on
    int inside = 0;
    for (int trial = 0; trial < 2000; ++trial) {
      const Vec3 x(coordinate(random), coordinate(random), coordinate(random));
      const double distance = nearest_surface(g, x).distance_m;
      if (std::abs(distance) < 1e-12) continue;
      EXPECT_EQ(sim::is_inside(g, x), distance < 0.0) << static_cast<int>(kind) << " at " << x.transpose();
      inside += distance < 0.0;
    }
    EXPECT_GT(inside, 50);
  }
}

TEST(ColliderShape, WorldBoundsHoldTheShape) {
  ColliderGeometry g = shape(ColliderShape::Capsule, Vec3(1, 2, 3), Vec3(0, 0, 90));  // local y along world −x
  g.radius_m = 0.5;
  g.half_length_m = 1.0;
  Vec3 lo, hi;
  ASSERT_TRUE(sim::world_bounds(g, lo, hi));
  expect_near(lo, Vec3(-0.5, 1.5, 2.5));
  expect_near(hi, Vec3(2.5, 2.5, 3.5));
  EXPECT_FALSE(sim::world_bounds(shape(ColliderShape::Plane), lo, hi));
}

}  // namespace
