// Newton with smooth colliders inside its potential: with the lags held, the colliders' terms' gradient is the
// derivative of their energy (a curved sphere and a tilted box, so that the lagged normal differs between vertices).
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "sim/contact/collider_shape.hpp"
#include "sim/integrators/incremental_potential.hpp"
#include "sim/solvers/block_system.hpp"
#include "support.hpp"

namespace {

using integrator_tests::make_world;
using integrator_tests::wiggle;
using softbody::Vec3;

// A unit sphere sunk 0.1 m into a sphere collider on its left and a tilted box on its right, sliding: every term of
// both colliders is non-zero at some vertex.
constexpr const char* kSunk = R"({ "gravity": [0, -9.81, 0],
    "colliders": [ { "shape": "sphere", "position": [-0.6, -0.9, 0], "radius": 1.0, "contact": "smooth",
                     "friction": 0.5, "restitution": 0.5 },
                   { "shape": "box", "position": [0.8, -0.3, 0], "size": [1, 1, 2], "rotation": [10, 0, 30],
                     "contact": "smooth", "friction": 0.3, "restitution": 0.2 } ],
    "bodies": [ { "mesh": "icosphere:2", "position": [0, 0.9, 0], "mass": 1.0, "stiffness": 300.0,
                  "damping": 2.0, "pressure": 40.0 } ] })";

TEST(NewtonColliderPotential, GradientMatchesFiniteDifferencesOfTheEnergy) {
  sim::World world = make_world(kSunk, sim::IntegratorKind::Newton);
  sim::State& s = world.state;
  const double h = 1.0 / 60;
  for (std::size_t i = 0; i < s.x.size(); ++i) s.v[i] = Vec3(1.0, -0.5, 0.3) + 0.2 * wiggle(i, 0.0);
  sim::IncrementalPotential potential;
  sim::BlockSystem hessian;
  potential.build(world.model);
  hessian.build(world.model.vertex_count(), potential.pairs());
  potential.begin_step(world.model, s, h);
  std::vector<Vec3> x(s.x.size());
  for (std::size_t i = 0; i < s.x.size(); ++i) x[i] = s.x[i] + h * s.v[i] + 0.01 * wiggle(i, 1.0);
  Eigen::VectorXd gradient = Eigen::VectorXd::Zero(hessian.size());
  potential.update_lags(world.model, x);
  potential.assemble(world.model, x, sim::IncrementalPotential::Hessian::Exact, hessian, gradient);
  std::vector<int> inside;
  for (std::size_t i = 0; i < x.size(); ++i) {
    for (const sim::Collider& c : world.model.colliders) {
      if (sim::nearest_surface(c.geometry, x[i]).distance_m < 0.0) {
        inside.push_back(static_cast<int>(i));
        break;
      }
    }
  }
  ASSERT_GT(inside.size(), 10u);
  const integrator_tests::GradientMismatch m =
      integrator_tests::gradient_mismatch(potential, world.model, hessian, x, gradient, inside, /*step=*/1e-7);
  std::printf("%zu vertices inside colliders: max |dE/dx numeric - analytic| = %.3e N (largest component %.3e N)\n",
              inside.size(), m.worst_N, m.scale_N);
  EXPECT_LT(m.worst_N, 1e-5 * m.scale_N);
}

}  // namespace
