// Newton with the smooth floor inside its potential: the floor terms' derivatives, no pass-through of a ball
// thrown at the floor at 5 m/s with 1/60 s steps, and first-order convergence through an impact.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "sim/forces/energy.hpp"
#include "sim/integrators/incremental_potential.hpp"
#include "sim/integrators/newton_euler.hpp"
#include "sim/solvers/block_system.hpp"
#include "support.hpp"

namespace {

using integrator_tests::make_world;
using integrator_tests::wiggle;
using softbody::Vec3;

// A unit sphere sunk 0.1 m into the smooth floor (its lowest ring of vertices 0 to 10 cm deep, some inside the
// 2 mm smoothing depth), sliding sideways: every floor term of E is non-zero.
std::string sunk_scene(double friction, double restitution) {
  return R"({ "gravity": [0, -9.81, 0], "floor": { "contact": "smooth", "friction": )" + std::to_string(friction) +
         R"(, "restitution": )" + std::to_string(restitution) + R"( },
    "bodies": [ { "mesh": "icosphere:2", "position": [0, 0.9, 0], "mass": 1.0, "stiffness": 300.0,
                  "damping": 2.0, "pressure": 40.0 } ] })";
}

// E of a step of h from the sunk sphere moving at v = (1, −0.5, 0.3) m/s + 0.2 wiggle, assembled at
// x = x̂ + 0.01 wiggle, with the floor's lagged weights taken there.
struct SunkPotential {
  SunkPotential(double friction, double restitution, double h)
      : world(make_world(sunk_scene(friction, restitution), sim::IntegratorKind::Newton)) {
    sim::State& s = world.state;
    for (std::size_t i = 0; i < s.x.size(); ++i) s.v[i] = Vec3(1.0, -0.5, 0.3) + 0.2 * wiggle(i, 0.0);
    potential.build(world.model);
    hessian.build(world.model.vertex_count(), potential.pairs());
    potential.begin_step(world.model, s, h);
    x.resize(s.x.size());
    for (std::size_t i = 0; i < s.x.size(); ++i) x[i] = s.x[i] + h * s.v[i] + 0.01 * wiggle(i, 1.0);
    gradient.setZero(hessian.size());
    potential.update_lags(world.model, x);
    potential.assemble(world.model, x, sim::IncrementalPotential::Hessian::Exact, hessian, gradient);
  }
  int vertices_below() const {
    return static_cast<int>(std::count_if(x.begin(), x.end(), [](const Vec3& p) { return p.y() < 0.0; }));
  }

  sim::World world;
  sim::IncrementalPotential potential;
  sim::BlockSystem hessian;
  std::vector<Vec3> x;
  Eigen::VectorXd gradient;
};

// With the lagged dashpot weights and friction forces held, ∇E (floor terms included) is the derivative of E:
// central differences of E at the vertices below the floor.
TEST(NewtonFloorPotential, GradientMatchesFiniteDifferencesOfTheEnergy) {
  SunkPotential p(/*friction=*/0.5, /*restitution=*/0.5, /*h=*/1.0 / 60);
  ASSERT_GT(p.vertices_below(), 5);
  constexpr double kStep = 1e-7;  // m: small against the 2 mm smoothing depth
  std::vector<int> below;
  for (std::size_t i = 0; i < p.x.size(); ++i) {
    if (p.x[i].y() <= 0.0) below.push_back(static_cast<int>(i));
  }
  const integrator_tests::GradientMismatch m =
      integrator_tests::gradient_mismatch(p.potential, p.world.model, p.hessian, p.x, p.gradient, below, kStep);
  const double worst = m.worst_N, scale = m.scale_N;
  std::printf("%d vertices below the floor: max |dE/dx numeric - analytic| = %.3e N (largest component %.3e N)\n",
              p.vertices_below(), worst, scale);
  EXPECT_LT(worst, 1e-5 * scale);
}

