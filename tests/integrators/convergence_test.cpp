// Measured convergence orders on a smooth scene: the error against a fine reference shrinks like dt^p.
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "support.hpp"

namespace {

// A breathing sphere under gravity, no floor (so no contact events: smooth motion). It starts at its spring
// rest shape; the gas pushes it outward, it overshoots and breathes while falling. Dampers are on so that
// Verlet's handling of velocity-dependent forces is part of what is measured.
constexpr const char* kSmoothScene = R"({
  "gravity": [0, -9.81, 0],
  "bodies": [ { "mesh": "icosphere:2", "mass": 1.0, "stiffness": 500.0, "damping": 0.5, "pressure": 300 } ]
})";

// Time span: about 40 % of a breathing period, long enough for every mode to move, short enough that the
// coarsest steps below are in the asymptotic range. Every dt below divides it.
constexpr double kSpan = 0.128;  // s

// The reference: fifth order at 2 µs, 50× finer than the finest rk4 step, computed once; its distance to the same
// at 4 µs bounds its error and must be far below the smallest error measured.
integrator_tests::HalvingSweep& breathing() {
  static integrator_tests::HalvingSweep measurement(kSmoothScene, kSpan, 2e-6);
  return measurement;
}

struct OrderCase {
  sim::IntegratorKind integrator;
  double coarsest_dt;  // s; then halved four times
  double expected_order;
};

class ConvergenceOrder : public ::testing::TestWithParam<OrderCase> {};

TEST_P(ConvergenceOrder, MatchesTheMethodsOrder) {
  const OrderCase c = GetParam();
  const std::vector<double> errors = breathing().errors(c.integrator, c.coarsest_dt, 4);
  const double order =
      integrator_tests::report_observed_order(c.integrator, errors, breathing().reference_uncertainty());
  EXPECT_NEAR(order, c.expected_order, 0.2);
  EXPECT_GT(errors.back(), 1e-11) << "the finest error must stay far above round-off";
  EXPECT_LT(breathing().reference_uncertainty(), 1e-3 * errors.back()) << "the reference is not converged enough";
}

INSTANTIATE_TEST_SUITE_P(SmoothBreathingSphere, ConvergenceOrder,
                         ::testing::Values(OrderCase{sim::IntegratorKind::Euler, 1e-4, 1.0},
                                           OrderCase{sim::IntegratorKind::Symplectic, 1e-4, 1.0},
                                           OrderCase{sim::IntegratorKind::Verlet, 4e-4, 2.0},
                                           OrderCase{sim::IntegratorKind::Rk4, 1.28e-3, 4.0}),
                         [](const ::testing::TestParamInfo<OrderCase>& test) {
                           return sim::to_string(test.param.integrator);
                         });

// rk45 has no step to halve: its global error should follow the tolerance, roughly proportionally
// (Dormand–Prince's local error ∝ h⁵ and h ∝ tol^(1/5) make the error per unit time ∝ tol).
TEST(AdaptiveTolerance, ErrorFollowsTheTolerance) {
  const integrator_tests::ToleranceSweep sweep =
      integrator_tests::rk45_tolerance_sweep(kSmoothScene, kSpan, breathing().reference(), 4, 9);
  for (std::size_t k = 0; k < sweep.errors.size(); ++k) {
    EXPECT_LT(sweep.errors[k], 10.0 * sweep.tolerances[k]) << "the error should stay near the requested tolerance";
  }
  EXPECT_NEAR(sweep.slope, 1.0, 0.3);
}

}  // namespace
