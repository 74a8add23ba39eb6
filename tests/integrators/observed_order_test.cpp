// The accuracy benchmark's order report (analysis/observed_order.hpp): pairwise and least-squares orders of
// known power laws, and which runs of a sweep may enter the fit.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "analysis/observed_order.hpp"
#include "analysis/work_precision.hpp"

namespace {

using analysis::SweepPoint;
using sim::IntegratorKind;

TEST(ObservedOrder, RecoversAnExactPowerLaw) {
  std::vector<SweepPoint> points;
  for (int k = 0; k < 5; ++k) {
    const double h = 1e-4 / std::pow(2.0, k);
    points.push_back({h, 3.0 * std::pow(h, 4)});  // e = 3 h⁴
  }
  std::swap(points[0], points[3]);  // any order in, largest step first out
  const analysis::ObservedOrder order = analysis::observed_order(points);
  ASSERT_EQ(order.pairwise.size(), 4u);
  for (double p : order.pairwise) EXPECT_NEAR(p, 4.0, 1e-9);
  EXPECT_NEAR(order.fitted, 4.0, 1e-9);
  EXPECT_NEAR(order.fitted_standard_error, 0.0, 1e-9);  // on the line
  EXPECT_DOUBLE_EQ(order.points.front().step, 1e-4);
}

// e = h⁴ (1 ± ½), the sign alternating from run to run (an error constant that wobbles, as when a contact event
// falls at a different place in its step): the pairwise orders swing by ± log2 3 = ±1.58, the fit moves by
// only Σ(k − k̄) ln(1 ± ½) / (Σ(k − k̄)² ln 2) = 1.5 ln 3 / (17.5 ln 2) over six halvings.
TEST(ObservedOrder, LeastSquaresAveragesAWobblingConstant) {
  std::vector<SweepPoint> points;
  for (int k = 0; k < 6; ++k) {
    const double h = 4e-5 / std::pow(2.0, k);
    points.push_back({h, std::pow(h, 4) * (k % 2 == 0 ? 1.5 : 0.5)});
  }
  const analysis::ObservedOrder order = analysis::observed_order(points);
  ASSERT_EQ(order.pairwise.size(), 5u);
  for (std::size_t k = 0; k < order.pairwise.size(); ++k) {
    EXPECT_NEAR(order.pairwise[k], 4.0 + (k % 2 == 0 ? 1.0 : -1.0) * std::log2(3.0), 1e-9);
  }
  const double fitted = 4.0 + 1.5 * std::log(3.0) / (17.5 * std::log(2.0));
  EXPECT_NEAR(order.fitted, fitted, 1e-9);
  // The standard error from the residuals r_k = ln e_k − the line, recomputed here: √(Σ r² / 4 / Σ (ln h − mean)²).
  double residuals = 0.0, spread = 0.0, mean_log_h = 0.0, mean_log_e = 0.0;
  for (const SweepPoint& p : points) {
    mean_log_h += std::log(p.step) / 6.0;
    mean_log_e += std::log(p.error_m) / 6.0;
  }
  for (const SweepPoint& p : points) {
    const double r = std::log(p.error_m) - mean_log_e - fitted * (std::log(p.step) - mean_log_h);
    residuals += r * r;
    spread += std::pow(std::log(p.step) - mean_log_h, 2);
  }
  EXPECT_NEAR(order.fitted_standard_error, std::sqrt(residuals / 4.0 / spread), 1e-9);
  EXPECT_GT(order.fitted_standard_error, 0.1);
}

TEST(ObservedOrder, DropsRunsWithoutAnErrorAndNeedsTwo) {
  const analysis::ObservedOrder one = analysis::observed_order({{1e-4, 1e-8}, {5e-5, 0.0}, {2.5e-5, std::nan("")}});
  EXPECT_EQ(one.points.size(), 1u);
  EXPECT_TRUE(one.pairwise.empty());
  EXPECT_TRUE(std::isnan(one.fitted));
}

analysis::AccuracyRun run(IntegratorKind integrator, double dt, double error, analysis::RunStatus status,
                          double tolerance = 0.0) {
  analysis::AccuracyRun r;
  r.integrator = integrator;
  r.dt_s = dt;
  r.tolerance = tolerance;
  r.rms_error_m = error;
  r.status = status;
  r.wall_s = 1.0 / dt * 1e-5;
  return r;
}

// rk4 with an estimated stable dt of 1e-4 s: its runs at 8e-5 s (above half of it) and at the reference's floor
// stay out; 5e-5 s (exactly half) is in; euler's runs never enter rk4's fit; rk45's points are its tolerances.
analysis::AccuracyResult sweep() {
  using analysis::RunStatus;
  analysis::AccuracyResult result;
  result.scene_name = "synthetic";
  result.floor_factor = 100.0;
  result.reference.uncertainty_m = 1e-14;
  result.stable_dt_s.assign(sim::kIntegrators.size(), 1e-4);
  result.runs = {run(IntegratorKind::Rk4, 8e-5, 9e-8, RunStatus::Ok),
                 run(IntegratorKind::Rk4, 5e-5, std::pow(5e-5, 4), RunStatus::Ok),
                 run(IntegratorKind::Rk4, 2.5e-5, std::pow(2.5e-5, 4), RunStatus::Ok),
                 run(IntegratorKind::Rk4, 1.25e-5, std::pow(1.25e-5, 4), RunStatus::Ok),
                 run(IntegratorKind::Rk4, 6.25e-6, 1e-13, RunStatus::AtReference),
                 run(IntegratorKind::Euler, 2e-5, 1e-3, RunStatus::Ok),
                 run(IntegratorKind::Euler, 1e-5, 5e-4, RunStatus::Ok),
                 run(IntegratorKind::Rk45, 2e-4, 1e-4, RunStatus::Ok, 1e-3),
                 run(IntegratorKind::Rk45, 1e-4, 1e-5, RunStatus::Ok, 1e-4)};
  return result;
}

TEST(OrderFitPoints, KeepsOnlyRunsWellInsideTheStabilityRegionAndAboveTheReferencesFloor) {
  const analysis::AccuracyResult result = sweep();
  const std::vector<SweepPoint> rk4 = analysis::order_fit_points(result, IntegratorKind::Rk4);
  ASSERT_EQ(rk4.size(), 3u);
  EXPECT_DOUBLE_EQ(rk4[0].step, 5e-5);
  EXPECT_DOUBLE_EQ(rk4[2].step, 1.25e-5);
  EXPECT_NEAR(analysis::observed_order(rk4).fitted, 4.0, 1e-9);
  const std::vector<SweepPoint> rk45 = analysis::order_fit_points(result, IntegratorKind::Rk45);
  ASSERT_EQ(rk45.size(), 2u);
  EXPECT_NEAR(analysis::observed_order(rk45).fitted, 1.0, 1e-9);  // error ∝ tolerance
}

TEST(OrderFitPoints, TheSummaryReportsTheFittedOrders) {
  const std::string summary = analysis::accuracy_summary(sweep());
  EXPECT_NE(summary.find("observed order over 3 of 4 runs ok"), std::string::npos) << summary;
  EXPECT_NE(summary.find("pairwise 4.00, 4.00; least squares 4.00 +- 0.00"), std::string::npos) << summary;
  EXPECT_NE(summary.find("error ~ tolerance^p over 2 of 2 runs ok"), std::string::npos) << summary;
  EXPECT_NE(summary.find("euler: 2 runs ok"), std::string::npos) << summary;
}

}  // namespace
