// vbd's coarse level (sim/integrators/coarse_space.hpp): its correction never raises the step's energy, and one step's
// residual after k sweeps with and without it.
#include <cmath>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "sim/forces/dynamics.hpp"
#include "sim/forces/forces.hpp"
#include "sim/integrators/coarse_space.hpp"
#include "sim/integrators/vertex_block_descent.hpp"
#include "support.hpp"

namespace {

using softbody::Vec3;

// The ball of scenes/bounce_smooth.json (1 kg, k 1000 N/m, c 1 N·s/m, nRT 200 J) at icosphere `level`, in flight, or
// (`impact`) 1 cm into that scene's smooth floor at 4 m/s.
std::string flying_ball(int level, bool impact) {
  if (impact) {
    return R"({ "gravity": [0, -9.81, 0], "floor": { "height": 0.0, "contact": "smooth", "time_constant": 0.002,
         "restitution": 0.5, "friction": 0.5, "slip_speed": 0.1, "smoothing": 0.01 }, "bodies": [ { "mesh": "icosphere:)" +
           std::to_string(level) +
           R"(", "position": [0, 0.49, 0], "velocity": [2, -4, 0], "mass": 1.0, "stiffness": 1000.0,
         "damping": 1.0, "pressure": 200.0 } ] })";
  }
  return R"({ "gravity": [0, -9.81, 0], "bodies": [ { "mesh": "icosphere:)" + std::to_string(level) +
         R"(", "position": [0, 3, 0], "velocity": [2, 0, 0], "mass": 1.0, "stiffness": 1000.0, "damping": 1.0,
         "pressure": 200.0 } ] })";
}

// The ball squashed out of its round shape by smooth, non-affine radial waves (Legendre P3 and P4 of the height, a
// cos 3φ ring), as after an impact, with a history of steps of h at its velocity: the next step is one BDF2 step of h.
void squash(sim::World& world, double h) {
  Vec3 centre = Vec3::Zero();
  for (const Vec3& x : world.state.x) centre += x;
  centre /= static_cast<double>(world.state.x.size());
  for (Vec3& x : world.state.x) {
    const Vec3 r = x - centre;
    const double c = r.y() / r.norm(), phi = std::atan2(r.z(), r.x());
    const double p3 = 0.5 * (5 * c * c * c - 3 * c), p4 = (35 * c * c * c * c - 30 * c * c + 3) / 8;
    x = centre + r * (1.0 + 0.03 * p3 + 0.02 * p4 + 0.02 * (1 - c * c) * std::cos(3 * phi));
  }
  const Vec3 g = world.model.gravity_m_per_s2;
  world.state.carry.previous_dt_s = h;
  world.state.carry.previous_x.clear();
  for (std::size_t i = 0; i < world.state.x.size(); ++i) {
    world.state.carry.previous_x.push_back(world.state.x[i] - h * world.state.v[i] + 0.5 * h * h * g);
  }
  world.state.carry.previous_v.assign(world.state.x.size(), world.state.v[0] - h * g);
}

// |m (x − y)/ĥ² − f(x, (x − x̃)/ĥ)| over all vertices [N] of a constant-step BDF2 step from `before` to `after`.
double bdf2_residual(sim::World& world, const sim::State& before, const sim::State& after) {
  const double h = before.carry.previous_dt_s, h_hat = 2.0 * h / 3.0;
  sim::State state = after;
  sim::Dynamics dynamics(world.model, world.workspace.forces);
  std::vector<Vec3> force;
  dynamics.forces(state, force);
  double sum = 0.0;
  for (std::size_t i = 0; i < force.size(); ++i) {
    const Vec3 base = (4.0 * before.x[i] - before.carry.previous_x[i]) / 3.0;
    const Vec3 target = base + h_hat * (4.0 * before.v[i] - before.carry.previous_v[i]) / 3.0;
    sum += (world.model.mass_kg[i] * (state.x[i] - target) / (h_hat * h_hat) - force[i]).squaredNorm();
  }
  return std::sqrt(sum);
}

// The start's residual (x = y) and the residual after one step of h with `sweeps` sweeps.
struct Residuals {
  double start = 0.0, after = 0.0, cpu_s = 0.0;
  std::vector<Vec3> start_x, x;  // x = y, and the step's end
};
Residuals one_step(int level, double h, int sweeps, int aggregates, bool impact = false) {
  sim::World world = integrator_tests::make_world(flying_ball(level, impact), sim::IntegratorKind::Vbd);
  squash(world, h);
  const sim::State before = world.state;
  sim::State start = before;
  const double h_hat = 2.0 * h / 3.0;
  for (std::size_t i = 0; i < start.x.size(); ++i) {
    const Vec3 base = (4.0 * before.x[i] - before.carry.previous_x[i]) / 3.0;
    const Vec3 velocity = (4.0 * before.v[i] - before.carry.previous_v[i]) / 3.0;
    start.x[i] = base + h_hat * velocity + h_hat * h_hat * world.model.gravity_m_per_s2;
    start.v[i] = (start.x[i] - base) / h_hat;
  }
  Residuals r;
  r.start = bdf2_residual(world, before, start);
  sim::VertexBlockDescent vbd(sweeps, true, aggregates);
  sim::Dynamics dynamics(world.model, world.workspace.forces);
  const std::clock_t t0 = std::clock();
  vbd.step(dynamics, world.state, h);
  r.cpu_s = static_cast<double>(std::clock() - t0) / CLOCKS_PER_SEC;
  EXPECT_EQ(vbd.statistics().steps, 1);
  r.after = bdf2_residual(world, before, world.state);
  r.start_x = start.x;
  r.x = world.state.x;
  return r;
}

