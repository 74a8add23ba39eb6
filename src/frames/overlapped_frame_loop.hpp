// The frame loop with simulation and output overlapped: frame n is delivered while frame n + 1 steps.
#pragma once

#include <span>

#include "frames/capturing_sink.hpp"
#include "frames/frame_loop.hpp"

namespace frames {

// Same frames, same states and same sink calls as run_frames (capture then deliver, in frame order), but
// while the sinks deliver frame n on the calling thread (the one that owns a GL context), a worker thread
// steps the world (or loads a checkpoint) to the next chosen frame. On divergence every frame before the
// diverged one has been delivered; the sinks are finished with complete = false and the DivergedError
// propagates, as with run_frames; a stop request ends it the same way with frames::Interrupted, within one
// step of the worker, once the frame being delivered is complete (counted). RunStats::step_wall_s is then
// the worker's time, which overlaps the sinks'.
RunStats run_frames_overlapped(sim::World& world, const FrameClock& clock, std::span<CapturingFrameSink* const> sinks,
                               const Progress& progress = {}, const RunPlan& plan = {});

}  // namespace frames
