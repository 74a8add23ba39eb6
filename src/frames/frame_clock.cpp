// Frame clock planning.
#include "frames/frame_clock.hpp"

#include <cmath>
#include <cstdio>

#include "core/errors.hpp"

namespace frames {

FrameClock plan_frames(double duration_s, int fps, double requested_dt_s, const std::string& context) {
  const std::string prefix = context.empty() ? "" : context + ": ";
  FrameClock clock;
  clock.frame_interval_s = 1.0 / fps;
  const double ratio = clock.frame_interval_s / requested_dt_s;
  constexpr double kRelativeSlack = 1e-9;  // a dt that divides 1/fps up to round-off counts as dividing it
  const double steps = std::ceil(ratio * (1.0 - kRelativeSlack));
  if (!(steps <= kMaxStepsPerFrame)) {  // also NaN
    char text[200];
    std::snprintf(text, sizeof text,
                  "solver.dt: %.6g s needs %.3g steps per frame at %d fps, more than the limit of %d", requested_dt_s,
                  steps, fps, kMaxStepsPerFrame);
    throw softbody::InputError(prefix + text);
  }
  clock.steps_per_frame = std::max(1, static_cast<int>(steps));
  clock.dt_s = clock.frame_interval_s / clock.steps_per_frame;
  if (std::abs(clock.dt_s - requested_dt_s) > kRelativeSlack * requested_dt_s) {
    char note[256];
    std::snprintf(
        note, sizeof note,
        "solver.dt = %.6g s does not divide the frame interval 1/%d s; using dt = %.6g s (%d steps per frame)",
        requested_dt_s, fps, clock.dt_s, clock.steps_per_frame);
    clock.dt_note = note;
  }
  const double frames = std::ceil(duration_s * fps * (1.0 - kRelativeSlack));
  if (!(frames <= kMaxFrames)) {  // also NaN; the cast below needs it
    char text[200];
    std::snprintf(text, sizeof text, "duration: %.6g s at %d fps makes %.3g frames, more than the limit of %d",
                  duration_s, fps, frames, kMaxFrames);
    throw softbody::InputError(prefix + text);
  }
  clock.frame_count = static_cast<int>(frames);
  const double end_s = clock.frame_count * clock.frame_interval_s;
  if (end_s - duration_s > kRelativeSlack * end_s) {
    char note[200];
    std::snprintf(note, sizeof note,
                  "duration = %.6g s is not a whole number of frames at %d fps; the run ends at the next frame, t = "
                  "%.6g s",
                  duration_s, fps, end_s);
    clock.duration_note = note;
  }
  return clock;
}

double substep_dt(int fps, int substeps) { return 1.0 / fps / substeps; }

}  // namespace frames
