// The frame loop.
#include "frames/frame_loop.hpp"

#include <chrono>

#include "frames/wall_clock.hpp"

namespace frames {
void advance_one_frame(sim::World& world, const FrameClock& clock, int frame) {
  if (world.adaptive()) {
    world.advance_to(frame * clock.frame_interval_s);
    return;
  }
  for (int s = 0; s < clock.steps_per_frame; ++s) world.step(clock.dt_s);
  world.check_before_frame();  // the guard's full check before the frame is handed out
}

RunStats run_frames(sim::World& world, const FrameClock& clock, std::span<FrameSink* const> sinks,
                    const Progress& progress) {
  RunStats stats;
  const long long steps_before = world.state.steps;
  const long long rejected_before = world.state.rejected_steps;
  const auto start = WallClock::now();
  auto emit = [&](int index) {
    // Time from the frame index, not the accumulated step sum, so frame times carry no round-off drift.
    const double time_s = index * clock.frame_interval_s;
    for (FrameSink* sink : sinks) sink->on_frame(index, time_s, world);
    ++stats.frames;
    if (progress) progress(index, clock.frame_count);
  };
  try {
    emit(0);
    for (int frame = 1; frame <= clock.frame_count; ++frame) {
      const auto step_start = WallClock::now();
      advance_one_frame(world, clock, frame);
      stats.step_wall_s += seconds_since(step_start);
      stats.steps = world.state.steps - steps_before;
      stats.rejected_steps = world.state.rejected_steps - rejected_before;
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
