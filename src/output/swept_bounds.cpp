// Grows the swept box by every vertex of every frame.
#include "output/swept_bounds.hpp"

namespace output {

void SweptBounds::on_frame(int /*index*/, double /*time_s*/, const sim::World& world) {
  for (const softbody::Vec3& p : world.state.x) {
    min_ = min_.cwiseMin(p);
    max_ = max_.cwiseMax(p);
  }
}

}  // namespace output