// Without friction and dashpot (restitution 1: ζ = 0) nothing is lagged, and the floor's Hessian block
// m ω² s(d/δ) is the exact derivative of its gradient: checked along a direction r against central differences.
TEST(NewtonFloorPotential, SpringHessianIsTheDerivativeOfTheGradient) {
  SunkPotential p(/*friction=*/0.0, /*restitution=*/1.0, /*h=*/1.0 / 60);
  Eigen::VectorXd r(p.hessian.size());
  for (Eigen::Index k = 0; k < r.size(); ++k) r[k] = std::sin(1.7 * static_cast<double>(k));
  const double error = integrator_tests::hessian_mismatch(p.potential, p.world.model, p.hessian, p.x, r, /*step=*/1e-8);
  std::printf("|d(grad E)/dr - H r| / |H r| = %.3e\n", error);
  EXPECT_LT(error, 1e-6);
}

// The bounce ball (k 1000 N/m, c 1 N·s/m, nRT 50 J, 1 kg) thrown down at 5 m/s from 10 cm above the smooth
// floor, newton at 1/60 s: one step moves a vertex 8 cm, forty times the floor's 2 mm smoothing depth, but the
// floor is in E, so no vertex goes deeper than it does in the converged motion of the same contact (measured:
// 1.0 cm against 1.75 cm; backward Euler damps the impact), and the ball comes back up instead of passing through.
constexpr const char* kThrownDown = R"({ "gravity": [0, -9.81, 0], "floor": { "contact": "smooth" },
    "bodies": [ { "mesh": "icosphere:3", "position": [0, 1.1, 0], "velocity": [1, -5, 0], "mass": 1.0,
                  "stiffness": 1000.0, "damping": 1.0, "pressure": 50.0 } ] })";

// The deepest any vertex goes below the floor in the converged motion (rk45 at tolerance 1e-7, sampled every 1 ms) [m].
double converged_deepest(double duration_s) {
  sim::World world = make_world(kThrownDown, sim::IntegratorKind::Rk45, 1e-7);
  double deepest = 0.0;
  for (int s = 1; s <= static_cast<int>(std::lround(duration_s / 1e-3)); ++s) {
    world.advance_to(1e-3 * s);
    for (const Vec3& x : world.state.x) deepest = std::max(deepest, -x.y());
  }
  return deepest;
}

TEST(NewtonFloor, NoPassThroughAtFiveMetresPerSecondAndOneSixtiethOfASecond) {
  sim::World world = make_world(kThrownDown, sim::IntegratorKind::Newton);
  constexpr double kDt = 1.0 / 60;
  double deepest = 0.0, lowest_centre = 10.0;
  for (int s = 0; s < 90; ++s) {
    ASSERT_NO_THROW(world.step(kDt)) << "step " << s;
    for (const Vec3& x : world.state.x) deepest = std::max(deepest, -x.y());
    lowest_centre = std::min(lowest_centre, sim::centre_of_mass(world.model.bodies[0], world.state.x).y());
  }

  const auto& stats = dynamic_cast<const sim::NewtonEuler&>(*world.workspace.integrator).statistics();
  const double centre = sim::centre_of_mass(world.model.bodies[0], world.state.x).y();
  std::printf(
      "deepest vertex %.4f m below the floor (converged motion: %.4f m); centre lowest %.3f m, at 1.5 s %.3f m; Newton "
      "%.2f iterations per "
      "step (most %d), %lld unconverged\n",
      deepest, converged_deepest(0.3), lowest_centre, centre,
      static_cast<double>(stats.iterations) / static_cast<double>(stats.steps), stats.most_iterations,
      stats.unconverged_steps);
  EXPECT_LT(deepest, converged_deepest(0.3)) << "deeper than the converged motion of the same contact";
  EXPECT_GT(lowest_centre, 0.3) << "the ball was crushed or passed through";
  EXPECT_GT(centre, 0.5);
}

}  // namespace
