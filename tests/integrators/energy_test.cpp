// Energy behaviour without dampers or contacts: bounded for the symplectic methods, the known growth for
// forward Euler.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "sim/step/diagnostics.hpp"
#include "support.hpp"

namespace {

using integrator_tests::make_world;
using integrator_tests::total_energy;

// A small breathing sphere without dampers, gravity or floor: total energy (kinetic + spring + gas
// −nRT ln(V/V0)) is exactly conserved by the equations of motion. It starts at rest in its spring rest
// shape at V0, where every energy term is zero, so E(0) = 0.
constexpr const char* kConservativeScene = R"({
  "gravity": [0, 0, 0],
  "bodies": [ { "mesh": "icosphere:1", "mass": 1.0, "stiffness": 500.0, "damping": 0.0, "pressure": 100.0 } ]
})";

struct EnergyTrace {
  double max_kinetic_J = 0.0;    // the scale of the motion's energy
  double max_deviation_J = 0.0;  // max |E(t) − E(0)| over the run
  double early_mean_J = 0.0;     // mean E − E(0) over the first tenth of the run
  double late_mean_J = 0.0;      // ... and the last tenth
};

EnergyTrace trace_energy(sim::IntegratorKind integrator, double dt, long long steps) {
  sim::World world = make_world(kConservativeScene, integrator);
  const double e0 = total_energy(world);
  EnergyTrace trace;
  constexpr long long kSampleEvery = 50;
  const long long tenth = steps / 10;
  long long early_samples = 0, late_samples = 0;
  for (long long s = 1; s <= steps; ++s) {
    world.step(dt);
    if (s % kSampleEvery != 0) continue;
    const sim::BodyDiagnostics d = sim::diagnose(world.model, world.state, 0);
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

class BoundedEnergy : public ::testing::TestWithParam<sim::IntegratorKind> {};

// 10^5 steps of 0.5 ms (50 s, about 170 breathing periods). A symplectic method conserves a modified
// energy within O(h^p) of the true one, so the error oscillates without drifting: it must stay a small
// fraction of the motion's energy and its mean must not move between the first and last tenth.
TEST_P(BoundedEnergy, StaysBoundedOverHundredThousandSteps) {
  const EnergyTrace trace = trace_energy(GetParam(), 5e-4, 100000);
  std::printf("%s: max |E - E0| = %.3e J (max kinetic %.3e J), mean E - E0: first tenth %.3e J, last tenth %.3e J\n",
              sim::to_string(GetParam()).c_str(), trace.max_deviation_J, trace.max_kinetic_J, trace.early_mean_J,
              trace.late_mean_J);
  EXPECT_LT(trace.max_deviation_J, 0.05 * trace.max_kinetic_J);
  EXPECT_LT(std::abs(trace.late_mean_J - trace.early_mean_J), 0.2 * trace.max_deviation_J + 1e-12);
}

INSTANTIATE_TEST_SUITE_P(SymplecticMethods, BoundedEnergy,
                         ::testing::Values(sim::IntegratorKind::Symplectic, sim::IntegratorKind::Verlet),
                         [](const ::testing::TestParamInfo<sim::IntegratorKind>& test) {
                           return sim::to_string(test.param);
                         });

// Forward Euler's exact (1 + h²ω²) energy growth per step on a single oscillator is tested in
// tests/euler_physics_test.cpp (TwoParticleSpring.EnergyGrowsByExactlyOnePlusHSquaredOmegaSquaredPerStep).

// On the sphere every mode grows by its own (1 + h²ω²) per step: the energy rises steadily, unlike the
// symplectic methods' bounded oscillation at the same step.
TEST(ForwardEulerEnergy, GrowsOnTheSphereWhereSymplecticMethodsStayBounded) {
  const EnergyTrace euler = trace_energy(sim::IntegratorKind::Euler, 5e-5, 4000);
  std::printf(
      "euler on the sphere, h = 5e-5 s, 4000 steps: mean E - E0 first tenth %.3e J, last tenth %.3e J "
      "(max kinetic %.3e J)\n",
      euler.early_mean_J, euler.late_mean_J, euler.max_kinetic_J);
  EXPECT_GT(euler.late_mean_J, euler.early_mean_J + 0.01 * euler.max_kinetic_J);
}

}  // namespace
