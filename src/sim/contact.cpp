// Floor contact models.
#include "sim/contact.hpp"

namespace sim {

int resolve_floor_paper(double height_m, std::span<Vec3> x, std::span<Vec3> v) {
  int below = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (x[i].y() >= height_m) continue;
    v[i] = -v[i];
    x[i].y() = height_m;
    ++below;
  }
  return below;
}

}  // namespace sim
