// Newton with the smooth body contact inside its potential: the contact terms' derivatives against finite
// differences and against the smooth contact's force, and two balls that stack at 1/60 s without sinking in.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "sim/contact/body_collision.hpp"
#include "sim/contact/body_contact_potential.hpp"
#include "sim/integrators/newton_euler.hpp"
#include "sim/step/diagnostics.hpp"
#include "support.hpp"

namespace {

using integrator_tests::make_world;
using integrator_tests::wiggle;
using softbody::Vec3;

// Two unit spheres pressed 3 cm into each other, off-centre, and sliding past each other, with a 4 cm smoothing
// skin (a 2 mm one holds no vertex of these coarse meshes): their contact has vertices outside the skin, inside
// the smoothing band and past it, so every contact term of E is non-zero.
constexpr const char* kPressed = R"({ "gravity": [0, -9.81, 0],
    "collisions": { "contact": "smooth", "restitution": 0.3, "friction": 0.6, "smoothing": 0.04 },
    "bodies": [ { "mesh": "icosphere:2", "position": [0, 0, 0], "mass": 1.0, "stiffness": 300.0, "damping": 2.0,
                  "pressure": 40.0 },
                { "mesh": "icosphere:2", "position": [1.97, 0.1, 0.05], "mass": 1.5, "stiffness": 300.0,
                  "damping": 2.0, "pressure": 40.0 } ] })";

// E of a step of h from the pressed pair (left ball moving at (0.5, 0.2, 0), right one at (−0.5, −0.3, 0.4) m/s,
// + 0.2 wiggle), assembled at x = x̂ + 0.001 wiggle with the contacts' lags taken there.
struct PressedPotential {
  explicit PressedPotential(double step_s) : world(make_world(kPressed, sim::IntegratorKind::Newton)), h(step_s) {
    sim::State& s = world.state;
    const int right = world.model.bodies[1].first_vertex;
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      const Vec3 drift = static_cast<int>(i) < right ? Vec3(0.5, 0.2, 0.0) : Vec3(-0.5, -0.3, 0.4);
      s.v[i] = drift + 0.2 * wiggle(i, 0.0);
    }
    potential.build(world.model);
    hessian.build(world.model.vertex_count(), potential.pairs());
    potential.begin_step(world.model, s, h);
    x.resize(s.x.size());
    for (std::size_t i = 0; i < s.x.size(); ++i) x[i] = s.x[i] + h * s.v[i] + 0.001 * wiggle(i, 1.0);
    gradient.setZero(hessian.size());
    potential.update_lags(world.model, x);
    potential.assemble(world.model, x, sim::IncrementalPotential::Hessian::Exact, hessian, gradient);
    collider.find_smooth_frames(world.model.bodies, x, frames);
  }
  // Contacts by depth d = δ − s: outside the skin (d ≤ 0), in the smoothing band (0 < d < δ), past it.
  std::array<int, 3> contacts_by_depth() const {
    std::array<int, 3> count{};
    const double skin = world.model.body_contact.smooth.smoothing_m;
    for (const auto& f : frames)
      ++count[skin - f.signed_distance_m <= 0.0 ? 0 : skin - f.signed_distance_m < skin ? 1 : 2];
    return count;
  }

  sim::World world;
  double h;
  sim::IncrementalPotential potential;
  sim::BlockSystem hessian;
  std::vector<Vec3> x;
  Eigen::VectorXd gradient;
  sim::BodyCollider collider;
  std::vector<sim::BodyCollider::SmoothFrame> frames;
};

// With the lags held (frames, dashpot weights, friction forces), ∇E is the derivative of E: central differences
// of E at every vertex and triangle corner of a contact.
TEST(NewtonContactPotential, GradientMatchesFiniteDifferencesOfTheEnergy) {
  PressedPotential p(1.0 / 60);
  const std::array<int, 3> by_depth = p.contacts_by_depth();
  std::printf("contacts: %d outside the skin, %d in the smoothing band, %d past it\n", by_depth[0], by_depth[1],
              by_depth[2]);
  ASSERT_GT(by_depth[1], 0);
  ASSERT_GT(by_depth[2], 0);
  std::vector<int> checked;
  for (const auto& f : p.frames) {
    checked.push_back(f.vertex);
    checked.insert(checked.end(), f.corners.begin(), f.corners.end());
  }
  std::sort(checked.begin(), checked.end());
  checked.erase(std::unique(checked.begin(), checked.end()), checked.end());
  constexpr double kStep = 1e-7;  // m: small against the 4 cm skin
  const integrator_tests::GradientMismatch m =
      integrator_tests::gradient_mismatch(p.potential, p.world.model, p.hessian, p.x, p.gradient, checked, kStep);
  const double worst = m.worst_N, scale = m.scale_N;
  std::printf("%zu vertices in contacts: max |dE/dx numeric - analytic| = %.3e N (largest component %.3e N)\n",
              checked.size(), worst, scale);
  EXPECT_LT(worst, 1e-5 * scale);
}

