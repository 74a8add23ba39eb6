// The frame loop.
#include "frames/frame_loop.hpp"

#include "frames/stop_request.hpp"
#include "frames/wall_clock.hpp"

namespace frames {
namespace {

// One frame interval of whole steps, then the guard's full check before the frame is handed out; false
// (the frame unfinished) when a stop was requested before one of its steps.
bool step_one_frame(sim::World& world, const FrameClock& clock, sim::StopQuery stop) {
  for (int s = 0; s < clock.steps_per_frame; ++s) {
    if (stop()) return false;
    world.step(clock.dt_s);
  }
  world.check_before_frame();
  return true;
}

}  // namespace

Advance advance_to_frame(sim::World& world, const FrameClock& clock, int current, int target,
                         const Checkpoints* checkpoints, sim::StopQuery stop) {
  Advance advance;
  if (checkpoints) {
    const int stored = checkpoints->latest_at_or_before(target);
    if (stored > current) {
      world.state = checkpoints->load(stored);  // a copied State is a checkpoint: the same bits as stepping
      current = stored;
      advance.loaded = true;
    }
  }
  const long long steps_before = world.state.steps, rejected_before = world.state.rejected_steps;
  for (int frame = current + 1; frame <= target && !advance.stopped; ++frame) {
    // Adaptive: its every step had the full check.
    const bool reached =
        world.adaptive() ? world.advance_to(frame_time_s(clock, frame), stop) : step_one_frame(world, clock, stop);
    advance.stopped = !reached;
  }
  advance.steps = world.state.steps - steps_before;
  advance.rejected = world.state.rejected_steps - rejected_before;
  return advance;
}

RunStats run_frames(sim::World& world, const FrameClock& clock, std::span<FrameSink* const> sinks,
                    const Progress& progress, const RunPlan& plan) {
  const FrameSelection selection = plan.frames.count() > 0 ? plan.frames : FrameSelection::all(clock.frame_count);
  RunStats stats;
  const auto start = WallClock::now();
  auto emit = [&](int index) {
    const double time_s = frame_time_s(clock, index);
    for (FrameSink* sink : sinks) sink->on_frame(index, time_s, world);
    ++stats.frames;
    if (progress) progress(stats.frames, selection.count());
    throw_if_stop_requested(stats.frames);  // SIGINT / SIGTERM: the frames handed out are complete
  };
  try {
    int current = 0;
    if (selection.contains(0)) emit(0);
    for (int frame = 1; frame <= selection.last(); ++frame) {
      if (!selection.contains(frame)) continue;
      const auto step_start = WallClock::now();
      const Advance advance = advance_to_frame(world, clock, current, frame, plan.checkpoints, plan.stop);
      if (advance.stopped) throw Interrupted(stop_signal(), stats.frames);  // the frame in progress is dropped
      current = frame;
      stats.step_wall_s += seconds_since(step_start);
      stats.loaded_states += advance.loaded ? 1 : 0;
      stats.steps += advance.steps;
      stats.rejected_steps += advance.rejected;
      emit(frame);
    }
  } catch (...) {
    for (FrameSink* sink : sinks) sink->finish(false);
    throw;
  }
  for (FrameSink* sink : sinks) sink->finish(true);
  stats.wall_s = seconds_since(start);
  return stats;
}

}  // namespace frames
