// One vertex's terms of vbd's step energy (sim/integrators/vertex_energy.hpp) against finite differences of the
// energy's change along its moves: the gradient, and the Hessian block with the gas's rank-one part nRT g gᵀ/V², the
// springs, the dampers, the inertia and the smooth floor's spring, dashpot and friction. Where every spring is
// stretched the block is E's exact Hessian; a compressed spring's transverse curvature is clamped at zero instead.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include "sim/forces/forces.hpp"
#include "sim/integrators/vertex_energy.hpp"
#include "support.hpp"

namespace {

using softbody::Vec3;

// A pressurised ball pressed 2 cm into the smooth floor with friction and sliding sideways.
constexpr const char* kPressedBall = R"({
  "gravity": [0, -9.81, 0],
  "floor": { "height": 0.0, "contact": "smooth", "restitution": 0.5, "friction": 0.5, "smoothing": 0.01 },
  "bodies": [ { "mesh": "icosphere:2", "position": [0, 0.98, 0], "velocity": [1.5, -0.3, 0.5],
                "mass": 1.0, "stiffness": 500.0, "damping": 0.5, "pressure": 100.0 } ]
})";

struct Fixture {
  sim::World world;
  sim::VertexBlocks blocks;
  std::vector<Vec3> target, base;
  std::optional<sim::SmoothFloor> floor;
  double h_hat = 2.0 / 3.0 / 60.0;

  explicit Fixture(double scale) : world(make(scale)), blocks(sim::vertex_blocks(world.model.bodies[0])) {
    const std::vector<Vec3>& x = world.state.x;
    for (std::size_t i = 0; i < x.size(); ++i) {  // a step's targets near x, not at it: every term has a slope
      const double phase = static_cast<double>(i);
      base.push_back(x[i] - 0.6 * h_hat * world.state.v[i]);
      target.push_back(x[i] + Vec3(0.01 * std::sin(3.0 * phase), -0.02, 0.01 * std::cos(5.0 * phase)));
    }
    floor = sim::resolve_smooth_floor(*world.model.floor);
  }
  static sim::World make(double scale) {
    sim::Solver solver;
    solver.integrator = sim::IntegratorKind::Vbd;
    sim::World world = integrator_tests::make_world(kPressedBall, solver);
    Vec3 centre = Vec3::Zero();
    for (const Vec3& p : world.state.x) centre += p / static_cast<double>(world.state.x.size());
    for (Vec3& p : world.state.x) p = centre + scale * (p - centre);
    return world;
  }
  sim::BodySolve solve() const {
    const sim::Body& body = world.model.bodies[0];
    sim::BodySolve s{blocks, world.model.mass_kg,   target,       base,    h_hat,
                     0.0,    1.0 / (h_hat * h_hat), std::nullopt, &*floor, {}};
    s.gas = sim::GasLaw{body.params.pressure_J, sim::guarded_volume(0.0, body.rest.volume_m3)};
    return s;
  }
};

// The largest relative difference of vertex i's gradient and Hessian block from central differences of E's change.
struct Differences {
  double gradient = 0.0, hessian = 0.0;
};

Differences against_finite_differences(const Fixture& f, int i) {
  const sim::BodySolve s = f.solve();
  const std::span<const Vec3> x = f.world.state.x;
  const double volume = sim::enclosed_volume(f.world.model.bodies[0].topology.faces, f.world.state.x);
  sim::ConstraintLags lags;
  lags.resize(static_cast<std::size_t>(f.blocks.most_constraints));
  const sim::VertexTerms terms = sim::vertex_terms(s, i, x, volume, lags);
  auto change = [&](const Vec3& step) { return sim::vertex_energy_change(s, i, x, volume, terms, lags, step); };
  constexpr double kStep = 1e-5;  // m
  const Eigen::Matrix3d hessian =
      (Eigen::Matrix3d() << terms.hessian.xx, terms.hessian.xy, terms.hessian.xz, terms.hessian.xy, terms.hessian.yy,
       terms.hessian.yz, terms.hessian.xz, terms.hessian.yz, terms.hessian.zz)
          .finished();
  Differences worst;
  for (int a = 0; a < 3; ++a) {
    const Vec3 ea = kStep * Vec3::Unit(a);
    const double slope = (change(ea) - change(-ea)) / (2.0 * kStep);
    worst.gradient = std::max(worst.gradient, std::abs(slope - terms.gradient[a]) / terms.gradient.norm());
    for (int b = 0; b < 3; ++b) {
      const Vec3 eb = kStep * Vec3::Unit(b);
      const double curvature =
          (change(ea + eb) - change(ea - eb) - change(-ea + eb) + change(-ea - eb)) / (4.0 * kStep * kStep);
      worst.hessian = std::max(worst.hessian, std::abs(curvature - hessian(a, b)) / hessian.norm());
    }
  }
  return worst;
}

