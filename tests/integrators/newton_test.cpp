// Backward Euler by Newton: its potential's derivatives, stability over the stiffness range at 1/60 s, energy
// behaviour, and the bounce ball's volume at 1/60 s against a converged run.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include "sim/integrators/incremental_potential.hpp"
#include "sim/integrators/newton_euler.hpp"
#include "sim/solvers/block_system.hpp"
#include "sim/step/diagnostics.hpp"
#include "support.hpp"

namespace {

using integrator_tests::make_world;
using integrator_tests::total_energy;
using integrator_tests::wiggle;
using softbody::Vec3;

const sim::NewtonEuler& newton_of(const sim::World& world) {
  return dynamic_cast<const sim::NewtonEuler&>(*world.workspace.integrator);
}

// A sphere moving and deformed, mid-step: every term of E is non-zero (pressure 0: no gas term).
std::string potential_scene(double pressure) {
  std::string text = R"({ "gravity": [0, -9.81, 0], "bodies": [ { "mesh": "icosphere:1", "mass": 1.0,
                         "stiffness": 300.0, "damping": 2.0, "pressure": )";
  text += std::to_string(pressure);
  text += "} ] }";
  return text;
}

// The potential of a step of h from a shaken state, evaluated at x = x̂ + offset · wiggle; `stretch` scales
// the start about the origin (the body's centre; > 1: every spring stretched, so no clamp is active).
struct PotentialAtAState {
  PotentialAtAState(double pressure, double stretch, double h, double offset)
      : world(make_world(potential_scene(pressure), sim::IntegratorKind::Newton)) {
    sim::State& s = world.state;
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      s.x[i] = stretch * s.x[i];
      s.v[i] = 0.3 * wiggle(i, 0.0);
    }
    potential.build(world.model);
    hessian.build(world.model.vertex_count(), potential.pairs());
    potential.begin_step(world.model, s, h);
    x.resize(s.x.size());
    for (std::size_t i = 0; i < s.x.size(); ++i) x[i] = s.x[i] + h * s.v[i] + offset * wiggle(i, 1.0);
    gradient.setZero(hessian.size());
    potential.assemble(world.model, x, sim::IncrementalPotential::Hessian::Exact, hessian, gradient);
  }

  sim::World world;
  sim::IncrementalPotential potential;
  sim::BlockSystem hessian;
  std::vector<Vec3> x;  // where E is evaluated: near x̂, off it
  Eigen::VectorXd gradient;
};

// ∇E is the backward Euler residual M(x − x̂)/h² − f(x, (x − x_n)/h); checked against central differences
// of E itself, so that the line search and the Newton system minimise the same function.
TEST(IncrementalPotential, GradientMatchesFiniteDifferencesOfTheEnergy) {
  PotentialAtAState p(/*pressure=*/40.0, /*stretch=*/1.0, /*h=*/1.0 / 60, /*offset=*/0.02);
  constexpr double kStep = 1e-6;  // m: central differences err by O(kStep²)·E''' and ε|E|/kStep
  double worst = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < p.x.size(); i += 5) {
    for (int c = 0; c < 3; ++c) {
      std::vector<Vec3> plus = p.x, minus = p.x;
      plus[i][c] += kStep;
      minus[i][c] -= kStep;
      double energy_scale = 0.0;
      const double numeric = (p.potential.energy(p.world.model, plus, energy_scale) -
                              p.potential.energy(p.world.model, minus, energy_scale)) /
                             (2.0 * kStep);
      const double analytic = p.gradient[p.hessian.dof(static_cast<int>(i)) + c];
      worst = std::max(worst, std::abs(numeric - analytic));
      scale = std::max(scale, std::abs(analytic));
    }
  }
  std::printf("max |dE/dx numeric - analytic| = %.3e N (largest component %.3e N)\n", worst, scale);
  EXPECT_LT(worst, 1e-6 * scale);
}

