// xpbd: its constraint step against backward Euler, its convergence to rk4 as the substeps grow, the edge
// colouring, and contacts at 1/60 s frames (a ball at 5 m/s onto the floor and onto another body).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "frames/frame_clock.hpp"
#include "scene/scene_json.hpp"
#include "setup/build_world.hpp"
#include "sim/contact/body_collision.hpp"
#include "sim/solvers/edge_colouring.hpp"
#include "sim/step/diagnostics.hpp"
#include "sim/step/stability.hpp"
#include "sim/step/world.hpp"
#include "support.hpp"

namespace {

using integrator_tests::rms_position_difference;
using softbody::Vec3;

// Two particles joined by one spring-damper along x, no gravity, no gas. For one constraint along a line,
// XPBD's substep is exactly backward Euler for the spring-damper (xpbd.hpp): with the reduced mass
// μ = m1 m2 / (m1 + m2) and the stretch s = x1 − x2 − L0, after a drift to s* = s + h ṡ,
//   μ (s' − s*) = −h² k s' − h c (s' − s)   ⇒   s' = (μ s* + h c s) / (μ + h² k + h c).
// Both forms: h ω = h·√(400/0.21) ≈ 2.2 at h = 0.05 s (classical, above xpbd_carried_dt) and 1.3 at 0.03 s
// (carried, where the carried force's push cancels in the algebra: Δλ = Δλ_classical + h² T).
void expect_one_spring_substep_is_backward_euler(double h) {
  const double m1 = 0.3, m2 = 0.7, k = 400.0, c = 2.0, rest = 1.0;
  sim::Body body;
  body.topology.edges = {{0, 1}};
  body.rest.edge_length_m = {rest};
  body.rest.mean_edge_m = rest;
  body.masses.kg = {m1, m2};
  body.masses.inverse = {1.0 / m1, 1.0 / m2};
  body.masses.total_kg = m1 + m2;
  body.params = {k, c, 0.0};
  sim::Solver solver;
  solver.integrator = sim::IntegratorKind::Xpbd;
  const std::vector<Vec3> x0 = {Vec3(1.2, 0, 0), Vec3(0, 0, 0)};  // stretched by 0.2 m
  sim::World world = sim::one_body_world(Vec3::Zero(), std::nullopt, solver, std::move(body), x0, Vec3::Zero());
  world.state.v = {Vec3(0.5, 0, 0), Vec3(-1.0, 0, 0)};
  const double mu = m1 * m2 / (m1 + m2);
  double s = 0.2, rate = 1.5;  // stretch [m], its rate [m/s]
  for (int n = 0; n < 5; ++n) {
    const double next = (mu * (s + h * rate) + h * c * s) / (mu + h * h * k + h * c);
    rate = (next - s) / h;
    s = next;
    world.step(h);
    const double stretch = world.state.x[0].x() - world.state.x[1].x() - rest;
    EXPECT_NEAR(stretch, s, 1e-14) << "substep " << n + 1;
    EXPECT_NEAR(world.state.v[0].x() - world.state.v[1].x(), rate, 1e-12) << "substep " << n + 1;
  }
  // The constraint forces are internal: the momentum m1 v1 + m2 v2 = 0.15 − 0.7 = −0.55 stays.
  EXPECT_NEAR(m1 * world.state.v[0].x() + m2 * world.state.v[1].x(), -0.55, 1e-12);
}

TEST(Xpbd, OneSpringSubstepIsBackwardEuler) { expect_one_spring_substep_is_backward_euler(0.05); }

TEST(Xpbd, OneSpringCarriedSubstepIsBackwardEuler) { expect_one_spring_substep_is_backward_euler(0.03); }

// A pressurised ball (icosphere:2, k 1000 N/m, c 2 N·s/m, nRT 50 J, 1 kg) without gravity or floor, released
// from its rest shape: it inflates and settles at the volume where the springs balance the gas. The carried
// form (xpbd.hpp) carries that load from substep to substep, so at h ω_max ≤ 1.8 it settles where 32 times the
// substeps do; the classical form (h ω_max ≥ 2.1, above the switch at 1.9) settles inflated, because one
// Gauss–Seidel pass per substep leaves the network short of the load (the bias of sim/step/stability.hpp). Measured
// (ω_max 999 rad/s): carried at 10 substeps per 1/60 s within 5e-7 of 320 substeps, classical at 7 +1.57 %.
constexpr const char* kFloatingBall = R"({ "fps": 60, "gravity": [0, 0, 0],
  "bodies": [ { "mesh": "icosphere:2", "mass": 1.0, "stiffness": 1000.0, "damping": 2.0, "pressure": 50.0 } ] })";

