// The box that every body's vertices stay inside over a run: what the framing camera must keep in view.
#pragma once

#include <limits>

#include "core/vec.hpp"
#include "frames/frame_sink.hpp"

namespace output {

class SweptBounds final : public frames::FrameSink {
 public:
  void on_frame(int index, double time_s, const sim::World& world) override;
  void finish(bool /*complete*/) override {}

  // Empty (min > max) until a frame came.
  bool empty() const { return min_.x() > max_.x(); }
  const softbody::Vec3& min() const { return min_; }
  const softbody::Vec3& max() const { return max_; }

 private:
  softbody::Vec3 min_ = softbody::Vec3::Constant(std::numeric_limits<double>::infinity());
  softbody::Vec3 max_ = softbody::Vec3::Constant(-std::numeric_limits<double>::infinity());
};

}  // namespace output
