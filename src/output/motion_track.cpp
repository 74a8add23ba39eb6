// One MotionSample per frame: the vertices' box and the mass-weighted mean velocity.
#include "output/motion_track.hpp"

#include <limits>

namespace output {

void MotionTrack::on_frame(int index, double time_s, const sim::World& world) {
  MotionSample sample;
  sample.frame = index;
  sample.time_s = time_s;
  sample.min = softbody::Vec3::Constant(std::numeric_limits<double>::infinity());
  sample.max = -sample.min;
  softbody::Vec3 momentum = softbody::Vec3::Zero();
  double mass = 0.0;
  for (std::size_t i = 0; i < world.state.x.size(); ++i) {
    sample.min = sample.min.cwiseMin(world.state.x[i]);
    sample.max = sample.max.cwiseMax(world.state.x[i]);
    momentum += world.model.mass_kg[i] * world.state.v[i];  // p = Σ m_i v_i [kg·m/s]
    mass += world.model.mass_kg[i];
  }
  sample.com_velocity = mass > 0.0 ? softbody::Vec3(momentum / mass) : softbody::Vec3::Zero();
  samples_.push_back(sample);
}

softbody::Vec3 MotionTrack::swept_min() const {
  softbody::Vec3 low = samples_.front().min;
  for (const MotionSample& s : samples_) low = low.cwiseMin(s.min);
  return low;
}

softbody::Vec3 MotionTrack::swept_max() const {
  softbody::Vec3 high = samples_.front().max;
  for (const MotionSample& s : samples_) high = high.cwiseMax(s.max);
  return high;
}

}  // namespace output
