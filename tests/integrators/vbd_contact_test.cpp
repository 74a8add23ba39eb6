// vbd with the smooth contact between bodies in its energy (sim/integrators/vertex_contacts.hpp): the contact terms'
// gradient and Hessian against finite differences of the local energy and against the smooth contact's force, the
// fixed point of converged sweeps against the model's own forces, the momentum of a converged step, and two balls
// that stack at 1/60 s without sinking in.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include "sim/contact/body_collision.hpp"
#include "sim/forces/dynamics.hpp"
#include "sim/integrators/vertex_block_descent.hpp"
#include "sim/integrators/vertex_contacts.hpp"
#include "sim/step/diagnostics.hpp"
#include "sim/step/step_plan.hpp"
#include "support.hpp"

namespace {

using integrator_tests::wiggle;
using softbody::Vec3;

sim::World vbd_world(const std::string& json_text, int sweeps) {
  sim::Solver solver;
  solver.integrator = sim::IntegratorKind::Vbd;
  solver.iterations = sweeps;
  return integrator_tests::make_world(json_text, solver);
}

// Two unit spheres pressed 3 cm into each other, off-centre, and sliding past each other, with a 4 cm smoothing skin
// (the scene of the removed newton integrator's test): vertices outside the skin, inside the smoothing
// band and past it, so every contact term is non-zero.
constexpr const char* kPressed = R"({ "gravity": [0, -9.81, 0],
    "collisions": { "contact": "smooth", "restitution": 0.3, "friction": 0.6, "smoothing": 0.04 },
    "bodies": [ { "mesh": "icosphere:2", "position": [0, 0, 0], "mass": 1.0, "stiffness": 300.0, "damping": 2.0,
                  "pressure": 40.0 },
                { "mesh": "icosphere:2", "position": [1.97, 0.1, 0.05], "mass": 1.5, "stiffness": 300.0,
                  "damping": 2.0, "pressure": 40.0 } ] })";

// The pressed pair's contacts lagged at x = x_n + ĥ v + 0.001 wiggle (left ball moving at (0.5, 0.2, 0), right one at
// (−0.5, −0.3, 0.4) m/s, + 0.2 wiggle), with x̃ = x_n.
struct PressedContacts {
  PressedContacts() : world(vbd_world(kPressed, 1)) {
    sim::State& s = world.state;
    const int right = world.model.bodies[1].first_vertex;
    base = s.x;
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      const Vec3 drift = static_cast<int>(i) < right ? Vec3(0.5, 0.2, 0.0) : Vec3(-0.5, -0.3, 0.4);
      s.v[i] = drift + 0.2 * wiggle(i, 0.0);
      x.push_back(s.x[i] + h_hat * s.v[i] + 0.001 * wiggle(i, 1.0));
    }
    contacts.build(world.model);
    contacts.lag(world.model, x, base, h_hat);
  }
  // Every vertex that takes part in a contact.
  std::vector<int> contact_vertices() {
    sim::BodyCollider collider;
    std::vector<sim::BodyCollider::SmoothFrame> frames;
    collider.find_smooth_frames(world.model.bodies, x, frames);
    std::vector<int> vertices;
    for (const auto& f : frames) {
      vertices.push_back(f.vertex);
      vertices.insert(vertices.end(), f.corners.begin(), f.corners.end());
    }
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    return vertices;
  }
  Vec3 gradient(int v) const {
    Vec3 g = Vec3::Zero();
    sim::Block3 unused;
    contacts.add_terms(v, g, unused);
    return g;
  }

  sim::World world;
  double h_hat = 2.0 / 3.0 / 60.0;
  std::vector<Vec3> x, base;
  sim::VertexContacts contacts;
};

Eigen::Matrix3d full(const sim::Block3& b) {
  return (Eigen::Matrix3d() << b.xx, b.xy, b.xz, b.xy, b.yy, b.yz, b.xz, b.yz, b.zz).finished();
}

