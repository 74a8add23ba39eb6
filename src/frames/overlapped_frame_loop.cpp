// The overlapped frame loop: one worker thread per frame interval steps the world while the caller delivers.
#include "frames/overlapped_frame_loop.hpp"

#include <chrono>

#include "frames/wall_clock.hpp"
#include <future>

namespace frames {
RunStats run_frames_overlapped(sim::World& world, const FrameClock& clock,
                               std::span<CapturingFrameSink* const> sinks, const Progress& progress) {
  RunStats stats;
  const long long steps_before = world.state.steps;
  const long long rejected_before = world.state.rejected_steps;
  const auto start = WallClock::now();
  auto capture = [&](int index) {
    for (CapturingFrameSink* sink : sinks) sink->capture(index, index * clock.frame_interval_s, world);
  };
  auto deliver = [&](int index) {
    for (CapturingFrameSink* sink : sinks) sink->deliver();
    ++stats.frames;
    if (progress) progress(index, clock.frame_count);
  };
  try {
    capture(0);
    for (int frame = 1; frame <= clock.frame_count; ++frame) {
      // The world is only touched by the worker until get(); the sinks work from their captured copy.
      std::future<double> stepping = std::async(std::launch::async, [&world, &clock, frame] {
        const auto step_start = WallClock::now();
        advance_one_frame(world, clock, frame);
        return seconds_since(step_start);
      });
      try {
        deliver(frame - 1);
      } catch (...) {
        stepping.wait();  // the worker must be done with the world before anyone else sees it
        throw;
      }
      stats.step_wall_s += stepping.get();  // rethrows the worker's DivergedError
      stats.steps = world.state.steps - steps_before;
      stats.rejected_steps = world.state.rejected_steps - rejected_before;
      capture(frame);
    }
    deliver(clock.frame_count);
  } catch (...) {
    for (CapturingFrameSink* sink : sinks) sink->finish(false);
    throw;
  }
  for (CapturingFrameSink* sink : sinks) sink->finish(true);
  stats.wall_s = seconds_since(start);
  return stats;
}

}  // namespace frames
