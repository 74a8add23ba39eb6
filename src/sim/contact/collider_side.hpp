// The contact passes' first test against a collider that stays where it is: whether a vertex's step (from where it was
// at the step's start to where it is now) lies entirely beyond one side of the collider's world box. Most of a body
// is beyond the same side of a collider (above a box it rests on, to the left of one far away), so the side is chosen
// once per pass, from the body's first vertex, and the test is then two comparisons per vertex; a vertex it does not
// clear is asked the full question (collider_contact_point, sim/contact/collider_sweep.hpp), whose first test is the
// same one over all six sides, so the answers are the same.
#pragma once

#include <algorithm>
#include <span>

#include "sim/contact/collider_sweep.hpp"

namespace sim {

// One of the six sides of a collider's world box: along `axis`, beyond position + reach (`upper`) or below
// position − reach.
struct BoxSide {
  int axis = 1;
  bool upper = true;
};

// How far the segment a → b lies beyond `side` of the collider's world box (>= 0: entirely beyond it) [m], with the
// very operations of the full test, so that a vertex cleared here is one that collider_contact_point() clears too.
inline double beyond_side(const ColliderGeometry& g, const Vec3& a, const Vec3& b, BoxSide side) {
  const int k = side.axis;
  if (side.upper) return (std::min(a[k], b[k]) - g.position_m[k]) - g.world_reach_m[k];
  return -(std::max(a[k], b[k]) - g.position_m[k]) - g.world_reach_m[k];
}

// The side that the segment a → b lies farthest beyond (the first on a tie).
inline BoxSide farthest_side(const ColliderGeometry& g, const Vec3& a, const Vec3& b) {
  BoxSide best{0, true};
  for (int axis = 0; axis < 3; ++axis) {
    for (const bool upper : {true, false}) {
      if (beyond_side(g, a, b, {axis, upper}) > beyond_side(g, a, b, best)) best = {axis, upper};
    }
  }
  return best;
}

// Which vertices a contact pass against a static collider can skip: those whose step lies beyond the side that the
// first vertex's step lies farthest beyond. Clears none when the collider moves (the step's start is carried with it
// first) or when there is no step start (the discrete test).
class ColliderSide {
 public:
  ColliderSide(const ColliderGeometry& g, const ColliderStepStart* start, std::span<const Vec3> x)
      : geometry_(g), start_(start) {
    active_ = start != nullptr && !g.velocity.moving && !start->pose->velocity.moving && !x.empty();
    if (active_) side_ = farthest_side(g, start->x[0], x[0]);
  }

  // True when vertex i, now at x1, surely touches nothing of the collider in this step.
  bool clears(std::size_t i, const Vec3& x1) const {
    return active_ && beyond_side(geometry_, start_->x[i], x1, side_) >= 0.0;
  }

 private:
  const ColliderGeometry& geometry_;
  const ColliderStepStart* start_;
  bool active_ = false;
  BoxSide side_;
};

}  // namespace sim