double settled_volume(int substeps) {  // per 1/60 s frame; returns the volume after 2 s [m³]
  sim::World world = integrator_tests::make_world(kFloatingBall, sim::IntegratorKind::Xpbd);
  integrator_tests::run_for(world, 2.0, frames::substep_dt(60, substeps));
  return sim::diagnose(world.model, world.state, 0).volume_m3;
}

TEST(Xpbd, CarriedFormSettlesAtTheEquilibriumVolume) {
  const sim::World world = integrator_tests::make_world(kFloatingBall, sim::IntegratorKind::Xpbd);
  const double omega_max = sim::estimate_stability(world.model, world.state).bodies.at(0).omega_max();  // rad/s
  const int carried_substeps = static_cast<int>(std::ceil(omega_max / (60.0 * 1.8)));
  const int classical_substeps = static_cast<int>(std::floor(omega_max / (60.0 * 2.1)));
  ASSERT_GE(classical_substeps, 1);
  const double converged = settled_volume(32 * carried_substeps);
  const double carried = settled_volume(carried_substeps), classical = settled_volume(classical_substeps);
  std::printf(
      "settled volume (omega_max %.0f rad/s): carried at %d substeps %.6f, classical at %d %.6f, at %d %.6f "
      "m^3 (%.4f %%, %.4f %%)\n",
      omega_max, carried_substeps, carried, classical_substeps, classical, 32 * carried_substeps, converged,
      100.0 * (carried / converged - 1.0), 100.0 * (classical / converged - 1.0));
  EXPECT_LT(std::abs(carried / converged - 1.0), 5e-4) << "the carried form: within 0.05 % of the equilibrium";
  EXPECT_GT(classical / converged - 1.0, 2e-3) << "the classical form: inflated (what the carried form removes)";
}

// Every edge once; no two edges of a colour share a vertex; at most 2Δ − 1 colours (the greedy bound).
TEST(Xpbd, EdgeColouringSeparatesEdgesThatShareAVertex) {
  const sim::World world =
      integrator_tests::make_world(R"({ "bodies": [ { "mesh": "icosphere:3" } ] })", sim::IntegratorKind::Xpbd);
  const sim::Body& body = world.model.bodies[0];
  const sim::EdgeColouring colouring = sim::colour_edges(body.topology.edges, body.vertex_count);
  std::vector<int> valence(static_cast<std::size_t>(body.vertex_count), 0);
  for (const auto& [i, j] : body.topology.edges) ++valence[i], ++valence[j];
  const int largest_valence = *std::max_element(valence.begin(), valence.end());
  EXPECT_LE(colouring.colours(), 2 * largest_valence - 1);
  std::vector<int> seen(body.topology.edges.size(), 0);
  for (int c = 0; c < colouring.colours(); ++c) {
    std::set<int> vertices;
    for (int k = colouring.colour_start[c]; k < colouring.colour_start[c + 1]; ++k) {
      const int e = colouring.edges[static_cast<std::size_t>(k)];
      ++seen[static_cast<std::size_t>(e)];
      for (int v : body.topology.edges[static_cast<std::size_t>(e)]) {
        EXPECT_TRUE(vertices.insert(v).second) << "colour " << c << " has two edges at vertex " << v;
      }
    }
  }
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<long>(seen.size())) << "every edge exactly once";
}

// scenes/breathing.json with `integrator`, integrated for kSpan at whole steps of dt, its dampers at 0.5 N·s/m
// instead of the scene's 0.01. Why: xpbd's springs behave like backward Euler, whose numerical damping of a
// mode per second is about h ω² / 2; the scene's fastest spring modes (ω ≈ 1000 rad/s) keep ringing under
// rk4 with c = 0.01 but die under xpbd even at h = 0.26 ms, which leaves an error floor of about 1 cm RMS
// (measured: 3.8e-2, 1.4e-2, 1.1e-2, 1.0e-2 m at 16 .. 128 substeps). With c = 0.5 they die within
// milliseconds under every method (γ = c λ_max ≈ 1000 1/s), and the comparison measures the motion both keep.
constexpr double kSpan = 1.0;              // s: 30 frames, about one breathing period
constexpr double kBreathingDamping = 0.5;  // N·s/m
sim::State breathing_state(sim::IntegratorKind integrator, double dt) {
  scene::Scene scene = scene::load_scene(std::string(SOFTBODY_SOURCE_DIR) + "/scenes/breathing.json");
  scene.solver.integrator = integrator;
  scene.bodies[0].damping_N_s_per_m = kBreathingDamping;
  std::vector<std::string> notes;
  sim::World world = setup::build_world(scene, notes);
  integrator_tests::run_for(world, kSpan, dt);
  return world.state;
}

