// Shapes that stay: a dented ball (non-convex) dropped on the floor keeps its dent with bending links and
// loses it without; every integrator takes the links; the stable-dt estimate counts their stiffness.
#include <cmath>
#include <cstdio>
#include <limits>

#include <gtest/gtest.h>

#include "analysis/shape_deviation.hpp"
#include "core/errors.hpp"
#include "mesh/generators.hpp"
#include "sim/forces/bending.hpp"
#include "sim/step/diagnostics.hpp"
#include "sim/step/stability.hpp"
#include "sim/step/world.hpp"

namespace {

using softbody::Vec3;

// icosphere:3 (unit radius) with its cap above y = 0.3 mirrored through that plane into the ball: a bowl-shaped
// dent 0.7 m deep (a red blood cell's shape, one side). The mirrored cap lies inside the sphere (its ring at
// y = 0.3 − s has radius √(1 − (0.3 + s)²) < √(1 − (0.3 − s)²)), so the mesh stays closed and embedded.
mesh::TriMesh dented_ball() {
  mesh::TriMesh ball = mesh::icosphere(3);
  for (Vec3& p : ball.vertices) {
    if (p.y() > 0.3) p.y() = 0.6 - p.y();
  }
  return ball;
}

struct Material {
  double k = 2000.0, c = 2.0, nRT = 20.0, k_b = 0.0;  // N/m, N·s/m, J, N/m
};

sim::World dented_world(const Material& material, sim::IntegratorKind integrator, std::optional<sim::Floor> floor,
                        const Vec3& gravity, double lift_m) {
  const mesh::TriMesh ball = dented_ball();
  std::vector<Vec3> x0 = ball.vertices;
  for (Vec3& p : x0) p.y() += lift_m;
  sim::Body body = sim::build_body(x0, ball.triangles, 1.0);
  body.params.stiffness_N_per_m = material.k;
  body.params.damping_N_s_per_m = material.c;
  body.params.pressure_J = material.nRT;
  body.params.bending_N_per_m = material.k_b;
  body.params.bending_damping_N_s_per_m = material.c * material.k_b / material.k;
  if (material.k_b > 0.0) sim::add_bending_links(body, x0);
  return sim::one_body_world(gravity, floor, sim::Solver{integrator}, std::move(body), x0, Vec3::Zero());
}

double deviation_now(const sim::World& world, const std::vector<Vec3>& rest) {
  return analysis::shape_deviation(rest, world.state.x, world.model.mass_kg).relative();
}

// 0.7 × the estimated stable dt (as solver.dt "auto"), or `cap` where the estimate has no limit; xpbd: the
// substep of its "substeps": "auto" in frames of `cap`.
double auto_dt(const sim::World& world, double cap) {
  const sim::StabilityEstimate estimate = sim::estimate_stability(world.model, world.state);
  if (world.model.solver.integrator == sim::IntegratorKind::Xpbd)
    return cap / sim::auto_substeps(world.model.solver.integrator, world.model, estimate, cap);
  return std::min(cap, sim::kAutoDtSafety * estimate.stable_dt(world.model.solver.integrator));
}

// Dropped from 0.5 m onto the friction floor and left to settle for 3 s: the largest deviation from the rest
// shape (rigid motion removed) relative to the body's size. Symplectic Euler at its automatic dt.
double settled_deviation(Material material) {
  sim::Floor floor;
  floor.contact = sim::FloorContact::Friction;
  sim::World world = dented_world(material, sim::IntegratorKind::Symplectic, floor, Vec3(0, -9.81, 0), 1.5);
  const std::vector<Vec3> rest = world.state.x;
  const double dt = auto_dt(world, 1e-3);
  const auto steps = std::lround(3.0 / dt);
  for (long s = 0; s < steps; ++s) world.step(dt);
  return deviation_now(world, rest);
}

TEST(BendingShape, DentedBallKeepsItsDentAfterADropWithBendingAndLosesItWithout) {
  Material material;  // the scene defaults: k 1000 N/m, c 1 N·s/m, nRT 50 J
  material.k = 1000.0;
  material.c = 1.0;
  material.nRT = 50.0;
  const double without = settled_deviation(material);
  material.k_b = 3.0 * material.k;
  const double with = settled_deviation(material);
  std::printf("dented ball settled: largest deviation / size %.3f without bending, %.3f with k_b = 3 k\n", without,
              with);
  // Without links the gas pushes the dent out (a larger volume lowers −nRT ln V: measured 0.353, the dent's floor
  // moved by about its 0.7 m depth against a size of 2.9 m); the links hold the dent's rim, a sharp fold (0.012;
  // at k_b = k the dent half pops, 0.105).
  EXPECT_GT(without, 0.25);
  EXPECT_LT(with, 0.05);
}

// Every integrator, from the dent pressed flatter (y × 0.8 about the centre) at rest, no gravity: the links and
// edges pull it back towards the rest shape, the dampers settle it. After 0.5 s the deviation is below half
// the initial one, and nothing diverged (a link force of the wrong sign or Jacobian would make the 2 k links
// unstable or leave the dent pressed).
TEST(BendingShape, EveryIntegratorPullsThePressedDentBack) {
  for (const sim::IntegratorInfo& info : sim::kIntegrators) {
    SCOPED_TRACE(std::string(info.name));
    Material material;
    material.k_b = 2000.0;
    sim::World world = dented_world(material, info.kind, std::nullopt, Vec3::Zero(), 0.0);
    const std::vector<Vec3> rest = world.state.x;
    for (Vec3& p : world.state.x) p.y() *= 0.8;
    const double initial = deviation_now(world, rest);
    const double dt = auto_dt(world, 1.0 / 240);
    if (world.adaptive()) {
      world.advance_to(0.5);
    } else {
      const auto steps = std::lround(0.5 / dt);
      for (long s = 0; s < steps; ++s) world.step(dt);
    }
    const double final = deviation_now(world, rest);
    std::printf("%-10s dt %.3g s: deviation %.4f -> %.4f\n", std::string(info.name).c_str(), dt, initial, final);
    ASSERT_TRUE(std::isfinite(final));
    EXPECT_LT(final, 0.5 * initial);
  }
}

// The estimate counts the links: stiffer links lower the explicit methods' stable dt, and symplectic Euler is
// stable at 0.7 × the estimate but not at 1.5 × it (with links 10 × stiffer than the edges, the links' modes set it).
TEST(BendingStability, EstimateFollowsTheLinksStiffness) {
  Material soft, stiff;
  soft.k_b = 0.0;
  stiff.k_b = 20000.0;
  soft.c = stiff.c = 0.0;  // undamped, no gas: the energy is conserved, and a growing mode shows as growing energy
  soft.nRT = stiff.nRT = 0.0;
  const sim::World a = dented_world(soft, sim::IntegratorKind::Symplectic, std::nullopt, Vec3::Zero(), 0.0);
  const sim::World b = dented_world(stiff, sim::IntegratorKind::Symplectic, std::nullopt, Vec3::Zero(), 0.0);
  const double dt_soft = sim::estimate_stability(a.model, a.state).stable_dt(sim::IntegratorKind::Symplectic);
  const double dt_stiff = sim::estimate_stability(b.model, b.state).stable_dt(sim::IntegratorKind::Symplectic);
  EXPECT_LT(dt_stiff, 0.5 * dt_soft);
  auto energy_growth = [&](double factor) {
    sim::World world = dented_world(stiff, sim::IntegratorKind::Symplectic, std::nullopt, Vec3::Zero(), 0.0);
    const std::vector<Vec3> rest = world.state.x;
    for (std::size_t i = 0; i < world.state.x.size(); ++i)
      world.state.v[i] = 0.01 * Vec3(std::sin(3.0 * static_cast<double>(i)), 0, 0);
    const double e0 = sim::diagnose(world.model, world.state, 0).total_J();
    try {
      for (int s = 0; s < 3000; ++s) world.step(factor * dt_stiff);
    } catch (const softbody::DivergedError&) {
      return std::numeric_limits<double>::infinity();  // the guard saw the energy run away (10× the start)
    }
    return sim::diagnose(world.model, world.state, 0).total_J() / e0;
  };
  EXPECT_LT(energy_growth(sim::kAutoDtSafety), 1.5);
  EXPECT_GT(energy_growth(1.5), 100.0);
}

}  // namespace
