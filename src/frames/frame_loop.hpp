// The run: step the world frame interval by frame interval and hand each frame to the sinks.
#pragma once

#include <functional>
#include <span>

#include "frames/frame_clock.hpp"
#include "frames/frame_sink.hpp"

namespace frames {

struct RunStats {
  long long steps = 0;           // accepted steps
  long long rejected_steps = 0;  // adaptive integrators: attempts whose error was above the tolerance
  int frames = 0;       // frames handed to the sinks, frame 0 included
  double wall_s = 0.0;  // wall-clock time of the whole loop, sinks included
  double step_wall_s = 0.0;  // wall-clock time spent stepping the world
};

// Simulates from frame `frame - 1` to frame `frame`: whole fixed steps, or the adaptive steps that land
// exactly on the frame time.
void advance_one_frame(sim::World& world, const FrameClock& clock, int frame);

// Called after each frame with (frames done, frames in all); may be empty.
using Progress = std::function<void(int, int)>;

// Frame 0 is the initial state; then clock.frame_count frames, each clock.steps_per_frame steps apart
// (adaptive integrators instead advance to each frame time with their own steps, landing on it exactly).
// On divergence the sinks are finished with complete = false and the DivergedError propagates: frames
// handed out before stay valid and no frame of a diverged state is emitted.
RunStats run_frames(sim::World& world, const FrameClock& clock, std::span<FrameSink* const> sinks,
                    const Progress& progress = {});

}  // namespace frames