// As the substeps grow, xpbd converges to the solution of the other integrators: rk4 at 1e-4 s (its distance to
// rk4 at 2e-4 s bounds its own error, far below xpbd's). Substeps 8 .. 2048 per 1/30 s frame (h = 4.2 .. 0.016 ms;
// ω_max = 709 rad/s, so h ω_max runs from 3 down to 0.012). At 8 substeps xpbd takes its classical form (above
// xpbd_carried_dt), from 16 on the carried one (sim/integrators/xpbd.hpp). Measured: 0.129 m at 8, then 1.17e-4,
// 7.1e-5, 6.0e-5, 4.3e-5, 2.6e-5, 1.5e-5, 7.7e-6, 4.0e-6 m at 16 .. 2048, halvings gaining 0.72, 0.24, 0.49, 0.71,
// 0.84, 0.92, 0.96: first order in the end (the dampers' terms), after a plateau where the error is the phase of
// the weakly damped spring modes (the linearised form that the carried one replaced: 9.3e-5 at 16, the same from
// 32 on; the classical form damped them like backward Euler: 0.037 m at 16 and 7.7e-4 m at 128 substeps).
// A solver that converged to anything else would level off at the difference instead (order → 0).
TEST(Xpbd, ConvergesToRk4AsTheSubstepsGrow) {
  const sim::State reference = breathing_state(sim::IntegratorKind::Rk4, 1e-4);
  const double uncertainty = rms_position_difference(breathing_state(sim::IntegratorKind::Rk4, 2e-4), reference);
  std::vector<double> errors;
  std::printf("xpbd on breathing.json (c = %.2g), %.1f s, against rk4 at 1e-4 s (uncertainty %.1e m):",
              kBreathingDamping, kSpan, uncertainty);
  for (int substeps = 8; substeps <= 2048; substeps *= 2) {
    errors.push_back(rms_position_difference(
        breathing_state(sim::IntegratorKind::Xpbd, frames::substep_dt(30, substeps)), reference));
    std::printf(" %d: %.3e", substeps, errors.back());
  }
  std::printf("\n  pairwise orders:");
  for (std::size_t k = 1; k < errors.size(); ++k) std::printf(" %.3f", std::log2(errors[k - 1] / errors[k]));
  std::printf("\n");
  for (std::size_t k = 1; k < errors.size(); ++k) EXPECT_LT(errors[k], errors[k - 1]) << "halving " << k;
  for (std::size_t k = errors.size() - 2; k < errors.size(); ++k) {  // the last two halvings: the asymptotic order
    const double order = std::log2(errors[k - 1] / errors[k]);
    EXPECT_GT(order, 0.8) << "halving " << k << ": at least first order";
    EXPECT_LT(order, 2.2) << "halving " << k;
  }
  EXPECT_LT(errors[1], 1e-3) << "16 substeps per frame (the carried form): within a millimetre of rk4";
  EXPECT_LT(errors.back(), 1e-5) << "2048 substeps per frame: within 10 µm of rk4";
  EXPECT_LT(uncertainty, 1e-3 * errors.back()) << "the reference is not converged enough";
}

// A ball of the issue's bounce (icosphere:3, k 1000 N/m, c 1 N·s/m, nRT 50 J, 1 kg) thrown down at 5 m/s from
// 5 cm above the friction floor, at 1/60 s frames.
constexpr const char* kDropOnFloor = R"({
  "fps": 60,
  "floor": { "contact": "friction" },
  "bodies": [ { "mesh": "icosphere:3", "position": [0, 1.05, 0], "velocity": [1, -5, 0], "mass": 1.0,
                "stiffness": 1000.0, "damping": 1.0, "pressure": 50.0 } ] })";

