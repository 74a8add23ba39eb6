// Frame timing: whole steps per frame, dt rounded down (never drifting) and reported.
#include <gtest/gtest.h>

#include "frames/frame_clock.hpp"

namespace {

TEST(FrameClock, DividingStepIsKeptSilently) {
  const frames::FrameClock clock = frames::plan_frames(2.0, 25, 1e-3);
  EXPECT_EQ(clock.steps_per_frame, 40);
  EXPECT_EQ(clock.frame_count, 50);
  EXPECT_NEAR(clock.dt_s, 1e-3, 1e-18);
  EXPECT_TRUE(clock.dt_note.empty());
}

TEST(FrameClock, NonDividingStepIsRoundedDownAndReported) {
  const frames::FrameClock clock = frames::plan_frames(3.0, 30, 1e-4);  // 1/30 s = 333.3 steps
  EXPECT_EQ(clock.steps_per_frame, 334);
  EXPECT_LT(clock.dt_s, 1e-4);
  EXPECT_NEAR(clock.dt_s * clock.steps_per_frame, 1.0 / 30, 1e-15);
  EXPECT_EQ(clock.frame_count, 90);
  EXPECT_NE(clock.dt_note.find("using dt = 9.98004e-05 s (334 steps per frame)"), std::string::npos) << clock.dt_note;
}

TEST(FrameClock, StepLongerThanFrameBecomesOneStepPerFrame) {
  const frames::FrameClock clock = frames::plan_frames(1.0, 10, 0.5);
  EXPECT_EQ(clock.steps_per_frame, 1);
  EXPECT_NEAR(clock.dt_s, 0.1, 1e-15);
  EXPECT_FALSE(clock.dt_note.empty());
}

// The run goes on to the next frame, and says so: at 1 fps a duration of 0.1 s ran a whole second without a word.
TEST(FrameClock, PartialLastFrameIsRoundedUpAndReported) {
  const frames::FrameClock clock = frames::plan_frames(1.01, 10, 0.01);
  EXPECT_EQ(clock.frame_count, 11);
  EXPECT_EQ(clock.duration_note,
            "duration = 1.01 s is not a whole number of frames at 10 fps; the run ends at the next frame, t = 1.1 s");
  EXPECT_TRUE(frames::plan_frames(2.0, 25, 1e-3).duration_note.empty()) << "50 whole frames";
  EXPECT_TRUE(frames::plan_frames(0.1, 30, 1e-3).duration_note.empty()) << "3 frames up to round-off";
}

// xpbd: dt = (1/fps) / substeps plans exactly `substeps` steps per frame, with no rounding note.
TEST(FrameClock, SubstepDtGivesThatManyStepsPerFrame) {
  for (int fps : {24, 30, 60}) {
    for (int substeps : {1, 7, 20, 33, 353, 10000}) {
      const frames::FrameClock clock = frames::plan_frames(3.0, fps, frames::substep_dt(fps, substeps));
      EXPECT_EQ(clock.steps_per_frame, substeps) << fps << " fps";
      EXPECT_TRUE(clock.dt_note.empty()) << clock.dt_note;
    }
  }
}

}  // namespace
