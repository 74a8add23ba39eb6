// The stable-dt estimate is conservative (no measured instability at or below it) and useful (within 2×).
#include <cstdio>

#include <gtest/gtest.h>

#include "analysis/limits.hpp"
#include "analysis/stable_dt.hpp"
#include "sim/step/stability.hpp"
#include "test_helpers.hpp"

namespace {

using sim::IntegratorKind;

sim::StabilityEstimate estimate_of(const sim::World& world) {
  return sim::estimate_stability(world.model, world.state);
}

// A coarse damped ball and an undamped one: small meshes, so a 5000-step bisection takes about a second.
const analysis::LimitBody kDamped{"coarse damped", "icosphere:1", 1e4, 2.0, 30.0};
const analysis::LimitBody kUndamped{"coarse undamped", "icosphere:1", 2000.0, 0.0, 50.0};
constexpr int kSteps = 5000;

class EstimateAgainstMeasurement : public ::testing::TestWithParam<std::tuple<analysis::LimitBody, IntegratorKind>> {};

TEST_P(EstimateAgainstMeasurement, IsConservativeAndWithinTwiceTheMeasuredLimit) {
  const analysis::LimitBody& body = std::get<0>(GetParam());
  const IntegratorKind integrator = std::get<1>(GetParam());  // not a structured binding: lambdas capture it
  const double estimate = estimate_of(analysis::limit_world(body, integrator)).stable_dt(integrator);
  ASSERT_GT(estimate, 0.0);
  const analysis::StableDtMeasurement measured = analysis::measure_stable_dt(
      [&] { return analysis::limit_world(body, integrator); }, 0.25 * estimate, 2.0 * estimate, kSteps);
  std::printf("%s, %s: estimate %.4g s, measured stable %.4g s, unstable %.4g s (estimate / measured %.3f)\n",
              body.name.c_str(), sim::to_string(integrator).c_str(), estimate, measured.stable_dt_s,
              measured.unstable_dt_s, estimate / measured.stable_dt_s);
  EXPECT_LE(estimate, measured.unstable_dt_s) << "the estimate must not reach into the unstable range";
  EXPECT_GE(estimate, 0.5 * measured.stable_dt_s) << "the estimate must be within a factor 2";
}

INSTANTIATE_TEST_SUITE_P(Bodies, EstimateAgainstMeasurement,
                         ::testing::Combine(::testing::Values(kDamped),
                                            ::testing::Values(IntegratorKind::Euler, IntegratorKind::Symplectic,
                                                              IntegratorKind::Verlet, IntegratorKind::Rk4,
                                                              IntegratorKind::Rk45)),
                         [](const auto& test) { return "damped_" + sim::to_string(std::get<1>(test.param)); });

// Forward Euler has no stable dt without dampers (see below), so the undamped body skips it.
INSTANTIATE_TEST_SUITE_P(UndampedBodies, EstimateAgainstMeasurement,
                         ::testing::Combine(::testing::Values(kUndamped),
                                            ::testing::Values(IntegratorKind::Symplectic, IntegratorKind::Verlet,
                                                              IntegratorKind::Rk4, IntegratorKind::Rk45)),
                         [](const auto& test) { return "undamped_" + sim::to_string(std::get<1>(test.param)); });

// Forward Euler without dampers has no stable dt: the estimate says so instead of inventing one.
TEST(Estimate, ForwardEulerWithoutDampersHasNoStableDt) {
  EXPECT_EQ(estimate_of(analysis::limit_world(kUndamped, IntegratorKind::Euler)).stable_dt(IntegratorKind::Euler), 0.0);
}

// The damper limit of forward Euler is c/k for underdamped modes (ζω = (c/k) ω² / 2); the estimate keeps
// sim::kSharpLimitMargin below it because every mode reaches |g| = 1 there at once.
TEST(Estimate, ForwardEulerDamperLimitIsCOverK) {
  const analysis::LimitBody ball{"bounce", "icosphere:2", 3000.0, 0.5, 30.0};
  const double dt = estimate_of(analysis::limit_world(ball, IntegratorKind::Euler)).stable_dt(IntegratorKind::Euler);
  EXPECT_NEAR(dt, sim::kSharpLimitMargin * 0.5 / 3000.0, 0.02 * 0.5 / 3000.0);
}

// Power iterations stay below Gershgorin's upper bound and above half of it on a regular mesh.
TEST(Estimate, PowerIterationsLieBelowTheGershgorinBound) {
  sim::World world = analysis::limit_world(kDamped, IntegratorKind::Symplectic);
  const sim::ModeBounds b =
      sim::mode_bounds(world.model.bodies[0], world.model.of(world.model.bodies[0], world.state.x));
  EXPECT_LE(b.lambda_max_per_kg, b.lambda_gershgorin_per_kg);
  EXPECT_GT(b.lambda_max_per_kg, 0.3 * b.lambda_gershgorin_per_kg);
}

}  // namespace

namespace {

// `softbody info` prints the estimate per integrator, and `--set solver.dt=auto` picks 0.7 × it.
TEST(InfoCommand, PrintsTheEstimateAndDtAutoUsesIt) {
  const auto result = testing_support::run_softbody("info scenes/bounce.json --set solver.dt=auto");
  EXPECT_EQ(result.exit_status, 0) << result.output;
  for (const char* expected :
       {"642 vertices, 1920 springs", "lumped vertex masses", "omega_max", "euler       0.000125 ", "vbd",
        "solver.dt = auto: 8.75e-05 s (0.70 x the estimated stable dt of euler"}) {
    EXPECT_NE(result.output.find(expected), std::string::npos) << expected << "\n" << result.output;
  }
}

// Forward Euler without dampers has no dt to pick: a bad-input error naming the key, exit status 2.
TEST(InfoCommand, DtAutoRefusesForwardEulerWithoutDampers) {
  const auto result =
      testing_support::run_softbody("info scenes/bounce.json --set solver.dt=auto --set bodies.0.damping=0");
  EXPECT_EQ(result.exit_status, 2) << result.output;
  EXPECT_NE(result.output.find("solver.dt: \"auto\" found no stable dt for euler"), std::string::npos) << result.output;
}

}  // namespace