// A coarse correction on a body in flight without dampers, where the step's energy
//   E(x) = Σ m |x − y|² / (2ĥ²) + Σ_e ½ k (|d_e| − L0)² − nRT ln V
// has no lagged terms, computed here on its own: it never rises, from stretched, compressed (buckling: clamped
// curvature) and wiggled starts at steps from 1/30 to 1/1920 s, and it falls.
double step_energy(const sim::Body& body, const sim::BodySolve& s, std::span<const Vec3> x) {
  double energy = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i)
    energy += 0.5 * s.mass_kg[i] * s.inverse_h2 * (x[i] - s.target[i]).squaredNorm();
  const sim::DistanceConstraints& c = body.constraints;
  for (std::size_t e = 0; e < c.size(); ++e) {
    const auto [i, j] = c.ends[e];
    const double stretch =
        (x[static_cast<std::size_t>(i)] - x[static_cast<std::size_t>(j)]).norm() - c.rest_length_m[e];
    energy += 0.5 * c.stiffness_N_per_m[e] * stretch * stretch;
  }
  return s.gas ? energy + s.gas->energy(sim::enclosed_volume(body.topology.faces, x)) : energy;
}

TEST(VbdCoarse, CorrectionNeverRaisesTheStepsEnergy) {
  sim::World world = integrator_tests::make_world(R"({ "gravity": [0, -9.81, 0], "bodies": [ { "mesh": "icosphere:4",
      "position": [0, 3, 0], "velocity": [2, 0, 0], "mass": 1.0, "stiffness": 1000.0, "damping": 0.0,
      "pressure": 200.0 } ] })",
                                                  sim::IntegratorKind::Vbd);
  const sim::Body& body = world.model.bodies[0];
  const sim::VertexBlocks blocks = sim::vertex_blocks(body);
  const sim::CoarseSpace space = sim::smooth_coarse_space(blocks, 128);
  sim::CoarseScratch scratch;
  Vec3 centre = Vec3::Zero();
  for (const Vec3& x : world.state.x) centre += x / static_cast<double>(world.state.x.size());
  int cases = 0, lowered = 0;
  for (const double scale : {0.9, 0.98, 1.0, 1.05}) {
    for (const double wiggle : {0.0, 0.01}) {
      for (const double h : {1.0 / 30, 1.0 / 240, 1.0 / 1920}) {
        const double h_hat = 2.0 * h / 3.0;
        std::vector<Vec3> x, target, base;
        for (std::size_t i = 0; i < world.state.x.size(); ++i) {
          x.push_back(centre + scale * (world.state.x[i] - centre) + wiggle * integrator_tests::wiggle(i, scale));
          base.push_back(x.back() - h_hat * world.state.v[i]);
          target.push_back(x.back() + h_hat * h_hat * world.model.gravity_m_per_s2 +
                           0.2 * wiggle * integrator_tests::wiggle(i, h));
        }
        sim::BodySolve s{blocks, world.model.mass_kg,   target,       base,    h_hat,
                         0.0,    1.0 / (h_hat * h_hat), std::nullopt, nullptr, {}};
        s.gas = sim::GasLaw{body.params.pressure_J, sim::guarded_volume(0.0, body.rest.volume_m3)};
        const double before = step_energy(body, s, x);
        const bool moved = sim::coarse_correction(body, s, space, x, true, scratch);
        const double after = step_energy(body, s, x);
        EXPECT_LE(after, before + 1e-12 * std::abs(before))
            << "scale " << scale << ", wiggle " << wiggle << ", h " << h;
        ++cases;
        if (moved && after < before) ++lowered;
      }
    }
  }
  std::printf("the coarse correction lowered E in %d of %d cases and never raised it\n", lowered, cases);
  EXPECT_EQ(lowered, cases);
}

