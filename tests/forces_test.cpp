// The force model: pressure as the exact gradient of the gas energy, springs and dampers in closed form.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "mesh/generators.hpp"
#include "sim/forces.hpp"

namespace {

using softbody::Vec3;

// An icosphere with every vertex moved randomly by up to 20 % of the radius: closed, but far from round.
std::vector<Vec3> deformed_sphere(const mesh::TriMesh& sphere, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  std::vector<Vec3> x;
  for (const Vec3& p : sphere.vertices) x.push_back(Vec3(3, 1, -2) + p + Vec3(jitter(random), jitter(random), jitter(random)));
  return x;
}

TEST(Pressure, ForcesSumToZeroOnClosedDeformedMesh) {
  const mesh::TriMesh sphere = mesh::icosphere(3);
  const std::vector<Vec3> x = deformed_sphere(sphere, 7);
  std::vector<Vec3> force(x.size(), Vec3::Zero()), scratch;
  const double nRT = 50.0;
  sim::add_pressure(sphere.triangles, nRT, 4.0, x, scratch, force);
  Vec3 net = Vec3::Zero();
  double magnitude = 0.0;
  for (const Vec3& f : force) {
    net += f;
    magnitude += f.norm();
  }
  // Round-off only: each face's push cancels exactly in exact arithmetic (Σ area vectors = 0).
  EXPECT_LT(net.norm(), 1e-14 * magnitude) << "net " << net.transpose() << " of total " << magnitude;
}

// f_i = nRT ∂(ln V)/∂x_i = P ∂V/∂x_i: compare with central differences of the volume.
TEST(Pressure, VertexForceIsPressureTimesVolumeGradient) {
  const mesh::TriMesh sphere = mesh::icosphere(2);
  std::vector<Vec3> x = deformed_sphere(sphere, 11);
  std::vector<Vec3> force(x.size(), Vec3::Zero()), scratch;
  const double nRT = 80.0;
  const double volume = sim::add_pressure(sphere.triangles, nRT, 1.0, x, scratch, force);
  EXPECT_NEAR(volume, sim::enclosed_volume(sphere.triangles, x), 1e-13);
  const double pressure = nRT / volume;
  const double h = 1e-3;
  double worst = 0.0;
  for (std::size_t i = 0; i < x.size(); i += 7) {
    for (int axis = 0; axis < 3; ++axis) {
      const double saved = x[i][axis];
      x[i][axis] = saved + h;
      const double up = sim::enclosed_volume(sphere.triangles, x);
      x[i][axis] = saved - h;
      const double down = sim::enclosed_volume(sphere.triangles, x);
      x[i][axis] = saved;
      const double expected = pressure * (up - down) / (2 * h);
      worst = std::max(worst, std::abs(force[i][axis] - expected) / std::max(1.0, std::abs(expected)));
    }
  }
  // Each face holds a vertex once, so V is linear in each single coordinate: central differences are
  // exact but for round-off (~1e-16 · V / h).
  EXPECT_LT(worst, 1e-10);
}

TEST(Volume, TranslationDoesNotChangeIt) {
  const mesh::TriMesh sphere = mesh::icosphere(3);
  std::vector<Vec3> far = sphere.vertices;
  for (Vec3& p : far) p += Vec3(1e4, -3e3, 5e3);
  EXPECT_NEAR(sim::enclosed_volume(sphere.triangles, far), sim::enclosed_volume(sphere.triangles, sphere.vertices), 1e-11);
}

TEST(Spring, HookeForceAlongTheSpring) {
  const std::vector<std::array<int, 2>> edges = {{0, 1}};
  const std::vector<double> rest = {2.0};
  const std::vector<Vec3> x = {Vec3(0, 0, 0), Vec3(3, 4, 0)};  // length 5, stretched by 3
  std::vector<Vec3> force(2, Vec3::Zero());
  sim::add_springs(edges, rest, 10.0, x, force);
  // f_0 = -k (|d| - L0) d̂ with d = x_0 - x_1 = (-3, -4, 0): pulls 0 towards 1 with 30 N.
  EXPECT_NEAR((force[0] - Vec3(18, 24, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((force[0] + force[1]).norm(), 0.0, 1e-12);
}

TEST(Damper, ActsOnlyAlongTheSpring) {
  const std::vector<std::array<int, 2>> edges = {{0, 1}};
  const std::vector<Vec3> x = {Vec3(0, 0, 0), Vec3(1, 0, 0)};
  const std::vector<Vec3> v = {Vec3(-2, 5, 0), Vec3(0, 0, 7)};  // separating at 2 m/s, sliding across
  std::vector<Vec3> force(2, Vec3::Zero());
  sim::add_dampers(edges, 3.0, x, v, force);
  // f_0 = -c ((v_0 - v_1)·d̂) d̂, d̂ = (-1, 0, 0), (v_0 - v_1)·d̂ = 2 → f_0 = -3·2·(-1,0,0) = (6, 0, 0).
  EXPECT_NEAR((force[0] - Vec3(6, 0, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((force[0] + force[1]).norm(), 0.0, 1e-12);
}

}  // namespace