// Inflated to 1.05 of its size every spring is stretched: the block is the exact Hessian. Every vertex below the floor
// and a sample of the others.
TEST(VbdVertexEnergy, GradientAndHessianMatchFiniteDifferences) {
  const Fixture f(1.05);
  Differences worst;
  int touching = 0;
  for (int i = 0; i < static_cast<int>(f.world.state.x.size()); ++i) {
    const bool below = f.world.state.x[static_cast<std::size_t>(i)].y() < 0.0;
    if (!below && i % 7 != 0) continue;
    touching += below ? 1 : 0;
    const Differences d = against_finite_differences(f, i);
    worst.gradient = std::max(worst.gradient, d.gradient);
    worst.hessian = std::max(worst.hessian, d.hessian);
  }
  std::printf("%d vertices below the floor; worst relative difference: gradient %.2e, Hessian %.2e\n", touching,
              worst.gradient, worst.hessian);
  ASSERT_GT(touching, 0) << "some vertices press into the floor";
  EXPECT_LT(worst.gradient, 1e-7);
  EXPECT_LT(worst.hessian, 1e-5);
}

// The gas's part alone: V is affine in one vertex, so −nRT ln V has the local Hessian nRT g gᵀ / V² exactly, and the
// block holds it (without gas the same vertex's block differs by that rank-one term).
TEST(VbdVertexEnergy, TheGasAddsItsRankOneTerm) {
  const Fixture f(1.05);
  sim::BodySolve with_gas = f.solve();
  sim::BodySolve without_gas = f.solve();
  without_gas.gas.reset();
  const double volume = sim::enclosed_volume(f.world.model.bodies[0].topology.faces, f.world.state.x);
  sim::ConstraintLags lags;
  lags.resize(static_cast<std::size_t>(f.blocks.most_constraints));
  constexpr int kVertex = 5;
  const sim::VertexTerms a = sim::vertex_terms(with_gas, kVertex, f.world.state.x, volume, lags);
  const sim::VertexTerms b = sim::vertex_terms(without_gas, kVertex, f.world.state.x, volume, lags);
  const Vec3 g = a.volume_gradient;
  const double nRT = f.world.model.bodies[0].params.pressure_J, w = nRT / (volume * volume);
  const double round_off = 1e-14 * (a.hessian.xx + a.hessian.yy + a.hessian.zz);  // of the whole block [N/m]
  std::printf("gas term nRT/V² |g|² = %.3e N/m of a block with trace %.3e N/m\n", w * g.squaredNorm(),
              a.hessian.xx + a.hessian.yy + a.hessian.zz);
  EXPECT_NEAR(a.hessian.xx - b.hessian.xx, w * g.x() * g.x(), round_off);
  EXPECT_NEAR(a.hessian.xy - b.hessian.xy, w * g.x() * g.y(), round_off);
  EXPECT_NEAR(a.hessian.yz - b.hessian.yz, w * g.y() * g.z(), round_off);
  // The same from finite differences of the energy's change with and without the gas.
  const sim::VertexTerms a_again = sim::vertex_terms(with_gas, kVertex, f.world.state.x, volume, lags);
  auto gas_change = [&](const Vec3& step) {
    return sim::vertex_energy_change(with_gas, kVertex, f.world.state.x, volume, a_again, lags, step) -
           sim::vertex_energy_change(without_gas, kVertex, f.world.state.x, volume, b, lags, step);
  };
  constexpr double kStep = 1e-4;  // m
  double worst = 0.0;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      const Vec3 er = kStep * Vec3::Unit(r), ec = kStep * Vec3::Unit(c);
      const double curvature =
          (gas_change(er + ec) - gas_change(er - ec) - gas_change(-er + ec) + gas_change(-er - ec)) /
          (4 * kStep * kStep);
      worst = std::max(worst, std::abs(curvature - w * g[r] * g[c]) / (w * g.squaredNorm()));
    }
  }
  std::printf("the gas's curvature from finite differences: worst relative difference %.2e\n", worst);
  EXPECT_LT(worst, 1e-5);
  const Vec3 pressure_force = a.gradient - b.gradient;  // −P g
  EXPECT_LT((pressure_force + nRT / volume * g).norm(), 1e-14 * a.gradient.norm() + 1e-12 * nRT / volume * g.norm());
}

