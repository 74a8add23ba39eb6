// A body's breathing mode (sim/step/breathing_mode.hpp), which `softbody info` prints and warns on: its frequency is
// the period at which the model's volume swings, and vbd's converged steps damp it at BDF2's own ratio.
#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "sim/forces/forces.hpp"
#include "sim/step/breathing_mode.hpp"
#include "support.hpp"

namespace {

// The peers' breathing ball (bench/peers/breathing.json) at icosphere:2: no gravity, floor or dampers, started at its
// rest shape, so the gas swells it and it breathes about its inflated shape undamped.
constexpr const char* kUndampedBall = R"({
  "gravity": [0, 0, 0],
  "bodies": [ { "mesh": "icosphere:2", "mass": 1.0, "stiffness": 1000.0, "damping": 0.0, "pressure": 50.0 } ]
})";

sim::BreathingMode mode_of(const sim::World& world) {
  const sim::Body& body = world.model.bodies[0];
  return sim::breathing_mode(body, world.model.of(body, world.state.x));
}

// The volume every `sample_s` over `duration_s`, the world stepped by `dt` (which divides sample_s).
std::vector<double> volume_history(sim::World& world, double duration_s, double sample_s, double dt) {
  std::vector<double> volumes;
  const auto samples = static_cast<long long>(std::llround(duration_s / sample_s));
  for (long long k = 0; k < samples; ++k) {
    integrator_tests::run_for(world, sample_s, dt);
    volumes.push_back(sim::enclosed_volume(world.model.bodies[0].topology.faces, world.state.x));
  }
  return volumes;
}

// The swing's half heights (maximum − the next minimum) / 2 at the maxima's sample indices from `first`.
struct Swings {
  std::vector<double> at, half_height;
};
Swings swings(const std::vector<double>& v, std::size_t first) {
  Swings s;
  for (std::size_t i = std::max<std::size_t>(first, 1); i + 1 < v.size(); ++i) {
    if (!(v[i] > v[i - 1] && v[i] >= v[i + 1])) continue;
    std::size_t j = i + 1;
    while (j + 1 < v.size() && !(v[j] < v[j - 1] && v[j] <= v[j + 1])) ++j;
    if (j + 1 >= v.size()) break;
    s.at.push_back(static_cast<double>(i));
    s.half_height.push_back(0.5 * (v[i] - v[j]));
  }
  return s;
}

// The least-squares slope of y over x.
double slope(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    sx += x[k];
    sy += y[k];
    sxx += x[k] * x[k];
    sxy += x[k] * y[k];
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

// rk4 at 0.1 ms (about 1/300 of the period) is the model's motion: the volume swings at 2π/ω, and keeps its height.
TEST(BreathingMode, IsThePeriodAtWhichTheModelsVolumeSwings) {
  sim::World world = integrator_tests::make_world(kUndampedBall, sim::IntegratorKind::Rk4);
  const sim::BreathingMode mode = mode_of(world);
  EXPECT_EQ(mode.damping_ratio, 0.0);
  constexpr double kSample = 5e-4;
  const std::vector<double> v = volume_history(world, 0.5, kSample, 1e-4);
  const Swings s = swings(v, 20);
  ASSERT_GE(s.at.size(), 10u);
  const double period = kSample * (s.at.back() - s.at.front()) / static_cast<double>(s.at.size() - 1);
  std::printf("breathing mode %.2f rad/s: period %.5f s predicted, %.5f s measured over %zu swings\n", mode.omega,
              2.0 * std::numbers::pi / mode.omega, period, s.at.size());
  EXPECT_NEAR(period * mode.omega / (2.0 * std::numbers::pi), 1.0, 0.01);
  EXPECT_NEAR(s.half_height.back() / s.half_height.front(), 1.0, 0.05) << "the model does not damp it";
}

// With dampers (the bounce's ball: c = 1 N s/m, nRT 200 J; ζ ≈ 0.1) each swing is e^(−2π ζ/√(1 − ζ²)) of the one
// before.
TEST(BreathingMode, DampingRatioIsTheSwingsDecay) {
  constexpr const char* kDampedBall = R"({
    "gravity": [0, 0, 0],
    "bodies": [ { "mesh": "icosphere:2", "mass": 1.0, "stiffness": 1000.0, "damping": 1.0, "pressure": 200.0 } ]
  })";
  sim::World world = integrator_tests::make_world(kDampedBall, sim::IntegratorKind::Rk4);
  const sim::BreathingMode mode = mode_of(world);
  const std::vector<double> v = volume_history(world, 0.2, 2e-4, 1e-4);
  const Swings s = swings(v, 0);
  ASSERT_GE(s.at.size(), 4u);
  const double zeta = mode.damping_ratio;
  const double predicted = std::exp(-2.0 * std::numbers::pi * zeta / std::sqrt(1.0 - zeta * zeta));
  const double measured = std::pow(s.half_height[3] / s.half_height[0], 1.0 / 3.0);
  std::printf("damping ratio %.4f: each swing %.4f of the one before predicted, %.4f measured\n", zeta, predicted,
              measured);
  EXPECT_GT(zeta, 0.05);
  EXPECT_NEAR(measured / predicted, 1.0, 0.03);
}

// A BDF2 step of ẏ = i ω y multiplies y by ξ, a root of (3/2 − i z) ξ² − 2 ξ + ½ = 0 (z = ω h); the recurrence itself,
// run until the smaller root has died out, shrinks |y| by e^(−ζ z) per step.
TEST(BreathingMode, Bdf2DampingRatioIsTheRecurrencesDecay) {
  using Complex = std::complex<double>;
  for (const double z : {0.1, 0.26, 1.0, 3.3}) {
    Complex older(1.0, 0.0), previous = std::exp(Complex(0.0, z)), next;  // exact history
    for (int n = 0; n < 400; ++n) {
      next = (2.0 * previous - 0.5 * older) / Complex(1.5, -z);
      older = previous;
      previous = next;
    }
    const double per_step = std::abs(previous) / std::abs(older);
    EXPECT_NEAR(sim::bdf2_damping_ratio(z), -std::log(per_step) / z, 1e-9 * sim::bdf2_damping_ratio(z)) << z;
  }
  EXPECT_EQ(sim::bdf2_damping_ratio(0.0), 0.0);
}

// vbd at a fixed step of 1.25 ms (ω h ≈ 0.26) with its sweeps converged (32 at 162 vertices) is BDF2, so the undamped
// breathing decays at BDF2's rate ζ(ω h) ω and no faster: what `info` warns of where h is a whole frame.
TEST(BreathingMode, VbdDampsItAtBdf2sRatio) {
  sim::Solver solver;
  solver.integrator = sim::IntegratorKind::Vbd;
  solver.iterations = 32;
  sim::World world = integrator_tests::make_world(kUndampedBall, solver);
  const sim::BreathingMode mode = mode_of(world);
  constexpr double kStep = 1.25e-3;
  const std::vector<double> v = volume_history(world, 1.0, kStep, kStep);
  const Swings s = swings(v, 40);
  ASSERT_GE(s.at.size(), 20u);
  std::vector<double> log_height;
  for (const double h : s.half_height) log_height.push_back(std::log(h));
  const double measured = -slope(s.at, log_height) / kStep;  // [1/s]
  const double predicted = sim::bdf2_damping_ratio(mode.omega * kStep) * mode.omega;
  std::printf("vbd at omega h = %.3f: the breathing decays at %.4f 1/s, BDF2's ratio gives %.4f 1/s\n",
              mode.omega * kStep, measured, predicted);
  EXPECT_NEAR(measured / predicted, 1.0, 0.05);
}

}  // namespace
