// The paper's Figure 1 with the paper's method: the ball goes forward, touches the floor, and goes back.
#include <algorithm>

#include <gtest/gtest.h>

#include "scene/scene_json.hpp"
#include "setup/build_world.hpp"
#include "sim/step/diagnostics.hpp"
#include "test_helpers.hpp"

namespace {

struct Track {
  double landing_time_s = -1.0;  // first sample with a vertex within 5 mm of the floor
  double farthest_x_m = 0.0;     // largest centre-of-mass x
  double final_x_m = 0.0;
  double most_backward_vx = 0.0;  // most negative centre-of-mass x velocity after landing
  double diameter_m = 0.0;        // the ball's height (highest minus lowest vertex) at t = 0
  double deepest_height_m = 1e9;  // its least height within kSquashWindow_s of landing (the squash)
  double deepest_time_s = 0.0;
  double recovered_height_m = 0.0;  // its greatest height after the squash, up to kSquashWindow_s + 0.1 s
};

constexpr double kSquashWindow_s = 0.5;

// Highest minus lowest vertex of the only body, m.
double height_of(const sim::State& state) {
  const auto [lowest, highest] = std::minmax_element(
      state.x.begin(), state.x.end(), [](const sim::Vec3& a, const sim::Vec3& b) { return a.y() < b.y(); });
  return highest->y() - lowest->y();
}

// Runs scenes/bounce.json with `dt` for `duration` seconds, sampling 100 times a second.
Track run_bounce(double dt, double duration) {
  const scene::Scene s = scene::load_scene(std::string(SOFTBODY_SOURCE_DIR) + "/scenes/bounce.json");
  std::vector<std::string> notes;
  sim::World world = setup::build_world(s, notes);
  Track track;
  track.diameter_m = height_of(world.state);
  const long long steps_per_sample = std::llround(0.01 / dt);
  for (int sample = 1; sample <= std::lround(duration * 100); ++sample) {
    testing_support::run_steps(world, steps_per_sample, dt);
    const sim::BodyDiagnostics d = sim::diagnose(world.model, world.state, 0);
    if (track.landing_time_s < 0 && d.min_y_m < 0.005) track.landing_time_s = world.state.time_s;
    track.farthest_x_m = std::max(track.farthest_x_m, d.com_m.x());
    track.final_x_m = d.com_m.x();
    if (track.landing_time_s >= 0)
      track.most_backward_vx = std::min(track.most_backward_vx, d.com_velocity_m_per_s.x());
    const double since_landing_s = world.state.time_s - track.landing_time_s;
    if (track.landing_time_s >= 0 && since_landing_s <= kSquashWindow_s &&
        height_of(world.state) < track.deepest_height_m) {
      track.deepest_height_m = height_of(world.state);
      track.deepest_time_s = world.state.time_s;
      track.recovered_height_m = 0.0;
    } else if (track.landing_time_s >= 0 && since_landing_s <= kSquashWindow_s + 0.1) {
      track.recovered_height_m = std::max(track.recovered_height_m, height_of(world.state));
    }
  }
  return track;
}

void expect_goes_back(const Track& track) {
  // Free fall from 2 m: the bottom reaches the floor after sqrt(2·2/9.81) = 0.64 s, having moved 1.28 m.
  EXPECT_NEAR(track.landing_time_s, 0.64, 0.02);
  EXPECT_GT(track.farthest_x_m, 1.4) << "goes forward";
  EXPECT_LT(track.most_backward_vx, -0.4) << "moves back towards where it came from";
  EXPECT_LT(track.final_x_m, track.farthest_x_m - 0.15) << "ends behind its farthest point";
}

// The figure's squash (issue 16): the default ball lands soft enough that its height drops below 0.78 of
// its diameter (measured 0.71 at dt 1e-4 s and at 2.5e-5 s; the 1 kg, nRT 30 J ball before reached only
// 0.82-0.83, which read as hard), and springs back up by more than 7 % of the diameter within 0.6 s of
// landing (measured 18 % and 14 %): a squash, not a collapse.
void expect_squashes_and_springs_back(const Track& track) {
  EXPECT_LT(track.deepest_height_m, 0.78 * track.diameter_m) << "squash at t = " << track.deepest_time_s << " s";
  EXPECT_GT(track.recovered_height_m, track.deepest_height_m + 0.07 * track.diameter_m) << "springs back";
}

TEST(Bounce, SquashesOnLandingAndSpringsBack) { expect_squashes_and_springs_back(run_bounce(1e-4, 1.3)); }
TEST(Bounce, SquashSurvivesAFourTimesSmallerStep) { expect_squashes_and_springs_back(run_bounce(2.5e-5, 1.3)); }

TEST(Bounce, GoesForwardTouchesFloorAndGoesBack) { expect_goes_back(run_bounce(1e-4, 2.0)); }

// The bounce back is not forward Euler's instability: at a step four times smaller (0.15 of the stable
// limit instead of 0.6) it stays. What causes it is the paper's contact response (docs/physics/model.md,
// "The bounce back").
TEST(Bounce, GoingBackSurvivesAFourTimesSmallerStep) { expect_goes_back(run_bounce(2.5e-5, 2.0)); }

}  // namespace
