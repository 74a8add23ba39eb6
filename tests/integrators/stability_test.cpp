// Stability at large steps: vbd, every force implicit, stays stable 10× beyond the explicit limit; the explicit
// methods diverge there.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "core/errors.hpp"
#include "support.hpp"

namespace {

using integrator_tests::make_world;
using integrator_tests::total_energy;
using softbody::Vec3;

// A stiff breathing sphere, no dampers, gravity or floor: only the integrator can remove energy.
constexpr const char* kStiffSphere = R"({
  "gravity": [0, 0, 0],
  "bodies": [ { "mesh": "icosphere:2", "mass": 1.0, "stiffness": 5000.0, "damping": 0.0, "pressure": 100.0 } ]
})";

// Explicit stability limits on this scene, measured (scenes/breathing.json with stiffness 5000, no
// dampers): symplectic Euler and Verlet diverge from about 1.0 ms (2/ω_max), rk4 from about 1.4 ms
// (2.8/ω_max). The tests below check both sides of rk4's limit, the most generous.
constexpr double kExplicitLimit = 1.4e-3;  // s
constexpr double kLargeStep = 10 * kExplicitLimit;
constexpr int kSteps = 100;  // 1.4 s at the large step

// Every mode excited: a deterministic, non-smooth initial velocity field of about 0.5 m/s.
sim::World shaken_world(sim::IntegratorKind integrator) {
  sim::World world = make_world(kStiffSphere, integrator);
  std::vector<Vec3>& v = world.state.v;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const double s = static_cast<double>(i);
    v[i] = 0.5 * Vec3(std::sin(7.1 * s), std::cos(3.3 * s), std::sin(5.7 * s + 1.0));
  }
  return world;
}

TEST(VbdStability, TenTimesBeyondTheExplicitLimitEnergyNeverGrows) {
  sim::World world = shaken_world(sim::IntegratorKind::Vbd);
  const double e0 = total_energy(world);
  double highest = e0;
  for (int s = 0; s < kSteps; ++s) {
    ASSERT_NO_THROW(world.step(kLargeStep)) << "step " << s;
    highest = std::max(highest, total_energy(world));
  }
  const double e_end = total_energy(world);
  std::printf("vbd, dt = %.3g s: E0 = %.4f J, highest E = %.4f J, E after %d steps = %.4f J\n", kLargeStep, e0, highest,
              kSteps, e_end);
  EXPECT_LE(highest, e0 + 1e-9 * std::abs(e0));
  EXPECT_LT(e_end, e0);
}

class ExplicitAtTheLargeStep : public ::testing::TestWithParam<sim::IntegratorKind> {};

TEST_P(ExplicitAtTheLargeStep, Diverges) {
  sim::World world = shaken_world(GetParam());
  EXPECT_THROW(integrator_tests::run_for(world, kSteps * kLargeStep, kLargeStep), softbody::DivergedError);
}

INSTANTIATE_TEST_SUITE_P(ExplicitMethods, ExplicitAtTheLargeStep,
                         ::testing::Values(sim::IntegratorKind::Euler, sim::IntegratorKind::Symplectic,
                                           sim::IntegratorKind::Verlet, sim::IntegratorKind::Rk4),
                         [](const ::testing::TestParamInfo<sim::IntegratorKind>& test) {
                           return sim::to_string(test.param);
                         });

// Both sides of the limit quoted above, so the "10×" is measured, not assumed.
TEST(ExplicitLimit, Rk4IsStableJustBelowAndDivergesJustAbove) {
  sim::World below = shaken_world(sim::IntegratorKind::Rk4);
  const double e0 = total_energy(below);
  EXPECT_NO_THROW(integrator_tests::run_for(below, 1000 * 0.9 * kExplicitLimit, 0.9 * kExplicitLimit));
  EXPECT_LT(total_energy(below), e0 + 1e-3 * std::abs(e0));
  sim::World above = shaken_world(sim::IntegratorKind::Rk4);
  EXPECT_THROW(integrator_tests::run_for(above, 1000 * 1.1 * kExplicitLimit, 1.1 * kExplicitLimit),
               softbody::DivergedError);
}

}  // namespace