// With the linear fields of the placed mesh the coarse space holds every affine motion of the body: where the step's
// energy is the inertia alone (springs of 1e-6 N/m, no gas) and x − y is an affine field, one correction (an exact
// Newton step on a quadratic) takes E to round-off; the cells' smooth translations alone leave 4e-4 of it.
TEST(VbdCoarse, LinearFieldsHoldEveryAffineMotion) {
  sim::World world = integrator_tests::make_world(R"({ "gravity": [0, 0, 0], "bodies": [ { "mesh": "icosphere:4",
      "position": [0, 3, 0], "mass": 1.0, "stiffness": 1e-6, "damping": 0.0, "pressure": 0.0 } ] })",
                                                  sim::IntegratorKind::Vbd);
  const sim::Body& body = world.model.bodies[0];
  const sim::VertexBlocks blocks = sim::vertex_blocks(body);
  const sim::CoarseSpace cells = sim::smooth_coarse_space(blocks, 128);
  const sim::CoarseSpace linear = sim::smooth_coarse_space(blocks, 128, body.rest.position_m);
  EXPECT_EQ(linear.aggregates, cells.aggregates + 3);
  Eigen::Matrix3d A;
  A << 0.02, -0.03, 0.01, 0.03, -0.01, 0.02, -0.01, 0.015, 0.03;  // a turn, a stretch and a shear
  const Vec3 t(0.01, -0.02, 0.005), centre(0.3, 2.0, -0.4);       // about a point off the body's centre
  const double h_hat = 2.0 / 3.0 / 60.0;
  const std::vector<Vec3>& y = world.state.x;
  std::vector<Vec3> start;
  for (const Vec3& p : y) start.push_back(p + A * (p - centre) + t);
  const sim::BodySolve s{blocks, world.model.mass_kg, y, y, h_hat, 0.0, 1.0 / (h_hat * h_hat), std::nullopt, nullptr,
                         {}};
  const double before = step_energy(body, s, start);
  double left[2] = {0.0, 0.0};
  for (int with_linear = 0; with_linear < 2; ++with_linear) {
    std::vector<Vec3> x = start;
    sim::CoarseScratch scratch;
    EXPECT_TRUE(sim::coarse_correction(body, s, with_linear ? linear : cells, x, true, scratch));
    left[with_linear] = step_energy(body, s, x) / before;
  }
  std::printf("one correction leaves %.3g of E with the cells alone, %.3g with the linear fields\n", left[0], left[1]);
  EXPECT_GT(left[0], 1e-5);
  EXPECT_LT(left[1], 1e-12);
}

// Where plain sweeps stall (icosphere:5, a squashed ball in flight, a step of 1/30 s: 16 sweeps take the residual to
// 0.42 of its start), the coarse level takes it about 3× further with the same sweeps.
TEST(VbdCoarse, CoarseLevelReducesTheResidualWhereSweepsStall) {
  const Residuals plain = one_step(5, 1.0 / 30.0, 16, 0);
  const Residuals coarse = one_step(5, 1.0 / 30.0, 16, 128);
  std::printf("icosphere:5, 16 sweeps: residual %.3f of its start without the coarse level, %.3f with 128 cells\n",
              plain.after / plain.start, coarse.after / coarse.start);
  EXPECT_GT(plain.after, 0.3 * plain.start);
  EXPECT_LT(coarse.after, 0.5 * plain.after);
}

// `coarse_space: "auto"` takes 128 cells from 5000 vertices: icosphere:5 (10,242) steps exactly as with 128,
// icosphere:4 (2,562) exactly as with none.
TEST(VbdCoarse, AutoTakesTheCoarseLevelFromFiveThousandVertices) {
  EXPECT_EQ(sim::auto_coarse_cells(4999), 0);
  EXPECT_EQ(sim::auto_coarse_cells(5000), 128);
  constexpr int kAuto = sim::VertexBlockDescent::kAutoAggregates;
  EXPECT_EQ(one_step(5, 1.0 / 30.0, 4, kAuto).x, one_step(5, 1.0 / 30.0, 4, 128).x);
  EXPECT_EQ(one_step(4, 1.0 / 30.0, 4, kAuto).x, one_step(4, 1.0 / 30.0, 4, 0).x);
  EXPECT_NE(one_step(4, 1.0 / 30.0, 4, kAuto).x, one_step(4, 1.0 / 30.0, 4, 128).x);
}

// RMS |a − b| over vertices [m].
double rms_distance(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += (a[i] - b[i]).squaredNorm();
  return std::sqrt(sum / static_cast<double>(a.size()));
}

// The table of docs/notes/2026-12-05-vbd-coarse.md (run with --gtest_also_run_disabled_tests; level 6 takes a while):
// the residual, and the distance to the converged step (400 sweeps with 128 cells) against the start's.
TEST(VbdCoarse, DISABLED_ResidualTable) {
  for (const bool impact : {false, true}) {
    for (const int level : {3, 4, 5, 6}) {
      const Residuals converged = one_step(level, impact ? 1.0 / 1920 : 1.0 / 30, 400, 128, impact);
      const double start_error = rms_distance(converged.start_x, converged.x);
      std::printf("%s level %d converged: residual %.3e of %.3e, |y - x*| %.3e m\n", impact ? "impact" : "flight",
                  level, converged.after, converged.start, start_error);
      for (const int aggregates : {0, 64, 128}) {
        for (const int sweeps : {1, 2, 4, 8, 16}) {
          const Residuals r = one_step(level, impact ? 1.0 / 1920 : 1.0 / 30, sweeps, aggregates, impact);
          std::printf("%s level %d cells %3d sweeps %2d: residual %.4f, error %.4f of the start's, cpu %.4f s\n",
                      impact ? "impact" : "flight", level, aggregates, sweeps, r.after / r.start,
                      rms_distance(r.x, converged.x) / start_error, r.cpu_s);
        }
      }
    }
  }
}

}  // namespace
