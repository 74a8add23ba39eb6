// Where frames go: the CSV writer, the renderer, the mesh exporter. The frame loop calls every sink
// once per frame, then finish() once, also when the run stops early (so frames already written stay).
#pragma once

#include "sim/step/world.hpp"

namespace frames {

class FrameSink {
 public:
  virtual ~FrameSink() = default;
  // Frame `index` (0 is the initial state) at simulated time `time_s`.
  virtual void on_frame(int index, double time_s, const sim::World& world) = 0;
  // Completes the output; `complete` is false when the run stopped early (diverged, interrupted).
  virtual void finish(bool complete) = 0;
};

}  // namespace frames
