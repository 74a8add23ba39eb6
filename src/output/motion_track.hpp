// What the bodies do frame by frame, in a few numbers: the box around them and their centre of mass's
// height and velocity. The framing camera and the figure's choice of frames read it.
#pragma once

#include <vector>

#include "core/vec.hpp"
#include "frames/frame_sink.hpp"

namespace output {

struct MotionSample {
  int frame = 0;
  double time_s = 0.0;
  softbody::Vec3 min;           // m, over every vertex of every body
  softbody::Vec3 max;           // m
  softbody::Vec3 com_velocity;  // m/s, all bodies' centre of mass (vertex masses)
  double height_m() const { return max.y() - min.y(); }
};

class MotionTrack final : public frames::FrameSink {
 public:
  void on_frame(int index, double time_s, const sim::World& world) override;
  void finish(bool /*complete*/) override {}

  const std::vector<MotionSample>& samples() const { return samples_; }
  // The box every vertex stays inside over all frames (samples() must not be empty).
  softbody::Vec3 swept_min() const;
  softbody::Vec3 swept_max() const;

 private:
  std::vector<MotionSample> samples_;
};

}  // namespace output
