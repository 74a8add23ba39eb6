// The run: step the world frame interval by frame interval and hand each chosen frame to the sinks.
#pragma once

#include <functional>
#include <span>

#include "frames/frame_clock.hpp"
#include "frames/frame_selection.hpp"
#include "frames/frame_sink.hpp"
#include "frames/stop_request.hpp"
#include "sim/step/step.hpp"

namespace frames {

struct RunStats {
  long long steps = 0;           // accepted steps
  long long rejected_steps = 0;  // adaptive integrators: attempts whose error was above the tolerance
  int frames = 0;                // frames handed to the sinks, frame 0 included
  int loaded_states = 0;         // frames whose state came from a checkpoint instead of stepping
  double wall_s = 0.0;           // wall-clock time of the whole loop, sinks included
  double step_wall_s = 0.0;      // wall-clock time spent stepping the world (and loading checkpoints)
};

// Stored states a run can start from instead of stepping from frame 0 (a state cache).
struct Checkpoints {
  // The largest frame <= `frame` whose state is stored (or anything below 1 when none is of use).
  std::function<int(int frame)> latest_at_or_before;
  // The stored state of `frame` (one that latest_at_or_before returned); throws when it cannot be read.
  std::function<sim::State(int frame)> load;
};

// How a run goes: which frames the sinks get, and where states may come from.
struct RunPlan {
  FrameSelection frames;                     // default: every frame
  const Checkpoints* checkpoints = nullptr;  // none: every state is stepped from frame 0
  sim::StopQuery stop = stop_requested;      // asked before every step (advance_to_frame): SIGINT / SIGTERM's flag
};

// Called after each delivered frame with (frames done, frames chosen in all); may be empty.
using Progress = std::function<void(int, int)>;

// What advance_to_frame did.
struct Advance {
  bool loaded = false;     // a checkpoint's state was loaded
  long long steps = 0;     // accepted steps taken (after the load)
  long long rejected = 0;  // rejected attempts (adaptive integrators)
  bool stopped = false;    // a stop was requested (SIGINT / SIGTERM): the world is part of the way only
};

// Brings the world from frame `current` to frame `target` (> current): when a checkpoint lies between
// them, its state is loaded first; then, frame by frame, whole steps followed by the guard's full check,
// or the adaptive steps that land exactly on the frame time. Before every step it looks whether a stop was
// requested (`stop`: frames/stop_request.hpp's, or the Python module's signal check) and if so returns at once
// with `stopped`: the caller discards the frame.
Advance advance_to_frame(sim::World& world, const FrameClock& clock, int current, int target,
                         const Checkpoints* checkpoints, sim::StopQuery stop = stop_requested);

// Frame 0 is the initial state; then clock.frame_count frames, each clock.steps_per_frame steps apart
// (adaptive integrators instead advance to each frame time with their own steps, landing on it exactly).
// The sinks get the frames of plan.frames only, in order; the run stops at the last of them. On divergence
// the sinks are finished with complete = false and the DivergedError propagates: frames handed out before
// stay valid and no frame of a diverged state is emitted. A stop request (SIGINT / SIGTERM) ends the run
// within one step the same way, with frames::Interrupted: the frame in progress is never handed out.
RunStats run_frames(sim::World& world, const FrameClock& clock, std::span<FrameSink* const> sinks,
                    const Progress& progress = {}, const RunPlan& plan = {});

}  // namespace frames