// The exact Hessian (sparse part plus the gas's rank-one terms u uᵀ) is the derivative of the gradient:
// checked along a non-smooth direction r against central differences of ∇E, with gas, dampers and springs
// both stretched and compressed.
TEST(IncrementalPotential, ExactHessianIsTheDerivativeOfTheGradient) {
  PotentialAtAState p(/*pressure=*/40.0, /*stretch=*/1.0, /*h=*/1.0 / 60, /*offset=*/0.02);
  ASSERT_FALSE(p.potential.gas_terms().empty());
  Eigen::VectorXd r(p.hessian.size());
  for (Eigen::Index k = 0; k < r.size(); ++k) r[k] = std::sin(1.7 * static_cast<double>(k));
  const double error = integrator_tests::hessian_mismatch(p.potential, p.world.model, p.hessian, p.x, r, /*step=*/1e-6);
  std::printf("|d(grad E)/dr - H r| / |H r| = %.3e\n", error);
  EXPECT_LT(error, 1e-7);
}

// The smallest eigenvalue of the assembled Hessian's sparse part plus the gas's rank-one terms, from the dense
// matrix (a small mesh: 42 vertices) [N/m].
double smallest_eigenvalue(const PotentialAtAState& p) {
  const Eigen::Index n = p.hessian.size();
  Eigen::MatrixXd dense(n, n);
  Eigen::VectorXd unit = Eigen::VectorXd::Zero(n), column(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    unit[k] = 1.0;
    p.hessian.multiply(unit, column);
    dense.col(k) = column;
    unit[k] = 0.0;
  }
  for (const sim::IncrementalPotential::GasTerm& term : p.potential.gas_terms()) {
    Eigen::VectorXd u = Eigen::VectorXd::Zero(n);
    for (std::size_t i = 0; i < term.direction.size(); ++i)
      u.segment<3>(p.hessian.dof(static_cast<int>(i))) = term.direction[i];
    dense += u * u.transpose();
  }
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(dense).eigenvalues().minCoeff();
}

// Compressed springs make the exact Hessian indefinite at a large step; the definite form (clamped springs,
// projected gas curvature) must then be positive definite: at least the inertia M/h² in every direction.
TEST(IncrementalPotential, DefiniteFormIsPositiveDefiniteWhereTheExactOneIsNot) {
  PotentialAtAState p(/*pressure=*/40.0, /*stretch=*/0.7, /*h=*/0.1, /*offset=*/0.0);
  const double exact = smallest_eigenvalue(p);
  p.potential.assemble(p.world.model, p.x, sim::IncrementalPotential::Hessian::Definite, p.hessian, p.gradient);
  const double definite = smallest_eigenvalue(p);
  const double inertia = *std::min_element(p.world.model.mass_kg.begin(), p.world.model.mass_kg.end()) / (0.1 * 0.1);
  std::printf("smallest eigenvalue: exact %.4g N/m, definite %.4g N/m (min m/h^2 = %.4g N/m)\n", exact, definite,
              inertia);
  EXPECT_LT(exact, 0.0) << "the exact Hessian of a sphere squeezed to 0.7 of its size is indefinite";
  EXPECT_GE(definite, inertia * (1.0 - 1e-9));
}

// Gravity alone: E is quadratic, one Newton step solves it exactly, and backward Euler for a constant force
// is symplectic Euler's update: it leads the parabola by ½ g h t.
TEST(NewtonFreeFall, MissesByHalfGHTLikeEveryFirstOrderMethod) {
  sim::World world = make_world(R"({ "gravity": [0, -9.81, 0],
    "bodies": [ { "mesh": "icosphere:1", "position": [0, 5, 0], "velocity": [1.5, 4, -0.5], "mass": 1.0,
                  "stiffness": 0.0, "damping": 0.0, "pressure": 0.0 } ] })",
                                sim::IntegratorKind::Newton);
  const Vec3 x0 = world.state.x[0], v0(1.5, 4, -0.5), g(0, -9.81, 0);
  constexpr double kDt = 1e-3, kDuration = 1.0;
  integrator_tests::run_for(world, kDuration, kDt);
  const Vec3 leading =
      x0 + v0 * kDuration + 0.5 * g * kDuration * (kDuration + kDt);  // x_n = x0 + v0 t + ½ g t (t + h)
  // v' = (x' − x_n)/h loses ε|x|/h ≈ 1e-12 m/s a step to cancellation at x ≈ 5 m: 1e-9 m after 1000 steps.
  EXPECT_LT((world.state.x[0] - leading).norm(), 1e-9);
  EXPECT_EQ(newton_of(world).statistics().unconverged_steps, 0);
}

