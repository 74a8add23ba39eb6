// Energy behaviour without dampers or contacts: bounded for the symplectic methods, the known growth for
// forward Euler.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "sim/diagnostics.hpp"
#include "support.hpp"

namespace {

using integrator_tests::make_world;
using integrator_tests::total_energy;
using softbody::Vec3;

// A small breathing sphere without dampers, gravity or floor: total energy (kinetic + spring + gas
// −nRT ln(V/V0)) is exactly conserved by the equations of motion. It starts at rest in its spring rest
// shape at V0, where every energy term is zero, so E(0) = 0.
constexpr const char* kConservativeScene = R"({
  "gravity": [0, 0, 0],
  "bodies": [ { "mesh": "icosphere:1", "mass": 1.0, "stiffness": 500.0, "damping": 0.0, "pressure": 100.0 } ]
})";

struct EnergyTrace {
  double max_kinetic_J = 0.0;         // the scale of the motion's energy
  double max_deviation_J = 0.0;       // max |E(t) − E(0)| over the run
  double early_mean_J = 0.0;          // mean E − E(0) over the first tenth of the run
  double late_mean_J = 0.0;           // ... and the last tenth
};

EnergyTrace trace_energy(scene::Integrator integrator, double dt, long long steps) {
  sim::World world = make_world(kConservativeScene, integrator);
  const double e0 = total_energy(world);
  EnergyTrace trace;
  constexpr long long kSampleEvery = 50;
  const long long tenth = steps / 10;
  long long early_samples = 0, late_samples = 0;
  for (long long s = 1; s <= steps; ++s) {
    world.step(dt);
    if (s % kSampleEvery != 0) continue;
    const sim::BodyDiagnostics d = sim::diagnose(world, 0);
    const double deviation = d.total_J() - e0;
    trace.max_kinetic_J = std::max(trace.max_kinetic_J, d.kinetic_J);
    trace.max_deviation_J = std::max(trace.max_deviation_J, std::abs(deviation));
    if (s <= tenth) {
      trace.early_mean_J += deviation;
      ++early_samples;
    } else if (s > steps - tenth) {
      trace.late_mean_J += deviation;
      ++late_samples;
    }
  }
  trace.early_mean_J /= static_cast<double>(early_samples);
  trace.late_mean_J /= static_cast<double>(late_samples);
  return trace;
}

class BoundedEnergy : public ::testing::TestWithParam<scene::Integrator> {};

// 10^5 steps of 0.5 ms (50 s, about 170 breathing periods). A symplectic method conserves a modified
// energy within O(h^p) of the true one, so the error oscillates without drifting: it must stay a small
// fraction of the motion's energy and its mean must not move between the first and last tenth.
TEST_P(BoundedEnergy, StaysBoundedOverHundredThousandSteps) {
  const EnergyTrace trace = trace_energy(GetParam(), 5e-4, 100000);
  std::printf("%s: max |E - E0| = %.3e J (max kinetic %.3e J), mean E - E0: first tenth %.3e J, last tenth %.3e J\n",
              scene::to_string(GetParam()).c_str(), trace.max_deviation_J, trace.max_kinetic_J, trace.early_mean_J,
              trace.late_mean_J);
  EXPECT_LT(trace.max_deviation_J, 0.05 * trace.max_kinetic_J);
  EXPECT_LT(std::abs(trace.late_mean_J - trace.early_mean_J), 0.2 * trace.max_deviation_J + 1e-12);
}

INSTANTIATE_TEST_SUITE_P(SymplecticMethods, BoundedEnergy,
                         ::testing::Values(scene::Integrator::Symplectic, scene::Integrator::Verlet),
                         [](const ::testing::TestParamInfo<scene::Integrator>& test) {
                           return scene::to_string(test.param);
                         });

// Two particles of mass m on one spring along x, released stretched: a single oscillator of
// ω = sqrt(k / μ), μ = m/2. Forward Euler maps (x, v) by a matrix of determinant 1 + h²ω², and the
// energy ½ μ v² + ½ k x² by exactly that factor every step (Hairer, Lubich & Wanner, Sect. I.1).
TEST(ForwardEulerEnergy, GrowsByOnePlusHSquaredOmegaSquaredPerStep) {
  const double m = 0.5, k = 200.0, h = 1e-3, rest = 1.0;
  const double omega = std::sqrt(k / (m / 2));  // rad/s
  sim::Topology topology;
  topology.edges = {{0, 1}};
  topology.rest_length_m = {rest};
  topology.mass_kg = {m, m};
  topology.inverse_mass = {1 / m, 1 / m};
  topology.total_mass_kg = 2 * m;
  sim::World world(Vec3::Zero(), std::nullopt, scene::Integrator::Euler);
  world.add_body(topology, sim::Params{k, 0.0, 0.0}, {Vec3::Zero(), Vec3(rest + 0.05, 0, 0)}, Vec3::Zero());
  const double e0 = total_energy(world);
  const int steps = 2000;  // E grows 5×: below the divergence guard's 10× runaway limit (sim/guard.hpp)
  for (int s = 0; s < steps; ++s) world.step(h);
  const double expected = std::pow(1 + h * h * omega * omega, steps);
  const double measured = total_energy(world) / e0;
  std::printf("euler, oscillator h*omega = %.3f: E/E0 after %d steps = %.6f, (1 + h^2 omega^2)^n = %.6f\n",
              h * omega, steps, measured, expected);
  EXPECT_NEAR(measured, expected, 1e-9 * expected);
}

// On the sphere every mode grows by its own (1 + h²ω²) per step: the energy rises steadily, unlike the
// symplectic methods' bounded oscillation at the same step.
TEST(ForwardEulerEnergy, GrowsOnTheSphereWhereSymplecticMethodsStayBounded) {
  const EnergyTrace euler = trace_energy(scene::Integrator::Euler, 5e-5, 4000);
  std::printf("euler on the sphere, h = 5e-5 s, 4000 steps: mean E - E0 first tenth %.3e J, last tenth %.3e J "
              "(max kinetic %.3e J)\n",
              euler.early_mean_J, euler.late_mean_J, euler.max_kinetic_J);
  EXPECT_GT(euler.late_mean_J, euler.early_mean_J + 0.01 * euler.max_kinetic_J);
}

}  // namespace
