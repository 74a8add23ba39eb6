// Free fall: methods exact for constant acceleration reproduce x0 + v0 t + ½ g t² to round-off.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "sim/step/diagnostics.hpp"
#include "support.hpp"

namespace {

using integrator_tests::kDust;
using integrator_tests::make_world;
using softbody::Vec3;

// A thrown, breathing, damped sphere, no floor. Springs, dampers and pressure are internal forces that sum
// to zero (Newton's third law; the pressure forces on a closed mesh sum to zero), so the centre of mass
// falls freely whatever the body does inside.
constexpr const char* kThrownSphere = R"({
  "gravity": [0, -9.81, 0],
  "bodies": [ { "mesh": "icosphere:2", "position": [0, 5, 0], "velocity": [1.5, 4, -0.5],
                "mass": 1.0, "stiffness": 500.0, "damping": 0.5, "pressure": 300.0 } ]
})";

const Vec3 kG(0, -9.81, 0);
const Vec3 kV0(1.5, 4, -0.5);
constexpr double kDt = 1e-3, kDuration = 1.0;  // 1000 steps
// Round-off: positions of a few metres carry ~1e-15 m each step; 1000 steps stay below 1e-12 m.
constexpr double kRoundOff = 1e-11;

Vec3 free_fall(const Vec3& x0, double t) { return x0 + kV0 * t + 0.5 * kG * t * t; }

class ExactFreeFall : public ::testing::TestWithParam<sim::IntegratorKind> {};

TEST_P(ExactFreeFall, CentreOfMassOfAThrownBreathingSphere) {
  sim::World world = make_world(kThrownSphere, GetParam());
  const Vec3 com0 = sim::diagnose(world.model, world.state, 0).com_m;
  integrator_tests::run_for(world, kDuration, kDt);
  const sim::BodyDiagnostics d = sim::diagnose(world.model, world.state, 0);
  const double error = (d.com_m - free_fall(com0, kDuration)).norm();
  const double velocity_error = (d.com_velocity_m_per_s - (kV0 + kG * kDuration)).norm();
  std::printf("%s: |COM - exact| = %.2e m, |v_COM - exact| = %.2e m/s\n", sim::to_string(GetParam()).c_str(), error,
              velocity_error);
  EXPECT_LT(error, kRoundOff);
  EXPECT_LT(velocity_error, kRoundOff);
}

TEST_P(ExactFreeFall, EveryVertexUnderGravityAlone) {
  sim::World world = make_world(kDust, GetParam());
  const std::vector<Vec3> x0 = world.state.x;
  integrator_tests::run_for(world, kDuration, kDt);
  double worst = 0.0;
  for (std::size_t i = 0; i < x0.size(); ++i) {
    worst = std::max(worst, (world.state.x[i] - free_fall(x0[i], kDuration)).norm());
  }
  EXPECT_LT(worst, kRoundOff);
}

INSTANTIATE_TEST_SUITE_P(SecondOrderAndAbove, ExactFreeFall,
                         ::testing::Values(sim::IntegratorKind::Verlet, sim::IntegratorKind::Rk4),
                         [](const ::testing::TestParamInfo<sim::IntegratorKind>& test) {
                           return sim::to_string(test.param);
                         });

// The first-order methods are not exact for a parabola: forward Euler lags by ½ g h t, symplectic Euler
// leads by it. This checks that the test above can tell.
TEST(FirstOrderFreeFall, MissesByHalfGHT) {
  for (sim::IntegratorKind integrator : {sim::IntegratorKind::Euler, sim::IntegratorKind::Symplectic}) {
    sim::World world = make_world(kDust, integrator);
    const Vec3 x0 = world.state.x[0];
    integrator_tests::run_for(world, kDuration, kDt);
    const double error = (world.state.x[0] - free_fall(x0, kDuration)).norm();
    EXPECT_NEAR(error, 0.5 * 9.81 * kDt * kDuration, 1e-9) << sim::to_string(integrator);
  }
}

// xpbd is first order in what its constraints do, but its velocities are the half substeps' (the first substep
// kicks by h/2: sim/integrators/xpbd.hpp), so a constant force moves the positions exactly: the centre of mass of
// the thrown, breathing sphere (whose springs, dampers and gas are internal, and whose constraint corrections
// w_i Δλ n̂ and −w_j Δλ n̂ keep the momentum) and every free vertex follow the parabola to round-off, where a whole
// first kick would lead by ½ g h t (4.9 mm here). The velocity written out is the last half substep's: ½ g h behind.
// Its round-off is larger than the other methods': v = (x − x_prev)/h is taken from positions of a few metres,
// ulp(x)/h ≈ 1e-12 m/s each substep, and feeds the next positions (measured 5.6e-11 m and 1.1e-10 m/s).
TEST(XpbdFreeFall, PositionsFollowTheParabolaAndVelocitiesLagByHalfASubstep) {
  constexpr double kXpbdRoundOff = 1e-9;
  for (const bool dust : {false, true}) {
    sim::World world = make_world(dust ? kDust : kThrownSphere, sim::IntegratorKind::Xpbd);
    const Vec3 com0 = sim::diagnose(world.model, world.state, 0).com_m;
    const std::vector<Vec3> x0 = world.state.x;
    integrator_tests::run_for(world, kDuration, kDt);
    const sim::BodyDiagnostics d = sim::diagnose(world.model, world.state, 0);
    EXPECT_LT((d.com_m - free_fall(com0, kDuration)).norm(), kXpbdRoundOff);
    const Vec3 half_substep_velocity = kV0 + kG * (kDuration - 0.5 * kDt);
    EXPECT_LT((d.com_velocity_m_per_s - half_substep_velocity).norm(), kXpbdRoundOff);
    if (!dust) continue;  // the sphere's vertices breathe; the dust's each fall freely
    for (std::size_t i = 0; i < x0.size(); ++i) {
      EXPECT_LT((world.state.x[i] - free_fall(x0[i], kDuration)).norm(), kXpbdRoundOff);
    }
  }
}

}  // namespace