// The exact Hessian (the sparse part, the gas's and the contacts' rank-one terms) is the derivative of the
// gradient with the lags held, dashpot and friction included: along a non-smooth direction r.
TEST(NewtonContactPotential, HessianIsTheDerivativeOfTheGradient) {
  PressedPotential p(1.0 / 60);
  ASSERT_GT(p.potential.contact_terms().size(), 2 * p.frames.size() / 3) << "contacts without Hessian terms";
  Eigen::VectorXd r(p.hessian.size());
  for (Eigen::Index k = 0; k < r.size(); ++k) r[k] = std::sin(1.7 * static_cast<double>(k));
  const double error = integrator_tests::hessian_mismatch(p.potential, p.world.model, p.hessian, p.x, r, /*step=*/1e-8);
  std::printf("%zu contact terms: |d(grad E)/dr - H r| / |H r| = %.3e\n", p.potential.contact_terms().size(), error);
  EXPECT_LT(error, 1e-6);
}

// At the lag point the contact terms' −∇ is the smooth contact's force (sim/contact/body_collision.hpp) at the backward
// Euler velocity v' = (x − x_n)/h: the minimiser of E is backward Euler of the very force rk4 and the others see.
TEST(NewtonContactPotential, MinusTheGradientIsTheSmoothContactForce) {
  PressedPotential p(1.0 / 60);
  const sim::Model& model = p.world.model;
  sim::BodyContactPotential contact;
  contact.build(model);
  contact.begin_step(p.h);
  contact.lag(model, p.x);
  Eigen::VectorXd gradient = Eigen::VectorXd::Zero(p.hessian.size());
  contact.add_derivatives(model, p.x, p.world.state.x, gradient);
  std::vector<Vec3> velocity(p.x.size()), force(p.x.size(), Vec3::Zero());
  for (std::size_t i = 0; i < p.x.size(); ++i) velocity[i] = (p.x[i] - p.world.state.x[i]) / p.h;
  const sim::SmoothResponse response =
      sim::resolve_smooth_response(model.body_contact.smooth, model.body_contact.material);
  sim::BodyCollider collider;
  ASSERT_GT(collider.add_smooth_forces(model.bodies, model.mass_kg, p.x, velocity, response, force), 0);
  double worst = 0.0, largest = 0.0;
  for (std::size_t i = 0; i < p.x.size(); ++i) {
    worst = std::max(worst, (force[i] + gradient.segment<3>(3 * static_cast<Eigen::Index>(i))).norm());
    largest = std::max(largest, force[i].norm());
  }
  std::printf("largest contact force %.3e N; max |f + grad| = %.3e N\n", largest, worst);
  EXPECT_GT(largest, 1.0);
  EXPECT_LT(worst, 1e-12 * largest);
}

// Two bounce balls (k 1000 N/m, c 1 N·s/m, nRT 200 J, 1 kg) stacked on the smooth floor, the top one dropped from
// 10 cm above the bottom one (1.4 m/s at the touch).
constexpr const char* kTwoBalls = R"({ "gravity": [0, -9.81, 0],
    "floor": { "contact": "smooth", "restitution": 0.2, "friction": 0.8 },
    "collisions": { "contact": "smooth", "restitution": 0.2, "friction": 0.8 },
    "bodies": [ { "mesh": "icosphere:2", "position": [0, 1.0, 0], "mass": 1.0, "stiffness": 1000.0, "damping": 5.0,
                  "pressure": 200.0 },
                { "mesh": "icosphere:2", "position": [0, 3.1, 0], "mass": 1.0, "stiffness": 1000.0, "damping": 5.0,
                  "pressure": 200.0 } ] })";