// Every stiffness from 1 N/m to 10⁶ N/m at 1/60 s steps (the explicit methods' limit at 10⁶ N/m on this mesh
// is below 10⁻⁴ s): no dampers, gravity or floor, every mode excited, 2 s. Backward Euler's numerical
// damping may only remove energy, and every step must reach the Newton tolerance.
class NewtonStiffnessRange : public ::testing::TestWithParam<double> {};

TEST_P(NewtonStiffnessRange, StableAtOneSixtiethOfASecondEnergyNeverGrows) {
  const double k = GetParam();
  std::string scene = R"({ "gravity": [0, 0, 0], "bodies": [ { "mesh": "icosphere:2", "mass": 1.0, "stiffness": )";
  scene += std::to_string(k);
  scene += R"(, "damping": 0.0, "pressure": 100.0 } ] })";
  sim::World world = make_world(scene, sim::IntegratorKind::Newton);
  for (std::size_t i = 0; i < world.state.v.size(); ++i) world.state.v[i] = 0.5 * wiggle(i, 0.0);
  const double e0 = total_energy(world);
  double highest = e0;
  constexpr double kDt = 1.0 / 60;
  for (int s = 0; s < 120; ++s) {
    ASSERT_NO_THROW(world.step(kDt)) << "step " << s;
    highest = std::max(highest, total_energy(world));
  }
  const sim::NewtonEuler::Statistics& stats = newton_of(world).statistics();
  std::printf(
      "k = %.0e N/m: E0 = %.4f J, highest %.4f J, end %.4f J; Newton iterations %.2f per step (most %d), "
      "%lld halvings, %lld unconverged\n",
      k, e0, highest, total_energy(world), static_cast<double>(stats.iterations) / static_cast<double>(stats.steps),
      stats.most_iterations, stats.halvings, stats.unconverged_steps);
  EXPECT_LE(highest, e0 + 1e-9 * std::abs(e0));
  EXPECT_EQ(stats.unconverged_steps, 0);
}

INSTANTIATE_TEST_SUITE_P(OneToAMillionNewtonsPerMetre, NewtonStiffnessRange,
                         ::testing::Values(1.0, 10.0, 100.0, 1e3, 1e4, 1e5, 1e6),
                         [](const ::testing::TestParamInfo<double>& test) {
                           std::string name = "k";
                           name += std::to_string(static_cast<long long>(test.param));
                           return name;
                         });

// Backward Euler's numerical damping is first order: an undamped mode of frequency ω keeps |1/(1 + ihω)|² =
// 1/(1 + h²ω²) of its energy per step, e^(−h ω² t) to leading order. On a conservative breathing sphere (no
// dampers, gravity or floor: the exact energy is constant; the gas excites every mode, up to ω_max ≈ 400 rad/s)
// over 20 ms with h ω_max² t < 0.1, the energy lost halves with the step, while the energy never rises above
// its start.
TEST(NewtonEnergy, NumericalDampingHalvesWithTheStep) {
  constexpr double kDuration = 0.02;  // s
  auto energy_lost = [](double dt) {
    sim::World world = make_world(R"({ "gravity": [0, 0, 0],
      "bodies": [ { "mesh": "icosphere:1", "mass": 1.0, "stiffness": 500.0, "damping": 0.0, "pressure": 100.0 } ] })",
                                  sim::IntegratorKind::Newton);
    const double e0 = total_energy(world);
    double highest = e0;
    for (int s = 0; s < static_cast<int>(std::lround(kDuration / dt)); ++s) {
      world.step(dt);
      highest = std::max(highest, total_energy(world));
    }
    EXPECT_LE(highest, e0 + 1e-9);
    return e0 - total_energy(world);
  };
  const double coarse = energy_lost(2e-5), fine = energy_lost(1e-5);
  std::printf("energy lost in %.0f ms: %.4e J at 2e-5 s, %.4e J at 1e-5 s, ratio %.3f\n", 1e3 * kDuration, coarse, fine,
              coarse / fine);
  EXPECT_GT(fine, 0.0);
  EXPECT_NEAR(coarse / fine, 2.0, 0.15);
}

}  // namespace
