// rk45 in the frame loop, contacts with every integrator, and bit-identical reruns.
#include <algorithm>
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "core/errors.hpp"
#include "frames/frame_clock.hpp"
#include "frames/frame_loop.hpp"
#include "support.hpp"

namespace {

using integrator_tests::make_world;

constexpr const char* kBounce = R"({
  "gravity": [0, -9.81, 0],
  "floor": { "height": 0.0 },
  "bodies": [ { "mesh": "icosphere:2", "position": [0, 1.3, 0], "velocity": [1, -2, 0],
                "mass": 1.0, "stiffness": 1000.0, "damping": 1.0, "pressure": 50.0 } ]
})";

// Records, for every frame, the time the loop announces and the world's own clock.
class TimeRecorder final : public frames::FrameSink {
 public:
  void on_frame(int, double time_s, const sim::World& world) override {
    announced.push_back(time_s);
    world_time.push_back(world.state.time_s);
    lowest_y = std::min(lowest_y, lowest(world));
    double mean_y = 0.0;
    for (const softbody::Vec3& x : world.state.x) mean_y += x.y() / static_cast<double>(world.state.x.size());
    centre_y.push_back(mean_y);
  }
  void finish(bool) override {}
  static double lowest(const sim::World& world) {
    double y = 1e300;
    for (const softbody::Vec3& x : world.state.x) y = std::min(y, x.y());
    return y;
  }
  std::vector<double> announced, world_time, centre_y;
  double lowest_y = 1e300;
};

TEST(Rk45FrameLoop, LandsExactlyOnEveryFrameTimeAndCountsSteps) {
  sim::World world = make_world(kBounce, sim::IntegratorKind::Rk45, 1e-5);
  const frames::FrameClock clock = frames::plan_frames(1.0, 30, 1e-4);
  TimeRecorder recorder;
  frames::FrameSink* sinks[] = {&recorder};
  const frames::RunStats stats = frames::run_frames(world, clock, sinks);
  ASSERT_EQ(recorder.announced.size(), 31u);
  for (std::size_t f = 0; f < recorder.announced.size(); ++f) {
    EXPECT_EQ(recorder.world_time[f], recorder.announced[f]) << "frame " << f;  // exactly, not nearly
  }
  EXPECT_EQ(stats.steps, world.state.steps);
  EXPECT_EQ(stats.rejected_steps, world.state.rejected_steps);
  EXPECT_GT(stats.steps, 30);
  EXPECT_GE(recorder.lowest_y, 0.0) << "the contact projection runs after every accepted step";
}

TEST(Rk45FrameLoop, TooTightAToleranceIsReportedAsDivergence) {
  sim::World world = make_world(kBounce, sim::IntegratorKind::Rk45, 1e-300);
  EXPECT_THROW(world.advance_to(0.1), softbody::DivergedError);
}

class EveryIntegrator : public ::testing::TestWithParam<sim::IntegratorKind> {};

// Contacts stay a post-step projection for every integrator: no vertex is ever below the floor, and after
// the impact the body's centre rises again (the centre is what its mean vertex height stands for here).
TEST_P(EveryIntegrator, BouncesOffTheFloor) {
  sim::World world = make_world(kBounce, GetParam());
  const frames::FrameClock clock = frames::plan_frames(0.8, 30, 2e-4);
  TimeRecorder recorder;
  frames::FrameSink* sinks[] = {&recorder};
  frames::run_frames(world, clock, sinks);
  EXPECT_GE(recorder.lowest_y, 0.0);
  const auto bottom = std::min_element(recorder.centre_y.begin(), recorder.centre_y.end());
  ASSERT_NE(bottom, recorder.centre_y.end() - 1) << "the body never came back up";
  EXPECT_GT(*std::max_element(bottom, recorder.centre_y.end()), *bottom + 0.1) << "no rebound";
}

// Same scene, same integrator: the same bits, including through contacts and step-size control.
TEST_P(EveryIntegrator, RerunsAreBitIdentical) {
  auto run = [] {
    sim::World world = make_world(kBounce, GetParam(), 1e-5);
    const frames::FrameClock clock = frames::plan_frames(0.6, 30, 2e-4);
    frames::run_frames(world, clock, {});
    return world.state;
  };
  const sim::State a = run(), b = run();
  ASSERT_EQ(a.x.size(), b.x.size());
  EXPECT_EQ(std::memcmp(a.x.data(), b.x.data(), a.x.size() * sizeof(softbody::Vec3)), 0);
  EXPECT_EQ(std::memcmp(a.v.data(), b.v.data(), a.v.size() * sizeof(softbody::Vec3)), 0);
}

INSTANTIATE_TEST_SUITE_P(All, EveryIntegrator,
                         ::testing::Values(sim::IntegratorKind::Euler, sim::IntegratorKind::Symplectic,
                                           sim::IntegratorKind::Verlet, sim::IntegratorKind::Rk4,
                                           sim::IntegratorKind::Rk45, sim::IntegratorKind::Xpbd,
                                           sim::IntegratorKind::Vbd),
                         [](const ::testing::TestParamInfo<sim::IntegratorKind>& test) {
                           return sim::to_string(test.param);
                         });

}  // namespace