// No vertex passes the floor, and none gets deeper in one substep than the substep's travel allows: the
// contact is resolved in every substep, so at h = 1/60/S a vertex at the impact speed (5 m/s plus what
// gravity and the springs add) travels at most about 5.5 m/s · h before the floor puts it back.
TEST(Xpbd, BallAt5MetresPerSecondStaysOnTheFloorAtSixtyFramesPerSecond) {
  for (const int substeps : {1, 4, 16}) {
    sim::World world = integrator_tests::make_world(kDropOnFloor, sim::IntegratorKind::Xpbd);
    const double h = frames::substep_dt(60, substeps);
    double deepest = 0.0, lowest = 1.0, highest_after_bounce = 0.0, fastest = 0.0;
    for (int step = 0; step < 60 * substeps; ++step) {  // 1 s
      for (const Vec3& v : world.state.v) fastest = std::max(fastest, v.norm());
      world.step(h);
      deepest = std::max(deepest, world.workspace.deepest_floor_penetration_m);
      const sim::BodyDiagnostics d = sim::diagnose(world.model, world.state, 0);
      lowest = std::min(lowest, d.min_y_m);
      if (world.state.time_s > 0.5) highest_after_bounce = std::max(highest_after_bounce, d.com_m.y());
    }
    std::printf(
        "substeps %2d (h %.3g ms): deepest before the projection %.4f m (travel bound %.4f m), fastest "
        "vertex %.2f m/s\n",
        substeps, 1e3 * h, deepest, fastest * h, fastest);
    EXPECT_GE(lowest, 0.0) << "a vertex below the floor after a step";
    EXPECT_LE(deepest, fastest * h * (1.0 + 1e-9)) << "deeper than one substep's travel";
    EXPECT_GT(fastest, 4.9) << "the ball did arrive at speed";
    const sim::BodyDiagnostics end = sim::diagnose(world.model, world.state, 0);
    EXPECT_GT(end.volume_m3, 0.5 * world.model.bodies[0].rest.volume_m3) << "not crushed";
    EXPECT_GT(highest_after_bounce, 0.3) << "the ball stands on the floor afterwards (centre well above it)";
  }
}

// The deepest any vertex of one body lies inside another (generalised winding number > ½), measured from
// above as its distance to the nearest vertex of the other body's surface (≥ the distance to the surface).
double deepest_inside(const sim::World& world) {
  double deepest = 0.0;
  for (std::size_t a = 0; a < world.model.bodies.size(); ++a) {
    for (std::size_t b = 0; b < world.model.bodies.size(); ++b) {
      if (a == b) continue;
      const sim::Body& surface = world.model.bodies[b];
      const auto surface_x = world.model.of(surface, world.state.x);
      for (const Vec3& p : world.model.of(world.model.bodies[a], world.state.x)) {
        if (sim::winding_number(surface_x, surface.topology.faces, p) <= 0.5) continue;
        double nearest = INFINITY;
        for (const Vec3& q : surface_x) nearest = std::min(nearest, (p - q).norm());
        deepest = std::max(deepest, nearest);
      }
    }
  }
  return deepest;
}

// A small ball (icosphere:2, radius 0.5 m) thrown down at 5 m/s onto a ball resting on the floor (icosphere:3,
// radius 1 m): the body contact runs in every substep and pushes a vertex out by all of that substep's travel
// into the other body (sim::PushLimit). Checked at every frame of 1/60 s for 1 s. Measured: no vertex inside at
// 2, 4 and 10 substeps; at 1 substep (8 cm per step, more than the search's half edge of 7.5 cm) the small ball
// passes through (no continuous collision). With the push also capped at a twentieth of an edge per substep
// (the velocity-based integrators' cap) it sank 1.7 cm at 4 substeps and passed through at 2.
TEST(Xpbd, BallAt5MetresPerSecondDoesNotSinkIntoAnotherBody) {
  constexpr const char* kDropOnBall = R"({
    "fps": 60,
    "floor": { "contact": "friction" },
    "bodies": [
      { "mesh": "icosphere:3", "position": [0, 1.0, 0], "mass": 1.0, "stiffness": 1000.0, "damping": 1.0, "pressure": 50.0 },
      { "mesh": "icosphere:2", "scale": 0.5, "position": [0.0, 2.6, 0], "velocity": [0, -5, 0], "mass": 0.5,
        "stiffness": 1000.0, "damping": 1.0, "pressure": 25.0 } ] })";
  for (const int substeps : {2, 4, 10}) {
    sim::World world = integrator_tests::make_world(kDropOnBall, sim::IntegratorKind::Xpbd);
    const double h = frames::substep_dt(60, substeps);
    const double edge = world.model.bodies[0].rest.mean_edge_m;
    double deepest = 0.0;
    for (int frame = 1; frame <= 60; ++frame) {
      integrator_tests::run_for(world, 1.0 / 60.0, h);
      deepest = std::max(deepest, deepest_inside(world));
    }
    std::printf("substeps %2d: deepest vertex inside the other body %.4f m (%.2f mean edges of the big ball)\n",
                substeps, deepest, deepest / edge);
    EXPECT_LE(deepest, 0.5 * edge);
    EXPECT_GT(sim::diagnose(world.model, world.state, 1).min_y_m, 1.5) << "the small ball stays on top";
  }
}

}  // namespace
