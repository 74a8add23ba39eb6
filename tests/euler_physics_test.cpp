// Forward Euler (the paper's integrator) against closed forms: oscillator, free fall, conservation laws.
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "sim/step/diagnostics.hpp"
#include "sim/step/world.hpp"
#include "test_helpers.hpp"

namespace {

using softbody::Vec3;
using testing_support::run_steps;
using testing_support::world_from_text;

// Two particles of mass m joined by one spring of stiffness k along x, released stretched by `amplitude`.
sim::World two_particle_spring(double m, double k, double rest_length, double amplitude) {
  sim::Body body;
  body.topology.edges = {{0, 1}};
  body.rest.edge_length_m = {rest_length};
  body.masses.kg = {m, m};
  body.masses.inverse = {1 / m, 1 / m};
  body.masses.total_kg = 2 * m;
  body.params = sim::Params{k, 0.0, 0.0};
  return sim::one_body_world(Vec3::Zero(), std::nullopt, sim::Solver{sim::IntegratorKind::Euler}, std::move(body),
                             {Vec3::Zero(), Vec3(rest_length + amplitude, 0, 0)}, Vec3::Zero());
}

double stretch(const sim::World& world) { return (world.state.x[1] - world.state.x[0]).x() - 1.0; }

TEST(TwoParticleSpring, EnergyGrowsByExactlyOnePlusHSquaredOmegaSquaredPerStep) {
  const double m = 1.0, k = 100.0, h = 1e-3;
  const double omega = std::sqrt(k / (m / 2));  // reduced mass μ = m/2
  sim::World world = two_particle_spring(m, k, 1.0, 0.1);
  const double e0 = sim::diagnose(world.model, world.state, 0).total_J();
  const int n = 2000;
  run_steps(world, n, h);
  const double expected = e0 * std::pow(1 + h * h * omega * omega, n);
  EXPECT_NEAR(sim::diagnose(world.model, world.state, 0).total_J() / expected, 1.0, 1e-10);
}

TEST(TwoParticleSpring, PeriodMatchesClosedFormAndEulersDiscretePeriod) {
  const double m = 1.0, k = 100.0, h = 1e-4;
  const double omega = std::sqrt(k / (m / 2));
  sim::World world = two_particle_spring(m, k, 1.0, 0.1);
  // Upward zero crossings of the stretch, linearly interpolated.
  std::vector<double> crossings;
  double previous = stretch(world);
  for (int step = 1; step <= 12000; ++step) {
    world.step(h);
    const double current = stretch(world);
    if (previous < 0 && current >= 0) crossings.push_back(h * (step - 1 + previous / (previous - current)));
    previous = current;
  }
  ASSERT_GE(crossings.size(), 2u);
  const double measured = (crossings.back() - crossings.front()) / double(crossings.size() - 1);
  // Closed form 2π/ω; forward Euler rotates the phase by atan(hω) per step, so its period is
  // 2π h / atan(hω) = (2π/ω)(1 + (hω)²/3 + ...): relative difference 7e-7 here.
  const double closed_form = 2 * std::numbers::pi / omega;
  const double discrete = 2 * std::numbers::pi * h / std::atan(h * omega);
  EXPECT_NEAR(measured / discrete, 1.0, 1e-6);
  EXPECT_NEAR(measured / closed_form, 1.0, 1e-5);
}

constexpr const char* kSphereNoFloor = R"({
  "gravity": [0, -9.81, 0],
  "bodies": [ { "mesh": "icosphere:2", "position": [0, 3, 0], "velocity": [1, 2, 0],
                "mass": 1.0, "stiffness": 500.0, "damping": 2.0, "pressure": 60.0 } ] })";

