// The overlapped frame loop: one worker thread per chosen frame steps the world while the caller delivers.
#include "frames/overlapped_frame_loop.hpp"

#include <future>
#include <utility>

#include "frames/stop_request.hpp"
#include "frames/wall_clock.hpp"

namespace frames {

RunStats run_frames_overlapped(sim::World& world, const FrameClock& clock, std::span<CapturingFrameSink* const> sinks,
                               const Progress& progress, const RunPlan& plan) {
  const FrameSelection selection = plan.frames.count() > 0 ? plan.frames : FrameSelection::all(clock.frame_count);
  RunStats stats;
  const auto start = WallClock::now();
  auto capture = [&](int index) {
    for (CapturingFrameSink* sink : sinks) sink->capture(index, frame_time_s(clock, index), world);
  };
  auto deliver = [&]() {
    for (CapturingFrameSink* sink : sinks) sink->deliver();
    ++stats.frames;
    if (progress) progress(stats.frames, selection.count());
  };
  try {
    bool captured = false;  // a frame waits to be delivered
    if (selection.contains(0)) {
      capture(0);
      captured = true;
    }
    int current = 0;
    for (int frame = 1; frame <= selection.last(); ++frame) {
      if (!selection.contains(frame)) continue;
      // The world is only touched by the worker until get(); the sinks work from their captured copy.
      std::future<std::pair<Advance, double>> stepping =
          std::async(std::launch::async, [&world, &clock, &plan, current, frame] {
            const auto step_start = WallClock::now();
            const Advance advance = advance_to_frame(world, clock, current, frame, plan.checkpoints, plan.stop);
            return std::make_pair(advance, seconds_since(step_start));
          });
      try {
        if (captured) deliver();
        throw_if_stop_requested(stats.frames);  // SIGINT / SIGTERM: the frames delivered are complete
      } catch (...) {
        stepping.wait();  // the worker must be done with the world before anyone else sees it
        throw;
      }
      const auto [advance, seconds] = stepping.get();                       // rethrows the worker's DivergedError
      if (advance.stopped) throw Interrupted(stop_signal(), stats.frames);  // the frame in progress is dropped
      stats.step_wall_s += seconds;
      stats.loaded_states += advance.loaded ? 1 : 0;
      stats.steps += advance.steps;
      stats.rejected_steps += advance.rejected;
      current = frame;
      capture(frame);
      captured = true;
    }
    if (captured) deliver();
  } catch (...) {
    for (CapturingFrameSink* sink : sinks) sink->finish(false);
    throw;
  }
  for (CapturingFrameSink* sink : sinks) sink->finish(true);
  stats.wall_s = seconds_since(start);
  return stats;
}

}  // namespace frames
