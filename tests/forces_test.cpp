// The force model: pressure as the exact gradient of the gas energy, springs and dampers in closed form.
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "mesh/generators.hpp"
#include "reference_forces.hpp"
#include "sim/forces/forces.hpp"
#include "sim/step/finite_scan.hpp"

namespace {

using softbody::Vec3;

// An icosphere with every vertex moved randomly by up to 20 % of the radius: closed, but far from round.
std::vector<Vec3> deformed_sphere(const mesh::TriMesh& sphere, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  std::vector<Vec3> x;
  for (const Vec3& p : sphere.vertices)
    x.push_back(Vec3(3, 1, -2) + p + Vec3(jitter(random), jitter(random), jitter(random)));
  return x;
}

TEST(Pressure, ForcesSumToZeroOnClosedDeformedMesh) {
  const mesh::TriMesh sphere = mesh::icosphere(3);
  const std::vector<Vec3> x = deformed_sphere(sphere, 7);
  std::vector<Vec3> force(x.size(), Vec3::Zero());
  const double nRT = 50.0;
  reference::add_gas(sphere.triangles, nRT, 4.0, x, force);
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
  std::vector<Vec3> force(x.size(), Vec3::Zero());
  const double nRT = 80.0;
  const double volume = reference::add_gas(sphere.triangles, nRT, 1.0, x, force);
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
  EXPECT_NEAR(sim::enclosed_volume(sphere.triangles, far), sim::enclosed_volume(sphere.triangles, sphere.vertices),
              1e-11);
}

TEST(Spring, HookeForceAlongTheSpring) {
  const std::vector<std::array<int, 2>> edges = {{0, 1}};
  const std::vector<double> rest = {2.0};
  const std::vector<Vec3> x = {Vec3(0, 0, 0), Vec3(3, 4, 0)};  // length 5, stretched by 3
  std::vector<Vec3> force(2, Vec3::Zero());
  reference::add_springs(edges, rest, 10.0, x, force);
  // f_0 = -k (|d| - L0) d̂ with d = x_0 - x_1 = (-3, -4, 0): pulls 0 towards 1 with 30 N.
  EXPECT_NEAR((force[0] - Vec3(18, 24, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((force[0] + force[1]).norm(), 0.0, 1e-12);
}

TEST(Damper, ActsOnlyAlongTheSpring) {
  const std::vector<std::array<int, 2>> edges = {{0, 1}};
  const std::vector<Vec3> x = {Vec3(0, 0, 0), Vec3(1, 0, 0)};
  const std::vector<Vec3> v = {Vec3(-2, 5, 0), Vec3(0, 0, 7)};  // separating at 2 m/s, sliding across
  std::vector<Vec3> force(2, Vec3::Zero());
  reference::add_dampers(edges, 3.0, x, v, force);
  // f_0 = -c ((v_0 - v_1)·d̂) d̂, d̂ = (-1, 0, 0), (v_0 - v_1)·d̂ = 2 → f_0 = -3·2·(-1,0,0) = (6, 0, 0).
  EXPECT_NEAR((force[0] - Vec3(6, 0, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((force[0] + force[1]).norm(), 0.0, 1e-12);
}

// The fused edge loop World uses equals the two reference loops up to round-off, on a mesh large enough
// for several edge blocks and a partial last block, with a coincident pair that must get no force.
TEST(SpringDamper, FusedLoopEqualsSpringsPlusDampers) {
  const mesh::TriMesh sphere = mesh::icosphere(3);  // 1920 edges: 30 blocks of 64
  std::vector<Vec3> x = sphere.vertices, v(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double s = static_cast<double>(i);
    x[i] *= 1.0 + 0.1 * std::sin(s);
    v[i] = Vec3(std::cos(s), std::sin(2 * s), 0.5 * std::cos(3 * s));
  }
  std::vector<std::array<int, 2>> edges;
  for (const auto& f : sphere.triangles) {
    for (int k = 0; k < 3; ++k) {
      if (f[k] < f[(k + 1) % 3]) edges.push_back({f[k], f[(k + 1) % 3]});
    }
  }
  edges.push_back({0, 0});  // coincident endpoints: no direction, no force
  const std::vector<double> rest(edges.size(), 0.2);
  std::vector<Vec3> reference(x.size(), Vec3::Zero()), fused(x.size(), Vec3::Zero());
  reference::add_springs(edges, rest, 3000.0, x, reference);
  reference::add_dampers(edges, 0.5, x, v, reference);
  sim::DistanceConstraints damped{edges, rest, std::vector<double>(edges.size(), 3000.0),
                                  std::vector<double>(edges.size(), 0.5), edges.size()};
  sim::add_spring_dampers(damped, x, v, fused);
  double worst = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    worst = std::max(worst, (fused[i] - reference[i]).norm());
    scale = std::max(scale, reference[i].norm());
  }
  // Different rounding only: a few ulps of the largest edge force summed over six edges.
  EXPECT_LT(worst, 1e-12 * scale) << "worst " << worst << " of " << scale;
  std::vector<Vec3> undamped(x.size(), Vec3::Zero()), springs(x.size(), Vec3::Zero());
  reference::add_springs(edges, rest, 3000.0, x, springs);
  sim::DistanceConstraints undamped_springs = damped;
  undamped_springs.damping_N_s_per_m.assign(edges.size(), 0.0);
  sim::add_spring_dampers(undamped_springs, x, v, undamped);  // c = 0: the spring-only loop
  for (std::size_t i = 0; i < x.size(); ++i) EXPECT_LT((undamped[i] - springs[i]).norm(), 1e-12 * scale);
}

TEST(FiniteScan, FindsNaNAndInfinityAnywhere) {
  std::vector<Vec3> values(100, Vec3(1, -2, 3));
  EXPECT_TRUE(sim::all_finite(values));
  EXPECT_TRUE(sim::all_finite(std::span<const Vec3>()));
  values[57].z() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(sim::all_finite(values));
  values[57].z() = 0.0;
  values[99].x() = -std::numeric_limits<double>::infinity();
  EXPECT_FALSE(sim::all_finite(values));
  values[99].x() = std::numeric_limits<double>::max();  // large but finite
  EXPECT_TRUE(sim::all_finite(values));
}

}  // namespace

namespace {

// The gas's fused face pass computes 6 ∂V/∂x as area sums; the reference gradient (intent, the stability
// estimate) sums A n̂ / 3 per face. The two agree to round-off, and both equal ∂V/∂x by central differences.
TEST(Volume, AreaSumsAreSixTimesTheVolumeGradient) {
  const mesh::TriMesh sphere = mesh::icosphere(3);
  const std::vector<Vec3> x = deformed_sphere(sphere, 5);
  std::vector<Vec3> area_sums, gradient;
  const double volume = sim::volume_and_area_sums(sphere.triangles, x, area_sums);
  sim::volume_gradient(sphere.triangles, x, gradient);
  EXPECT_NEAR(volume, sim::enclosed_volume(sphere.triangles, x), 1e-13 * volume);
  double worst = 0.0, largest = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    worst = std::max(worst, (area_sums[i] / 6.0 - gradient[i]).norm());
    largest = std::max(largest, gradient[i].norm());
  }
  EXPECT_LT(worst, 1e-14 * largest) << "largest |dV/dx| " << largest;
}

// dV/dt = Σ ∂V/∂x_i · v_i: against the volume gradient's sum, and against a central difference of V along v
// (V is cubic in the positions, so the difference's error is (ε²/6) V‴ alone).
TEST(Volume, RateIsTheGradientAlongTheVelocities) {
  const mesh::TriMesh sphere = mesh::icosphere(3);
  const std::vector<Vec3> x = deformed_sphere(sphere, 11);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> speed(-2.0, 2.0);
  std::vector<Vec3> v;
  for (std::size_t i = 0; i < x.size(); ++i) v.push_back(Vec3(speed(random), speed(random), speed(random)));
  std::vector<Vec3> gradient;
  sim::volume_gradient(sphere.triangles, x, gradient);
  double along = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) along += gradient[i].dot(v[i]);
  constexpr double kEps = 1e-5;  // [s]
  std::vector<Vec3> ahead = x, behind = x;
  for (std::size_t i = 0; i < x.size(); ++i) {
    ahead[i] += kEps * v[i];
    behind[i] -= kEps * v[i];
  }
  const double central =
      (sim::enclosed_volume(sphere.triangles, ahead) - sim::enclosed_volume(sphere.triangles, behind)) / (2.0 * kEps);
  const double rate = sim::volume_rate(sphere.triangles, x, v);
  EXPECT_NEAR(rate, along, 1e-12 * std::abs(along));
  EXPECT_NEAR(rate, central, 1e-7 * std::abs(central));
}

}  // namespace
