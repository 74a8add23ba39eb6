// Body–body contact: momentum conserved in a head-on collision, no vertex left inside another body.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "sim/contact/body_collision.hpp"
#include "sim/step/diagnostics.hpp"
#include "sim/step/world.hpp"
#include "test_helpers.hpp"

namespace {

using softbody::Vec3;
using testing_support::total_momentum;

// Two balls meet head-on at 2 m/s each, with no friction and no gravity or floor. The contact impulses
// act in equal and opposite pairs (the vertex gets +J, the triangle's corners −w_k J with Σ w_k = 1), so
// the total momentum stays what it was to round-off, and the balls bounce apart.
TEST(BodyCollision, HeadOnCollisionConservesMomentumAndSeparates) {
  sim::World world = testing_support::world_from_text(R"({
    "gravity": [0, 0, 0],
    "solver": { "integrator": "symplectic" },
    "collisions": { "restitution": 0.8, "friction": 0.0 },
    "bodies": [
      { "mesh": "icosphere:2", "position": [-1.3, 0, 0], "velocity": [2, 0, 0], "mass": 1.0,
        "stiffness": 2000.0, "damping": 0.0, "pressure": 100.0 },
      { "mesh": "icosphere:2", "position": [1.3, 0.1, 0], "velocity": [-2, 0, 0], "mass": 1.5,
        "stiffness": 2000.0, "damping": 0.0, "pressure": 100.0 } ] })");
  const Vec3 before = total_momentum(world);
  testing_support::run_steps(world, 40000, 2.5e-5);  // 1 s: they touch after ~0.08 s
  const Vec3 after = total_momentum(world);
  EXPECT_LT((after - before).norm(), 1e-12) << before.transpose() << " -> " << after.transpose();
  const double vx_left = sim::diagnose(world.model, world.state, 0).com_velocity_m_per_s.x();
  const double vx_right = sim::diagnose(world.model, world.state, 1).com_velocity_m_per_s.x();
  EXPECT_LT(vx_left, -0.5) << "the lighter ball bounces back";
  EXPECT_GT(vx_right, 0.2) << "the heavier one too";
  EXPECT_GT(sim::diagnose(world.model, world.state, 1).com_m.x() - sim::diagnose(world.model, world.state, 0).com_m.x(),
            2.0)
      << "apart again";
}

// A small pile on a floor with friction: at the end no vertex of any body is inside another body
// (generalised winding number below one half).
TEST(BodyCollision, NoVertexEndsInsideAnotherBody) {
  sim::World world = testing_support::world_from_text(R"({
    "solver": { "integrator": "symplectic" },
    "floor": { "contact": "friction", "restitution": 0.1, "friction": 0.9 },
    "collisions": { "restitution": 0.1, "friction": 0.9 },
    "bodies": [
      { "mesh": "cube:4", "position": [0, 0.6, 0], "mass": 1.0, "stiffness": 3000.0, "damping": 4.0, "pressure": 40.0 },
      { "mesh": "icosphere:2", "position": [0.1, 1.8, 0], "scale": 0.5, "mass": 0.5, "stiffness": 3000.0, "damping": 3.0, "pressure": 30.0 },
      { "mesh": "capsule:12", "position": [-0.1, 3.0, 0.1], "scale": 0.5, "mass": 0.4, "stiffness": 3000.0, "damping": 3.0, "pressure": 20.0 } ] })");
  testing_support::run_steps(world, 40000, 2.5e-5);  // 1 s: landed and piled
  int inside = 0;
  double deepest = 0.0;
  for (std::size_t a = 0; a < world.model.bodies.size(); ++a) {
    for (std::size_t b = 0; b < world.model.bodies.size(); ++b) {
      if (a == b) continue;
      const sim::Body& surface = world.model.bodies[b];
      for (const Vec3& p : world.model.of(world.model.bodies[a], world.state.x)) {
        const double w = sim::winding_number(world.model.of(surface, world.state.x), surface.topology.faces, p);
        deepest = std::max(deepest, w);
        if (w > 0.5) ++inside;
      }
    }
  }
  EXPECT_EQ(inside, 0) << "largest winding number " << deepest;
  // And they did pile up: the ball rests above the cube, not beside it on the floor.
  EXPECT_GT(sim::diagnose(world.model, world.state, 1).min_y_m, 0.5);
}

