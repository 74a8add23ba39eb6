// vbd's lanes (sim/integrators/vertex_move_lanes.hpp): four or eight vertices of a colour moved at once must give the
// same bits as vertex_move one vertex at a time, through an impact on the smooth floor, with the coarse level and on
// threads.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "sim/forces/dynamics.hpp"
#include "sim/forces/forces.hpp"
#include "sim/integrators/correction_lanes.hpp"
#include "sim/integrators/vertex_block_descent.hpp"
#include "sim/integrators/vertex_move_lanes.hpp"
#include "support.hpp"

namespace {

// A ball thrown at the smooth floor with friction, springs, dampers, bending links and gas: 0.1 m above it at 2 m/s,
// so the steps of 1/60 s below meet the impact.
constexpr const char* kThrownBall = R"({
  "gravity": [0, -9.81, 0],
  "floor": { "height": 0.0, "contact": "smooth", "restitution": 0.5, "friction": 0.5 },
  "bodies": [ { "mesh": "icosphere:LEVEL", "position": [0, 1.1, 0], "velocity": [1.0, -2.0, 0.3],
                "mass": 1.0, "stiffness": 1000.0, "damping": 1.0, "pressure": 200.0, "bending": 50.0 } ]
})";

struct LanesRun {
  sim::State state;
  sim::VertexBlockDescent::Statistics statistics;
};

// 0.25 s of steps of 1/60 s with `lanes` vertices at once (1: the lanes off; 4: AVX2; 8: AVX-512F), the ball an
// icosphere of `level`.
LanesRun run(int lanes, int level, int threads, int coarse_cells) {
  sim::enable_lanes(lanes > 1);
  sim::enable_wide_lanes(lanes == 8);
  sim::Solver solver;
  solver.integrator = sim::IntegratorKind::Vbd;
  solver.threads = threads;
  std::string scene = kThrownBall;
  scene.replace(scene.find("LEVEL"), 5, std::to_string(level));
  sim::World world = integrator_tests::make_world(scene, solver);
  sim::VertexBlockDescent vbd(4, true, coarse_cells);
  sim::Dynamics dynamics(world.model, world.workspace.forces);
  for (int step = 0; step < 15; ++step) vbd.step(dynamics, world.state, 1.0 / 60.0);
  sim::enable_lanes(true);
  sim::enable_wide_lanes(true);
  return {world.state, vbd.statistics()};
}

bool same_bits(const sim::State& a, const sim::State& b) {
  return a.x.size() == b.x.size() && std::memcmp(a.x.data(), b.x.data(), a.x.size() * sizeof(softbody::Vec3)) == 0 &&
         std::memcmp(a.v.data(), b.v.data(), a.v.size() * sizeof(softbody::Vec3)) == 0;
}

// The lane counts this CPU runs, beside one vertex at a time.
std::vector<int> lane_counts() {
  std::vector<int> counts;
  if (sim::lanes_available()) counts.push_back(4);
  if (sim::wide_lanes_available()) counts.push_back(8);
  return counts;
}

TEST(VbdLanes, TheSameBitsAsOneVertexAtATime) {
  struct Case {
    int level, threads, cells;
  };
  if (!sim::wide_lanes_available()) std::printf("this CPU has no AVX-512F: the eight lanes are not tested here\n");
  // Icosphere:4's larger colours are shared between two threads (at least 256 vertices each); icosphere:3's are not.
  for (const Case c : {Case{3, 1, 0}, Case{3, 1, 16}, Case{4, 2, 0}}) {
    const LanesRun without = run(1, c.level, c.threads, c.cells);
    EXPECT_EQ(without.statistics.lane_moves, 0);
    double lowest = without.state.x[0].y();
    for (const softbody::Vec3& x : without.state.x) lowest = std::min(lowest, x.y());
    EXPECT_LT(lowest, 0.0) << "the steps should reach the floor";
    for (const int lanes : lane_counts()) {
      const LanesRun with = run(lanes, c.level, c.threads, c.cells);
      const auto& s = with.statistics;
      std::printf(
          "icosphere:%d, %d thread(s), %d cells, %d lanes: %lld of %lld local steps in lanes, %lld steps, "
          "lowest vertex at y %.4f m\n",
          c.level, c.threads, c.cells, lanes, s.lane_moves, s.vertex_solves, s.steps, lowest);
      EXPECT_TRUE(same_bits(with.state, without.state))
          << c.level << ", " << c.threads << " thread(s), " << c.cells << " cells, " << lanes << " lanes";
      EXPECT_EQ(s.vertex_solves, without.statistics.vertex_solves);
      EXPECT_EQ(s.sure_steps, without.statistics.sure_steps);
      EXPECT_GT(s.lane_moves, s.vertex_solves / 2) << "the lanes should serve";
    }
  }
}

// The enclosed volume in chunks is the same bits with its faces' terms in lanes as one at a time, and on one thread as
// on two, and equals enclosed_volume's one-pass sum to round-off: on a dented, shifted ball (no symmetry to hide a
// wrong corner), one chunk or many, and with a face count that leaves a tail.
TEST(VbdLanes, EnclosedVolumeTheSameBits) {
  for (const int level : {2, 5}) {
    sim::Solver solver;
    solver.threads = 2;
    std::string scene = kThrownBall;
    scene.replace(scene.find("LEVEL"), 5, std::to_string(level));
    sim::World world = integrator_tests::make_world(scene, solver);
    std::vector<softbody::Vec3> x = world.state.x;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double s = static_cast<double>(i);
      x[i] += softbody::Vec3(0.3, -0.2, 0.1) + 0.01 * softbody::Vec3(std::sin(3.1 * s), std::cos(1.7 * s), std::sin(s));
    }
    std::vector<softbody::Triangle> faces = world.model.bodies[0].topology.faces;
    if (level == 2) faces.pop_back();  // 319 faces: a tail short of a lane group (an open surface: any sum will do)
    std::vector<double> partials;
    sim::enable_lanes(false);
    const double expected = sim::enclosed_volume_in_lanes(faces, x, nullptr, partials);
    sim::enable_lanes(true);
    EXPECT_NEAR(expected, sim::enclosed_volume(faces, x), 1e-14 * std::abs(expected)) << "icosphere:" << level;
    for (sim::PartRunner* runner : {static_cast<sim::PartRunner*>(nullptr), world.workspace.forces.runner.get()}) {
      const double in_lanes = sim::enclosed_volume_in_lanes(faces, x, runner, partials);
      EXPECT_EQ(std::memcmp(&expected, &in_lanes, sizeof(double)), 0)
          << "icosphere:" << level << ": " << expected << " against " << in_lanes << " in lanes";
    }
  }
}

}  // namespace
