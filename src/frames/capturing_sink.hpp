// A frame sink in two halves, so that its slow half can run while the world steps to the next frame.
#pragma once

#include "frames/frame_sink.hpp"

namespace frames {

// capture() copies what the frame needs from the world (called while the world is at rest);
// deliver() does the rest (rendering, writing) from that copy and never touches the world, so the
// frame loop may step the world on another thread meanwhile (run_frames_overlapped).
class CapturingFrameSink : public FrameSink {
 public:
  virtual void capture(int index, double time_s, const sim::World& world) = 0;
  virtual void deliver() = 0;
  // Both halves at once, for the plain frame loop.
  void on_frame(int index, double time_s, const sim::World& world) final {
    capture(index, time_s, world);
    deliver();
  }
};

}  // namespace frames