// Two balls started 10 cm into each other, with no gravity, floor, damping, restitution or friction: only the
// contact moves them apart. A push moves a vertex without a force, against its springs and gas, so it adds
// energy about in proportion to its speed (measured over this 1 s: +1.403 J with the old limit alone, a twentieth
// of the mean edge per step; at push speeds of 1, 0.3, 0.1 and 0.03 m/s: +0.297, +0.106, -0.007, -0.041 J). At the
// default push speed the impulses take more than the pushes add, and the balls come apart all the same.
TEST(BodyCollision, AnInitialOverlapIsPushedOutWithoutAddingEnergy) {
  const auto run = [](const std::string& collisions) {
    sim::World world = testing_support::world_from_text(R"({
      "gravity": [0, 0, 0],
      "solver": { "integrator": "symplectic" },
      "collisions": )" + collisions + R"(,
      "bodies": [
        { "mesh": "icosphere:2", "position": [-0.95, 0, 0], "mass": 1.0, "stiffness": 2000.0, "damping": 0.0, "pressure": 100.0 },
        { "mesh": "icosphere:2", "position": [0.95, 0, 0], "mass": 1.0, "stiffness": 2000.0, "damping": 0.0, "pressure": 100.0 } ] })");
    const auto energy = [&world] {
      return sim::diagnose(world.model, world.state, 0).total_J() +
             sim::diagnose(world.model, world.state, 1).total_J();
    };
    const double before = energy();
    testing_support::run_steps(world, 40000, 2.5e-5);  // 1 s
    const double apart =
        sim::diagnose(world.model, world.state, 1).com_m.x() - sim::diagnose(world.model, world.state, 0).com_m.x();
    return std::pair{energy() - before, apart};
  };
  const auto [gained, apart] = run(R"({ "restitution": 0.0, "friction": 0.0 })");
  EXPECT_LT(gained, 0.0) << "J: the default push speed (0.1 m/s) adds less than the impulses take";
  EXPECT_GT(apart, 2.2) << "m between the centres: the unit balls no longer overlap";
  const double gained_fast = run(R"({ "restitution": 0.0, "friction": 0.0, "push_speed": 1e9 })").first;
  EXPECT_GT(gained_fast, 1.0) << "J: pushes limited only by a twentieth of the edge per step (the old rule) add energy";
}

// Two balls meeting head-on at 1 m/s each with the smooth body contact, elastic (restitution 1: no dashpot), no
// friction, damping or gravity: the contact springs are conservative, so the total energy, with their stored
// energy (BodyDiagnostics::contact_J, Σ m ω² δ² R(d/δ) of each body's vertices in the other), stays what it was
// through the collision. Measured at dt 1e-5 s, every 10 ms: within 1.8 mJ of the start (symplectic Euler's
// oscillating error on the internal modes) while the contact springs hold up to 0.067 J; before they were
// counted the total dipped by that much.
TEST(BodyCollision, SmoothContactEnergyIsCountedAndConservedThroughAnElasticCollision) {
  sim::World world = testing_support::world_from_text(R"({
    "gravity": [0, 0, 0],
    "solver": { "integrator": "symplectic" },
    "collisions": { "contact": "smooth", "restitution": 1.0, "friction": 0.0 },
    "bodies": [
      { "mesh": "icosphere:2", "position": [-1.2, 0, 0], "velocity": [1, 0, 0], "mass": 1.0, "stiffness": 2000.0, "damping": 0.0, "pressure": 100.0 },
      { "mesh": "icosphere:2", "position": [1.2, 0, 0], "velocity": [-1, 0, 0], "mass": 1.0, "stiffness": 2000.0, "damping": 0.0, "pressure": 100.0 } ] })");
  const auto total = [&world](double& contact) {
    const sim::BodyDiagnostics a = sim::diagnose(world.model, world.state, 0),
                               b = sim::diagnose(world.model, world.state, 1);
    contact = a.contact_J + b.contact_J;
    return a.total_J() + b.total_J();
  };
  double contact = 0.0, most_stored = 0.0, worst = 0.0;
  const double start = total(contact);
  EXPECT_EQ(contact, 0.0) << "J: apart at the start";
  for (int k = 0; k < 60; ++k) {  // 0.6 s: they meet at about 0.2 s and part by 0.4 s
    testing_support::run_steps(world, 1000, 1e-5);
    const double now = total(contact);
    most_stored = std::max(most_stored, contact);
    worst = std::max(worst, std::abs(now - start));
  }
  std::printf("largest contact energy %.4f J, largest change of the total %.2e J\n", most_stored, worst);
  EXPECT_GT(most_stored, 0.03) << "J: the contact springs hold energy while the balls are pressed together";
  EXPECT_LT(worst, 0.005) << "J: the total, contact springs included, is conserved";
  EXPECT_GT(sim::diagnose(world.model, world.state, 1).com_velocity_m_per_s.x(), 0.8) << "m/s: they bounce back";
}

