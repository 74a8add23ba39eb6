// The bending links as forces: topology, minus the gradient of their energy, balanced, zero at rest, the
// hinge's analytic frequency, energy conserved by velocity Verlet at second order.
#include <cmath>
#include <cstdio>
#include <numbers>

#include <gtest/gtest.h>

#include "mesh/generators.hpp"
#include "sim/forces/bending.hpp"
#include "sim/forces/dynamics.hpp"
#include "sim/forces/energy.hpp"
#include "sim/step/diagnostics.hpp"
#include "sim/step/world.hpp"

namespace {

using softbody::Triangle;
using softbody::Vec3;

// A body of icosphere:2 (162 vertices) with bending links only (k = c = 0 on the edges, no gas).
sim::Body links_only_body(const std::vector<Vec3>& x, const std::vector<Triangle>& faces, double k_b) {
  sim::Body body = sim::build_body(x, faces, 1.0);
  body.params.bending_N_per_m = k_b;
  sim::add_bending_links(body, x);
  return body;
}

// x moved by a smooth, deterministic field of amplitude `amplitude` [m].
std::vector<Vec3> perturbed(std::vector<Vec3> x, double amplitude) {
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double s = static_cast<double>(i);
    x[i] += amplitude * Vec3(std::sin(1.7 * s), std::cos(0.9 * s + 0.3), std::sin(2.3 * s + 1.1));
  }
  return x;
}

std::vector<Vec3> forces_of(sim::World& world) {
  sim::Dynamics dynamics(world.model, world.workspace.forces);
  std::vector<Vec3> f;
  dynamics.forces(world.state, f);
  return f;
}

TEST(BendingLinks, TetrahedronLinksEachEdgeToTheOppositeOne) {
  // Edge (0, 1) of a tetrahedron has the vertices 2 and 3 across it, and so on: the six links are the six edges.
  const std::vector<Triangle> faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  const std::vector<std::array<int, 2>> links = sim::bending_links(faces);
  const std::vector<std::array<int, 2>> expected = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  EXPECT_EQ(links, expected);
}

TEST(BendingLinks, ClosedMeshHasOneLinkPerEdgeAndNoLinkIsAnEdge) {
  const mesh::TriMesh sphere = mesh::icosphere(2);
  const sim::Body body = sim::build_body(sphere.vertices, sphere.triangles, 1.0);
  const auto links = sim::bending_links(sphere.triangles);
  EXPECT_EQ(links.size(), body.topology.edges.size());  // every edge of a closed mesh is interior
  for (const auto& link : links) {
    EXPECT_FALSE(std::binary_search(body.topology.edges.begin(), body.topology.edges.end(), link));
  }
}

TEST(BendingForce, IsMinusTheGradientOfTheEnergy) {
  const mesh::TriMesh sphere = mesh::icosphere(2);
  const double k_b = 250.0;
  sim::Body body = links_only_body(sphere.vertices, sphere.triangles, k_b);
  const std::vector<Vec3> x = perturbed(sphere.vertices, 0.02);  // edges ~0.3 m: a few % bent
  sim::World world = sim::one_body_world(Vec3::Zero(), std::nullopt, sim::Solver{}, std::move(body), x, Vec3::Zero());
  const sim::Body& reference = world.model.bodies[0];  // its constraints built by the model
  const std::vector<Vec3> f = forces_of(world);
  // Central differences of E_b: O(h²) truncation (h = 1e-6 m) against round-off ε E / h.
  const double h = 1e-6;
  double worst = 0.0, largest = 0.0;
  std::vector<Vec3> y = x;
  for (std::size_t i = 0; i < x.size(); i += 7) {
    for (int d = 0; d < 3; ++d) {
      y[i][d] = x[i][d] + h;
      const double up = sim::bending_energy(reference, y);
      y[i][d] = x[i][d] - h;
      const double down = sim::bending_energy(reference, y);
      y[i][d] = x[i][d];
      const double gradient = (up - down) / (2 * h);
      worst = std::max(worst, std::abs(f[i][d] + gradient));
      largest = std::max(largest, std::abs(f[i][d]));
    }
  }
  ASSERT_GT(largest, 1.0);  // the bent links do push (k_b · 2 cm ~ 5 N)
  EXPECT_LT(worst, 1e-6 * largest) << "largest force " << largest;
}

TEST(BendingForce, SumsToZeroForceAndTorqueAndVanishesAtRest) {
  const mesh::TriMesh sphere = mesh::icosphere(2);
  sim::World at_rest =
      sim::one_body_world(Vec3::Zero(), std::nullopt, sim::Solver{},
                          links_only_body(sphere.vertices, sphere.triangles, 500.0), sphere.vertices, Vec3::Zero());
  for (const Vec3& f : forces_of(at_rest)) EXPECT_EQ(f.norm(), 0.0);  // |d| = ℓ0 exactly: no stretch

  const std::vector<Vec3> x = perturbed(sphere.vertices, 0.03);
  sim::World bent = sim::one_body_world(Vec3::Zero(), std::nullopt, sim::Solver{},
                                        links_only_body(sphere.vertices, sphere.triangles, 500.0), x, Vec3::Zero());
  const std::vector<Vec3> f = forces_of(bent);
  Vec3 total = Vec3::Zero(), torque = Vec3::Zero();
  double scale = 0.0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    total += f[i];
    torque += x[i].cross(f[i]);
    scale += f[i].norm();
  }
  ASSERT_GT(scale, 10.0);
  // Each link's pair of forces is equal, opposite and along the link: zero to round-off (ε · Σ|f|).
  EXPECT_LT(total.norm(), 1e-13 * scale);
  EXPECT_LT(torque.norm(), 1e-13 * scale);
}