// How deep the top ball is in the bottom one's contact skin: the largest d = δ − s over its vertices (s the signed
// distance to the bottom ball's surface; the contact starts at s = δ = 2 mm, so d > δ would be inside the
// surface) [m], and whether any vertex is inside by the winding number (> ½).
struct StackDepth {
  double skin_depth_m = 0.0;
  bool inside = false;
};
StackDepth stack_depth(const sim::World& world) {
  sim::BodyCollider collider;
  std::vector<sim::BodyCollider::SmoothFrame> frames;
  collider.find_smooth_frames(world.model.bodies, world.state.x, frames);
  const sim::Body& bottom = world.model.bodies[0];
  const sim::Body& top = world.model.bodies[1];
  const double skin = world.model.body_contact.smooth.smoothing_m;
  StackDepth result;
  for (const auto& f : frames) {
    if (f.vertex >= top.first_vertex) result.skin_depth_m = std::max(result.skin_depth_m, skin - f.signed_distance_m);
  }
  for (const Vec3& p : world.model.of(top, world.state.x)) {
    if (sim::winding_number(world.model.of(bottom, world.state.x), bottom.topology.faces, p) > 0.5)
      result.inside = true;
  }
  return result;
}

// `integrator` at `dt` over `samples` of 1/60 s: the deepest skin depth at the samples, the top ball's centre height
// at the last one and its mean over the second half, and the samples with a vertex inside the bottom ball.
struct StackRun {
  double deepest_m = 0.0, top_centre_m = 0.0, mean_top_centre_m = 0.0;
  int samples_inside = 0;
};
StackRun run_stack(sim::IntegratorKind integrator, double dt, int samples) {
  sim::World world = make_world(kTwoBalls, integrator);
  const int steps_per_sample = static_cast<int>(std::lround(1.0 / 60 / dt));
  StackRun run;
  for (int s = 0; s < samples; ++s) {
    for (int k = 0; k < steps_per_sample; ++k) world.step(dt);
    const StackDepth depth = stack_depth(world);
    run.deepest_m = std::max(run.deepest_m, depth.skin_depth_m);
    if (depth.inside) ++run.samples_inside;
    run.top_centre_m = sim::diagnose(world.model, world.state, 1).com_m.y();
    if (2 * s >= samples) run.mean_top_centre_m += run.top_centre_m / (samples - (samples + 1) / 2);
  }
  if (integrator == sim::IntegratorKind::Newton) {
    const auto& stats = dynamic_cast<const sim::NewtonEuler&>(*world.workspace.integrator).statistics();
    std::printf("newton: %.2f iterations per step (most %d), %lld unconverged steps of %lld\n",
                static_cast<double>(stats.iterations) / static_cast<double>(stats.steps), stats.most_iterations,
                stats.unconverged_steps, stats.steps);
  }
  return run;
}

// newton at 1/60 s: the top ball lands on the bottom one (1.4 m/s) and stays on it without sinking in: no vertex
// inside the bottom ball at any sample, none deeper in the contact skin than 1.1 × the converged motion's
// deepest (rk4 at 0.1 ms, the same samples; measured 0.94 mm against 0.96 mm, both short of the 2 mm at which a
// vertex would reach the surface), and the top ball at rest where the converged one oscillates about (within 2 cm
// of the mean of its last second, measured 9 mm: rk4 keeps bouncing ±7 cm on the gas springs, backward Euler damps
// that out).
TEST(NewtonContact, TwoBallsStackAtOneSixtiethOfASecondWithoutSinkingIn) {
  constexpr int kSamples = 120;  // 2 s
  const StackRun newton = run_stack(sim::IntegratorKind::Newton, 1.0 / 60, kSamples);
  const StackRun converged = run_stack(sim::IntegratorKind::Rk4, 1e-4, kSamples);
  std::printf(
      "top ball in the bottom one's contact skin, deepest: newton 1/60 s %.3f mm, rk4 0.1 ms %.3f mm; "
      "top centre at 2 s %.4f m (newton), mean over 1-2 s %.4f m (rk4); samples with a vertex inside: %d, %d\n",
      1e3 * newton.deepest_m, 1e3 * converged.deepest_m, newton.top_centre_m, converged.mean_top_centre_m,
      newton.samples_inside, converged.samples_inside);
  EXPECT_EQ(newton.samples_inside, 0);
  EXPECT_LT(newton.deepest_m, 1.1 * converged.deepest_m);
  EXPECT_NEAR(newton.top_centre_m, converged.mean_top_centre_m, 0.02);
}

}  // namespace