// A thin tetrahedron ABCD (a blade) in a scratch folder of that name: its faces ABC and ABD meet at the edge AB,
// along x, at 11.4°, opening towards +z. Returns the OBJ's path.
std::filesystem::path write_blade(const std::string& folder) {
  const std::filesystem::path blade = testing_support::scratch_dir(folder) / "blade.obj";
  std::ofstream out(blade);
  out << "v -1 0 0\nv 1 0 0\nv 0 0.1 1\nv 0 -0.1 1\n"  // A B C D
      << "f 1 4 2\nf 1 2 3\nf 1 3 4\nf 2 4 3\n";       // outward: ABD, ABC, ACD, BDC
  return blade;
}

// The smooth contact's inside/outside test next to a sharp edge: a thin tetrahedron whose faces ABC and ABD meet
// at the edge AB at 11.4° (a blade, as the split teapot's lid rim), and a small ball (icosphere:2, radius 5 cm)
// centred 3 cm in front of that edge, so that its vertices surround it, some inside the blade. Each frame's side
// (the sign of its signed distance) must agree with the generalised winding number. A point in front of the edge
// is nearest to both faces; by the first face's own normal alone (before 2026-12-03) the points on the other
// face's side were taken as inside (measured: 56 of the 162 frames), and the contact pushed them the wrong way
// with a spring as deep as the search (the split teapot gained 0.4 J in 0.1 s). The angle-weighted
// pseudonormal of the edge or corner (Bærentzen & Aanæs 2005) gets every side right.
TEST(BodyCollision, SmoothContactTellsInsideFromOutsideNextToASharpEdge) {
  const std::filesystem::path blade = write_blade("sharp_edge");
  sim::World world = testing_support::world_from_text(R"({
    "collisions": { "contact": "smooth" },
    "bodies": [ { "mesh": ")" + blade.string() + R"(" },
                { "mesh": "icosphere:2", "scale": 0.05, "position": [0, 0, -0.03] } ] })");
  sim::BodyCollider collider;
  std::vector<sim::BodyCollider::SmoothFrame> frames;
  collider.find_smooth_frames(world.model.bodies, world.state.x, frames);
  const sim::Body& surface = world.model.bodies[0];
  int disagree = 0, against_blade = 0;
  for (const sim::BodyCollider::SmoothFrame& frame : frames) {
    if (frame.corners[0] >= world.model.bodies[1].first_vertex) continue;  // the blade's corners against the ball
    ++against_blade;
    const double w = sim::winding_number(world.model.of(surface, world.state.x), surface.topology.faces,
                                         world.state.x[frame.vertex]);
    if (std::abs(frame.signed_distance_m) > 1e-9 && (frame.signed_distance_m < 0.0) != (w > 0.5)) ++disagree;
  }
  std::printf("%d frames against the blade, %d on the wrong side\n", against_blade, disagree);
  EXPECT_GT(against_blade, 100);
  EXPECT_EQ(disagree, 0);
}

// The impulse contact next to the same blade: a small ball (radius 5 cm) centred 8 cm in front of the sharp edge,
// all of it outside the blade and at least 3 cm from it (the contact's thickness is 2 % of the blade's mean edge,
// 2.6 cm). No vertex is in contact, so none may move. By the nearest face's plane alone (before 2026-12-03) the
// vertices on the other face's side were behind it, taken as inside and pushed, and those on the chosen face's
// side nearer to its plane than the thickness though 3 cm or more from the edge (measured: 112 contacts). The
// distance to the edge or corner, on the side of its pseudonormal, leaves them all alone.
TEST(BodyCollision, ImpulseContactLeavesAVertexInFrontOfASharpEdgeAlone) {
  const std::filesystem::path blade = write_blade("sharp_edge_impulse");
  sim::World world = testing_support::world_from_text(R"({
    "bodies": [ { "mesh": ")" + blade.string() + R"(" },
                { "mesh": "icosphere:2", "scale": 0.05, "position": [0, 0, -0.08] } ] })");
  const std::vector<Vec3> before = world.state.x;
  sim::BodyCollider collider;
  const int contacts = collider.resolve(world.model.bodies, world.model.inverse_mass, world.state,
                                        world.model.body_contact.material, sim::PushLimit{1e-3, 1e9, true});
  EXPECT_EQ(contacts, 0);
  EXPECT_EQ(world.state.x, before) << "no vertex moved";
}

TEST(BodyCollision, WindingNumberIsOneInsideZeroOutside) {
  sim::World world = testing_support::world_from_text(R"({ "bodies": [ { "mesh": "icosphere:2" } ] })");
  const sim::Body& body = world.model.bodies[0];
  EXPECT_NEAR(sim::winding_number(world.model.of(body, world.state.x), body.topology.faces, Vec3(0.1, 0.2, 0.3)), 1.0,
              1e-9);
  EXPECT_NEAR(sim::winding_number(world.model.of(body, world.state.x), body.topology.faces, Vec3(1.5, 0.2, 0.3)), 0.0,
              1e-9);
}

}  // namespace