// With the lags held, each vertex's gradient is the derivative of its local energy change, and its Hessian block the
// derivative of its gradient (central differences), for p and for the triangle corners alike.
TEST(VbdContact, VertexTermsMatchFiniteDifferencesOfTheLocalEnergy) {
  PressedContacts p;
  ASSERT_TRUE(p.contacts.active());
  const std::vector<int> vertices = p.contact_vertices();
  ASSERT_GT(p.contacts.contacts(), 10u);
  constexpr double kStep = 1e-7;  // m: small against the 4 cm skin
  double worst_gradient = 0.0, largest_gradient = 0.0, worst_hessian = 0.0, largest_hessian = 0.0;
  for (const int v : vertices) {
    Vec3 g = Vec3::Zero();
    sim::Block3 block;
    p.contacts.add_terms(v, g, block);
    const Eigen::Matrix3d H = full(block);
    for (int k = 0; k < 3; ++k) {
      const Vec3 e = kStep * Vec3::Unit(k);
      const double numeric = (p.contacts.energy_change(v, e) - p.contacts.energy_change(v, -e)) / (2.0 * kStep);
      worst_gradient = std::max(worst_gradient, std::abs(numeric - g[k]));
      Vec3& xv = p.x[static_cast<std::size_t>(v)];  // the contacts read x as it is now
      xv += e;
      const Vec3 plus = p.gradient(v);
      xv -= 2.0 * e;
      const Vec3 minus = p.gradient(v);
      xv += e;
      const Vec3 column = (plus - minus) / (2.0 * kStep);
      worst_hessian = std::max(worst_hessian, (column - H.col(k)).norm());
    }
    largest_gradient = std::max(largest_gradient, g.cwiseAbs().maxCoeff());
    largest_hessian = std::max(largest_hessian, H.cwiseAbs().maxCoeff());
    EXPECT_GE(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(H).eigenvalues().minCoeff(), -1e-9 * H.norm());
  }
  std::printf("%zu contacts, %zu vertices: gradient off by %.2e N of %.2e N, Hessian by %.2e N/m of %.2e N/m\n",
              p.contacts.contacts(), vertices.size(), worst_gradient, largest_gradient, worst_hessian, largest_hessian);
  EXPECT_GT(largest_gradient, 1.0);
  EXPECT_LT(worst_gradient, 1e-5 * largest_gradient);
  EXPECT_LT(worst_hessian, 1e-5 * largest_hessian);
}

// At the lag point −∇ of the contact terms is add_smooth_forces' force at BDF2's velocity v' = (x − x̃)/ĥ, and the
// vertices' gradients sum to zero (equal and opposite: momentum kept).
TEST(VbdContact, MinusTheGradientIsTheSmoothContactForce) {
  PressedContacts p;
  const sim::Model& model = p.world.model;
  std::vector<Vec3> velocity(p.x.size()), force(p.x.size(), Vec3::Zero());
  for (std::size_t i = 0; i < p.x.size(); ++i) velocity[i] = (p.x[i] - p.base[i]) / p.h_hat;
  const sim::SmoothResponse response =
      sim::resolve_smooth_response(model.body_contact.smooth, model.body_contact.material);
  sim::BodyCollider collider;
  ASSERT_GT(collider.add_smooth_forces(model.bodies, model.mass_kg, p.x, velocity, response, force), 0);
  double worst = 0.0, largest = 0.0;
  Vec3 sum = Vec3::Zero();
  for (std::size_t i = 0; i < p.x.size(); ++i) {
    const Vec3 g = p.gradient(static_cast<int>(i));
    worst = std::max(worst, (force[i] + g).norm());
    largest = std::max(largest, force[i].norm());
    sum += g;
  }
  std::printf("largest contact force %.3e N; max |f + grad| = %.3e N; |sum of gradients| %.2e N\n", largest, worst,
              sum.norm());
  EXPECT_GT(largest, 1.0);
  EXPECT_LT(worst, 1e-12 * largest);
  EXPECT_LT(sum.norm(), 1e-12 * largest);
}

// Total momentum Σ m v [kg m/s].
Vec3 momentum(const sim::World& world) {
  Vec3 sum = Vec3::Zero();
  for (std::size_t i = 0; i < world.state.v.size(); ++i) sum += world.model.mass_kg[i] * world.state.v[i];
  return sum;
}

// The pressed pair as a constant-step BDF2 history of steps of dt: x_{n−1} = x_n − dt v_n.
void give_history(sim::World& world, double dt) {
  world.state.carry.previous_dt_s = dt;
  world.state.carry.previous_v = world.state.v;
  world.state.carry.previous_x.clear();
  for (std::size_t i = 0; i < world.state.x.size(); ++i) {
    world.state.carry.previous_x.push_back(world.state.x[i] - dt * world.state.v[i]);
  }
}

// The two pressed spheres sliding past each other (the left one along +x, the right one along −x and z), with a
// BDF2 history of steps of dt.
void slide_past_each_other(sim::World& world, double dt) {
  const int right = world.model.bodies[1].first_vertex;
  for (std::size_t i = 0; i < world.state.x.size(); ++i) {
    world.state.v[i] = static_cast<int>(i) < right ? Vec3(0.5, 0.2, 0.0) : Vec3(-0.5, -0.3, 0.4);
  }
  give_history(world, dt);
}

