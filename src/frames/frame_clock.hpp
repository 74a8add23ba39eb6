// Frame timing: how many whole steps fit in one frame interval, and the dt that makes them fit exactly.
#pragma once

#include <string>

namespace frames {

struct FrameClock {
  double dt_s = 0.0;  // the step actually used: (1/fps) / steps_per_frame
  int steps_per_frame = 0;
  int frame_count = 0;  // frames after frame 0 (the initial state): ceil(duration · fps)
  double frame_interval_s = 0.0;
  std::string dt_note;  // non-empty when the requested dt was rounded down, saying so
  // Non-empty when the duration is not a whole number of frame intervals, saying that the run ends at the next frame.
  std::string duration_note;
};

// Runs beyond these are refused before they start (InputError naming the key and the limit): a frame
// index is an int, and 1e6 steps per frame is already 3e7 steps per simulated second at 30 fps.
inline constexpr int kMaxFrames = 100'000'000;       // frames after frame 0: 38 days at 30 fps
inline constexpr int kMaxStepsPerFrame = 1'000'000;  // steps per frame interval (fixed-step integrators)

// The simulated time of frame `index` [s]: from the index, not the accumulated step sum, so frame times carry no
// round-off drift (the CSV's time column, the frames the loops hand out).
inline double frame_time_s(const FrameClock& clock, int index) { return index * clock.frame_interval_s; }

// 1/fps must hold a whole number of steps: a requested dt that does not divide it is rounded down to
// the next dt that does (never drifting), and `dt_note` reports it.
// A run beyond kMaxFrames or kMaxStepsPerFrame throws softbody::InputError starting with `context` (the
// scene file) and naming the key and the limit.
FrameClock plan_frames(double duration_s, int fps, double requested_dt_s, const std::string& context = "");

// xpbd: each frame interval split into `substeps` substeps, dt = (1/fps) / substeps [s] (plan_frames of this dt
// gives steps_per_frame = substeps).
double substep_dt(int fps, int substeps);

}  // namespace frames