// With internal forces summing to zero, the centre of mass follows Euler's discrete free fall exactly:
// x_n = x_0 + n h v_0 + h² g n(n−1)/2.
TEST(FreeFall, CentreOfMassFollowsEulersDiscreteSolution) {
  sim::World world = world_from_text(kSphereNoFloor);
  const sim::BodyDiagnostics start = sim::diagnose(world.model, world.state, 0);
  const double h = 1e-4;
  const int n = 3000;
  run_steps(world, n, h);
  const Vec3 g(0, -9.81, 0);
  const Vec3 expected = start.com_m + n * h * start.com_velocity_m_per_s + h * h * g * (n * (n - 1) / 2.0);
  const sim::BodyDiagnostics end = sim::diagnose(world.model, world.state, 0);
  EXPECT_LT((end.com_m - expected).norm(), 1e-11) << end.com_m.transpose() << " vs " << expected.transpose();
  EXPECT_LT((end.com_velocity_m_per_s - (start.com_velocity_m_per_s + n * h * g)).norm(), 1e-10);
}

constexpr const char* kBreathingSphere = R"({
  "gravity": [0, 0, 0],
  "bodies": [ { "mesh": "icosphere:2", "mass": 1.0, "stiffness": 200.0, "damping": 0.0, "pressure": 40.0 } ] })";

TEST(Conservation, MomentumIsConstantWithoutExternalForces) {
  sim::World world = world_from_text(kBreathingSphere);
  std::mt19937 random(3);
  std::normal_distribution<double> speed(0.0, 0.5);
  for (Vec3& v : world.state.v) v = Vec3(speed(random), speed(random), speed(random));
  const Vec3 p0 = sim::diagnose(world.model, world.state, 0).momentum_kg_m_per_s;
  run_steps(world, 5000, 1e-4);
  const Vec3 p1 = sim::diagnose(world.model, world.state, 0).momentum_kg_m_per_s;
  EXPECT_LT((p1 - p0).norm(), 1e-12) << p0.transpose() << " -> " << p1.transpose();
}

// Highest angular frequency bound (Gershgorin on M⁻¹K for springs): ω²_max ≤ max_i 2 k valence_i / m_i.
double gershgorin_omega_squared(const sim::Body& body) {
  std::vector<int> valence(body.vertex_count, 0);
  for (const auto& [i, j] : body.topology.edges) {
    ++valence[i];
    ++valence[j];
  }
  double bound = 0.0;
  for (int i = 0; i < body.vertex_count; ++i) {
    bound = std::max(bound, 2.0 * body.params.stiffness_N_per_m * valence[i] * body.masses.inverse[i]);
  }
  return bound;
}

// Energy gained over `duration`, relative to the oscillation energy (the peak kinetic energy: the body
// starts at rest away from equilibrium, so all of its oscillation energy is kinetic at equilibrium).
double relative_energy_drift(double h, double duration) {
  sim::World world = world_from_text(kBreathingSphere);
  const double e0 = sim::diagnose(world.model, world.state, 0).total_J();
  double peak_kinetic = 0.0;
  for (long long n = std::llround(duration / h); n > 0; --n) {
    world.step(h);
    peak_kinetic = std::max(peak_kinetic, sim::diagnose(world.model, world.state, 0).kinetic_J);
  }
  return (sim::diagnose(world.model, world.state, 0).total_J() - e0) / peak_kinetic;
}

// Forward Euler gains energy at first order: each mode's energy grows by (1 + h²ω²) per step, so over a
// fixed time T the relative gain ≈ T h ω² (halves with h) and stays below (1 + h²ω²_max)^(T/h) − 1.
TEST(Conservation, EulerEnergyGainIsFirstOrderAndWithinItsBound) {
  // Undamped forward Euler is unstable at any step (every mode gains energy), so keep T h ω²_max small.
  const double duration = 0.05;
  const double h = 2e-6;
  const double drift_h = relative_energy_drift(h, duration);
  const double drift_half = relative_energy_drift(h / 2, duration);
  EXPECT_GT(drift_h, 0.0) << "forward Euler never loses energy without dampers";
  EXPECT_NEAR(drift_h / drift_half, 2.0, 0.2) << drift_h << " vs " << drift_half;
  sim::World world = world_from_text(kBreathingSphere);
  const double omega_squared = gershgorin_omega_squared(world.model.bodies[0]);
  const double bound = std::pow(1 + h * h * omega_squared, duration / h) - 1;
  EXPECT_LT(drift_h, bound) << "Gershgorin ω²_max = " << omega_squared;
}

}  // namespace