// After 1000 sweeps a step's end state satisfies BDF2's equation with the model's own forces (Dynamics, the smooth
// body contact's add_smooth_forces included): m (x' − y)/ĥ² = f(x', (x' − x̃)/ĥ), as vbd_test.cpp checks for the floor.
TEST(VbdContact, ConvergedSweepsSolveBdf2WithTheSmoothContactForce) {
  sim::World world = vbd_world(kPressed, 1000);
  constexpr double kDt = 1.0 / 240.0;
  slide_past_each_other(world, kDt);
  const sim::State before = world.state;
  world.step(kDt);
  const double h_hat = 2.0 * kDt / 3.0;
  sim::Dynamics dynamics(world.model, world.workspace.forces);
  std::vector<Vec3> force;
  dynamics.forces(world.state, force);
  std::vector<Vec3> contact(world.state.x.size(), Vec3::Zero());
  sim::BodyCollider collider;
  const sim::SmoothResponse response =
      sim::resolve_smooth_response(world.model.body_contact.smooth, world.model.body_contact.material);
  const int touching = collider.add_smooth_forces(world.model.bodies, world.model.mass_kg, world.state.x, world.state.v,
                                                  response, contact);
  double worst = 0.0, scale = 0.0, largest_contact = 0.0;
  for (std::size_t i = 0; i < force.size(); ++i) {
    const Vec3 base = (4.0 * before.x[i] - before.carry.previous_x[i]) / 3.0;
    const Vec3 velocity = (4.0 * before.v[i] - before.carry.previous_v[i]) / 3.0;
    const Vec3 target = base + h_hat * velocity;  // gravity is in f
    const Vec3 inertia = world.model.mass_kg[i] * (world.state.x[i] - target) / (h_hat * h_hat);
    worst = std::max(worst, (inertia - force[i]).norm());
    scale = std::max(scale, force[i].norm());
    largest_contact = std::max(largest_contact, contact[i].norm());
  }
  std::printf("BDF2 residual after 1000 sweeps: %.2e N of forces up to %.2e N (%d contacts, up to %.2e N)\n", worst,
              scale, touching, largest_contact);
  EXPECT_GT(touching, 0);
  EXPECT_GT(largest_contact, 1.0);
  EXPECT_LT(worst, 1e-7 * scale);
}

// Without gravity the contact forces (equal and opposite) and the bodies' own forces change no momentum: a converged
// step keeps Σ m v (BDF2: Σ m v' = Σ m ṽ, which is Σ m v_n for a history with the same momentum).
TEST(VbdContact, ConvergedStepKeepsMomentum) {
  std::string scene = kPressed;
  scene.replace(scene.find("-9.81"), 5, "0");
  sim::World world = vbd_world(scene, 1000);
  constexpr double kDt = 1.0 / 240.0;
  slide_past_each_other(world, kDt);
  const Vec3 before = momentum(world);
  double speed = 0.0;  // Σ m |v| [kg m/s]
  for (std::size_t i = 0; i < world.state.v.size(); ++i) speed += world.model.mass_kg[i] * world.state.v[i].norm();
  for (int n = 0; n < 4; ++n) world.step(kDt);
  const Vec3 after = momentum(world);
  std::printf("momentum (%.6f, %.6f, %.6f) -> (%.6f, %.6f, %.6f) kg m/s; change %.2e of %.2e\n", before.x(), before.y(),
              before.z(), after.x(), after.y(), after.z(), (after - before).norm(), speed);
  EXPECT_LT((after - before).norm(), 1e-9 * speed);
}

// Two bounce balls (k 1000 N/m, c 5 N·s/m, nRT 200 J, 1 kg) stacked on the smooth floor, the top one dropped from
// 10 cm above the bottom one (1.4 m/s at the touch): the scene of the removed newton integrator's test.
constexpr const char* kTwoBalls = R"({ "gravity": [0, -9.81, 0],
    "floor": { "contact": "smooth", "restitution": 0.2, "friction": 0.8 },
    "collisions": { "contact": "smooth", "restitution": 0.2, "friction": 0.8 },
    "bodies": [ { "mesh": "icosphere:2", "position": [0, 1.0, 0], "mass": 1.0, "stiffness": 1000.0, "damping": 5.0,
                  "pressure": 200.0 },
                { "mesh": "icosphere:2", "position": [0, 3.1, 0], "mass": 1.0, "stiffness": 1000.0, "damping": 5.0,
                  "pressure": 200.0 } ] })";

// How deep the top ball is in the bottom one's contact skin: the largest d = δ − s over its vertices [m], and whether
// any of its vertices is inside the bottom ball by the winding number.
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