// The hinge: two triangles (i, j, a) and (j, i, b) on the axis z through i and j, each wing of height h at an
// angle α from the bisecting plane x = 0, tips of mass m, i and j so heavy that they stay put, edges far
// stiffer than the link. Folding both wings by δ changes the link |a − b| = 2h sin α by 2h cos α δ:
//   U = ½ k_b (2h cos α δ)²,  T = 2 · ½ m h² δ̇²   ⇒   ω² = 2 k_b cos²α / m
// (the edges' stiffness k shifts it by O(k_b/k), the axis' mass by O(m/M)).
TEST(BendingHinge, FoldsAtTheAnalyticFrequency) {
  const double h = 0.3, alpha = 0.6, m = 0.01, k_b = 4.0, k = 4e5, heavy = 1e5;
  const std::vector<Vec3> x0 = {{0, 0, 0},
                                {0, 0, 1},
                                {h * std::sin(alpha), h * std::cos(alpha), 0.5},
                                {-h * std::sin(alpha), h * std::cos(alpha), 0.5}};
  sim::Body body;
  body.vertex_count = 4;
  body.topology.faces = {{0, 1, 2}, {1, 0, 3}};
  body.topology.edges = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}};
  for (const auto& [i, j] : body.topology.edges) body.rest.edge_length_m.push_back((x0[i] - x0[j]).norm());
  sim::add_bending_links(body, x0);
  ASSERT_EQ(body.topology.bending_links.size(), 1u);
  body.masses.kg = {heavy, heavy, m, m};
  for (double mass : body.masses.kg) body.masses.inverse.push_back(1.0 / mass);
  body.masses.total_kg = 2 * heavy + 2 * m;
  body.params.stiffness_N_per_m = k;
  body.params.bending_N_per_m = k_b;
  // Folded by δ0 = 0.01 rad: each tip turned about the z axis towards the other.
  const double delta0 = 0.01;
  std::vector<Vec3> x = x0;
  x[2] = Vec3(h * std::sin(alpha - delta0), h * std::cos(alpha - delta0), 0.5);
  x[3] = Vec3(-h * std::sin(alpha - delta0), h * std::cos(alpha - delta0), 0.5);
  const double omega = std::sqrt(2 * k_b * std::cos(alpha) * std::cos(alpha) / m);
  sim::World world = sim::one_body_world(Vec3::Zero(), std::nullopt, sim::Solver{sim::IntegratorKind::Verlet},
                                         std::move(body), x, Vec3::Zero());
  // Velocity Verlet at 1/2000 of the period; the link's length crosses its rest length twice per period.
  const double period = 2 * std::numbers::pi / omega, dt = period / 2000;
  auto stretch = [&] { return (world.state.x[2] - world.state.x[3]).norm() - 2 * h * std::sin(alpha); };
  std::vector<double> crossings;
  double before = stretch(), t = 0.0;
  while (crossings.size() < 11) {
    world.step(dt);
    t += dt;
    const double now = stretch();
    if ((before < 0) != (now < 0)) crossings.push_back(t - dt * now / (now - before));  // linear interpolation
    before = now;
    ASSERT_LT(t, 20 * period);
  }
  const double measured_period = (crossings[10] - crossings[0]) / 5.0;  // ten half periods
  std::printf("hinge: period %.6g s measured, %.6g s analytic\n", measured_period, period);
  EXPECT_NEAR(measured_period / period, 1.0, 2e-3) << "ω = " << omega << " rad/s";
}

// Undamped, without gas or gravity, velocity Verlet keeps E = T + U_springs + U_links within O(h²): the error at
// h is four times the error at h/2 (it would drift, not oscillate, if the link force were not −∇E_b).
TEST(BendingEnergy, VelocityVerletConservesItAtSecondOrder) {
  const mesh::TriMesh sphere = mesh::icosphere(1);
  auto run = [&](double dt) {
    sim::Body body = sim::build_body(sphere.vertices, sphere.triangles, 1.0);
    body.params.stiffness_N_per_m = 100.0;
    body.params.bending_N_per_m = 300.0;  // stiffer than the edges: the links' modes are the fastest
    sim::add_bending_links(body, sphere.vertices);
    sim::World world = sim::one_body_world(Vec3::Zero(), std::nullopt, sim::Solver{sim::IntegratorKind::Verlet},
                                           std::move(body), perturbed(sphere.vertices, 0.05), Vec3::Zero());
    const double e0 = sim::diagnose(world.model, world.state, 0).total_J();
    double worst = 0.0;
    const auto steps = std::lround(1.0 / dt);
    for (long s = 0; s < steps; ++s) {
      world.step(dt);
      worst = std::max(worst, std::abs(sim::diagnose(world.model, world.state, 0).total_J() - e0));
    }
    return worst / e0;
  };
  const double coarse = run(5e-4), fine = run(2.5e-4);
  std::printf("largest relative energy error: %.3g at h = 5e-4 s, %.3g at 2.5e-4 s (ratio %.3f)\n", coarse, fine,
              coarse / fine);
  EXPECT_LT(coarse, 1e-2);
  EXPECT_NEAR(coarse / fine, 4.0, 0.6) << "relative energy errors " << coarse << " and " << fine;
}

}  // namespace
