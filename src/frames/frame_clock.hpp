// Frame timing: how many whole steps fit in one frame interval, and the dt that makes them fit exactly.
#pragma once

#include <string>

namespace frames {

struct FrameClock {
  double dt_s = 0.0;           // the step actually used: (1/fps) / steps_per_frame
  int steps_per_frame = 0;
  int frame_count = 0;         // frames after frame 0 (the initial state): ceil(duration · fps)
  double frame_interval_s = 0.0;
  std::string dt_note;         // non-empty when the requested dt was rounded down, saying so
};

// 1/fps must hold a whole number of steps: a requested dt that does not divide it is rounded down to
// the next dt that does (never drifting), and `dt_note` reports it.
FrameClock plan_frames(double duration_s, int fps, double requested_dt_s);

// xpbd: each frame interval split into `substeps` substeps, dt = (1/fps) / substeps [s] (plan_frames of this dt
// gives steps_per_frame = substeps).
double substep_dt(int fps, int substeps);

}  // namespace frames