// The world over `samples` of 1/60 s in steps of dt: the deepest skin depth at the samples, the top ball's centre
// height at the last one and its mean over the second half, and the samples with a vertex inside the bottom ball.
struct StackRun {
  double deepest_m = 0.0, top_centre_m = 0.0, mean_top_centre_m = 0.0;
  int samples_inside = 0;
};
StackRun run_stack(const sim::Solver& solver, double dt, int samples) {
  sim::World world = integrator_tests::make_world(kTwoBalls, solver);
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
  if (solver.integrator == sim::IntegratorKind::Vbd) {
    const auto& stats = dynamic_cast<const sim::VertexBlockDescent&>(*world.workspace.integrator).statistics();
    std::printf("vbd: %lld steps in %d frames of 1/60 s, %.1f halvings per 1000 vertex solves\n", stats.steps, samples,
                1e3 * static_cast<double>(stats.halvings) / static_cast<double>(stats.vertex_solves));
  }
  return run;
}

// `vbd` stacking the two balls in 1/60 s frames for 2 s, beside the converged motion (rk4 at 0.1 ms, the same
// samples): no vertex of the top ball inside the bottom one at any sample, none deeper in the contact skin than
// `depth_ratio` × the converged motion's deepest, and the top ball's mean height over the last second within
// `mean_within_m` of the converged one's.
void expect_stack_as_converged(const sim::Solver& vbd, double depth_ratio, double mean_within_m) {
  constexpr int kSamples = 120;  // 2 s
  sim::Solver rk4;
  rk4.integrator = sim::IntegratorKind::Rk4;
  const StackRun run = run_stack(vbd, 1.0 / 60, kSamples);
  const StackRun converged = run_stack(rk4, 1e-4, kSamples);
  std::printf(
      "top ball in the bottom one's contact skin, deepest: vbd 1/60 s %.3f mm, rk4 0.1 ms %.3f mm; "
      "top centre's mean over 1-2 s %.4f m (vbd), %.4f m (rk4); samples with a vertex inside: %d, %d\n",
      1e3 * run.deepest_m, 1e3 * converged.deepest_m, run.mean_top_centre_m, converged.mean_top_centre_m,
      run.samples_inside, converged.samples_inside);
  EXPECT_EQ(run.samples_inside, 0);
  EXPECT_LT(run.deepest_m, depth_ratio * converged.deepest_m);
  EXPECT_NEAR(run.mean_top_centre_m, converged.mean_top_centre_m, mean_within_m);
}

// vbd at 1/60 s frames (8 sweeps; its steps shrink around the impacts): the top ball lands on the bottom
// one and stays on it without sinking in, by the criteria newton's test had: no vertex inside the bottom ball at any
// sample, none deeper in the contact skin than 1.1 × the converged motion's deepest (rk4 at 0.1 ms, the same samples),
// and the top ball within 2 cm of where the converged one oscillates (BDF2 keeps rk4's ±7 cm bounce on the gas springs,
// which backward Euler damps out, so the means over the last second are compared). Without the joint affine correction
// the mean sat 9 cm low at 4 sweeps (the stack's weight crossed one body per sweep); with it, 4 sweeps go 1.10 mm deep
// (1.14× rk4's 0.96 mm) with the mean 1.8 cm low, 8 sweeps 0.975 mm with the mean within 0.1 cm.
TEST(VbdContact, TwoBallsStackAtOneSixtiethOfASecondWithoutSinkingIn) {
  sim::Solver vbd;
  vbd.integrator = sim::IntegratorKind::Vbd;
  vbd.iterations = 8;
  expect_stack_as_converged(vbd, 1.1, 0.02);
}

// The same stack with "iterations": "converge": the bodies' sweeps, taken in turn, stop together where a sweep moves
// no vertex of either by more than the tolerance. Measured: 1.057 mm deep (1.10× rk4; 4 sweeps 1.14×, 8 sweeps 1.02×)
// and the top ball's mean 0.01 cm from rk4's (8 sweeps 0.1 cm), so the depth is held to 4 sweeps' bound, the mean to
// 0.5 cm.
TEST(VbdContact, TwoBallsStackWithSweepsUntilConverged) {
  sim::Solver vbd;
  vbd.integrator = sim::IntegratorKind::Vbd;
  vbd.sweep_control = sim::SweepControl::Converge;
  expect_stack_as_converged(vbd, 1.15, 0.005);
}

// A scene with vbd and the smooth contact between bodies (or smooth self-contact) is planned like any other: the
// program once refused it.
TEST(VbdContact, ScenesWithTheSmoothBodyContactAreAccepted) {
  sim::Solver solver;
  solver.integrator = sim::IntegratorKind::Vbd;
  solver.substeps = 2;
  for (const std::string& scene : {std::string(kTwoBalls), std::string(R"({ "collisions": { "contact": "smooth" },
          "bodies": [ { "mesh": "tube:12,10", "scale": 0.08, "self_collision": true } ] })")}) {
    sim::World world = integrator_tests::make_world(scene, solver);
    const sim::StepPlan plan = sim::resolve_step(world.model, world.state, 1.0 / 30, "scene.json");
    EXPECT_DOUBLE_EQ(plan.dt_s, 1.0 / 60);
  }
}

}  // namespace