// Shrunk to 0.9, every spring is compressed: the block's transverse curvature is clamped, so it exceeds E's curvature
// by k (L0/l − 1) per spring across it, and stays positive definite.
TEST(VbdVertexEnergy, CompressedSpringsAreClampedPositive) {
  const Fixture f(0.9);
  const sim::BodySolve s = f.solve();
  const double volume = sim::enclosed_volume(f.world.model.bodies[0].topology.faces, f.world.state.x);
  sim::ConstraintLags lags;
  lags.resize(static_cast<std::size_t>(f.blocks.most_constraints));
  for (int i = 0; i < static_cast<int>(f.world.state.x.size()); i += 5) {
    const sim::VertexTerms t = sim::vertex_terms(s, i, f.world.state.x, volume, lags);
    const Eigen::Matrix3d h = (Eigen::Matrix3d() << t.hessian.xx, t.hessian.xy, t.hessian.xz, t.hessian.xy,
                               t.hessian.yy, t.hessian.yz, t.hessian.xz, t.hessian.yz, t.hessian.zz)
                                  .finished();
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(h).eigenvalues().minCoeff(), 0.0) << "vertex " << i;
  }
  EXPECT_GT(against_finite_differences(f, 0).hessian, 1e-3)
      << "the clamp changes the block (so the test above can fail)";
}

// A Newton step that sure_descent lets skip the line search lowers E by at least a quarter of its slope (so by far more
// than the search's Armijo condition asks): compressed (buckling), rest-size and stretched balls on the floor, at steps
// from 1/960 to 1/15 s (the larger the step, the weaker the inertia and the longer the Newton step).
TEST(VbdVertexEnergy, SureDescentOnlyWhereTheStepLowersTheEnergy) {
  int sure = 0, unsure = 0;
  double least_ratio = 1.0;  // the smallest ΔE / (∇E·Δ) of a sure step (the bound says ≥ ¼)
  for (const double scale : {0.9, 0.98, 1.0, 1.05}) {
    for (const double h : {1.0 / 960.0, 1.0 / 60.0, 1.0 / 15.0}) {
      Fixture f(scale);
      f.h_hat = 2.0 * h / 3.0;
      const sim::BodySolve s = f.solve();
      const double volume = sim::enclosed_volume(f.world.model.bodies[0].topology.faces, f.world.state.x);
      sim::ConstraintLags lags;
      lags.resize(static_cast<std::size_t>(f.blocks.most_constraints));
      for (int i = 0; i < static_cast<int>(f.world.state.x.size()); ++i) {
        const sim::VertexTerms t = sim::vertex_terms(s, i, f.world.state.x, volume, lags);
        const Vec3 step = -t.hessian.solve(t.gradient);
        const double slope = t.gradient.dot(step);
        if (!sim::sure_descent(s, t, f.world.state.x[static_cast<std::size_t>(i)], volume, step, slope)) {
          ++unsure;
          continue;
        }
        ++sure;
        const double change = sim::vertex_energy_change(s, i, f.world.state.x, volume, t, lags, step);
        least_ratio = std::min(least_ratio, change / slope);
        EXPECT_LE(change, sim::kArmijo * slope) << "scale " << scale << ", h " << h << ", vertex " << i;
      }
    }
  }
  std::printf("%d sure steps, %d searched; the least decrease of a sure step: %.3f of its slope\n", sure, unsure,
              least_ratio);
  EXPECT_GT(sure, 0);
  EXPECT_GT(unsure, 0);
  EXPECT_GE(least_ratio, 0.25 - 1e-6);
}

}  // namespace
