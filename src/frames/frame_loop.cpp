// The frame loop.
#include "frames/frame_loop.hpp"

#include <chrono>

namespace frames {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

RunStats run_frames(sim::World& world, const FrameClock& clock, std::span<FrameSink* const> sinks,
                    const Progress& progress) {
  RunStats stats;
  const auto start = Clock::now();
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
      const auto step_start = Clock::now();
      for (int s = 0; s < clock.steps_per_frame; ++s) world.step(clock.dt_s);
      stats.step_wall_s += seconds_since(step_start);
      stats.steps += clock.steps_per_frame;
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
