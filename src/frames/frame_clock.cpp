// Frame clock planning.
#include "frames/frame_clock.hpp"

#include <cmath>
#include <cstdio>

#include "core/errors.hpp"

namespace frames {

FrameClock plan_frames(double duration_s, int fps, double requested_dt_s) {
  FrameClock clock;
  clock.frame_interval_s = 1.0 / fps;
  const double ratio = clock.frame_interval_s / requested_dt_s;
  constexpr double kRelativeSlack = 1e-9;  // a dt that divides 1/fps up to round-off counts as dividing it
  const double steps = std::ceil(ratio * (1.0 - kRelativeSlack));
  if (steps > 2e9) throw softbody::InputError("solver.dt: " + std::to_string(requested_dt_s) + " s needs more than 2e9 steps per frame");
  clock.steps_per_frame = std::max(1, static_cast<int>(steps));
  clock.dt_s = clock.frame_interval_s / clock.steps_per_frame;
  if (std::abs(clock.dt_s - requested_dt_s) > kRelativeSlack * requested_dt_s) {
    char note[256];
    std::snprintf(note, sizeof note,
                  "solver.dt = %.6g s does not divide the frame interval 1/%d s; using dt = %.6g s (%d steps per frame)",
                  requested_dt_s, fps, clock.dt_s, clock.steps_per_frame);
    clock.dt_note = note;
  }
  clock.frame_count = static_cast<int>(std::ceil(duration_s * fps * (1.0 - kRelativeSlack)));
  return clock;
}

double substep_dt(int fps, int substeps) { return 1.0 / fps / substeps; }

}  // namespace frames
