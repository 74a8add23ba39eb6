// Key frames of the motion, then the frames that spread the rest of the sheet evenly over the run.
#include "output/figure_frames.hpp"

#include <algorithm>
#include <cstdlib>

namespace output {
namespace {

using Motion = std::vector<MotionSample>;

// First frame >= `from` whose lowest vertex touches the floor; -1 when none does.
int first_contact(const Motion& motion, double floor_m, double tolerance_m, int from) {
  for (int i = from; i < static_cast<int>(motion.size()); ++i) {
    if (motion[i].min.y() <= floor_m + tolerance_m) return i;
  }
  return -1;
}

// The frame after `contact` where the body leaves the floor again (size() when it never does).
int end_of_contact(const Motion& motion, double floor_m, double tolerance_m, int contact) {
  int i = contact;
  while (i < static_cast<int>(motion.size()) && motion[i].min.y() <= floor_m + tolerance_m) ++i;
  return i;
}

int smallest_height(const Motion& motion, int from, int to) {
  int best = from;
  for (int i = from; i < to; ++i) {
    if (motion[i].height_m() < motion[best].height_m()) best = i;
  }
  return best;
}

// The highest lowest vertex after `from`, before the next contact; -1 when the body stays down.
int highest_rebound(const Motion& motion, double floor_m, double tolerance_m, int from) {
  const int next = first_contact(motion, floor_m, tolerance_m, from);
  const int to = next < 0 ? static_cast<int>(motion.size()) : next;
  if (from >= to) return -1;
  int best = from;
  for (int i = from; i < to; ++i) {
    if (motion[i].min.y() > motion[best].min.y()) best = i;
  }
  return best;
}

// First frame after `from` whose horizontal velocity points against frame 0's; -1 when none.
int turn_back(const Motion& motion, int from) {
  const softbody::Vec3& v0 = motion.front().com_velocity;
  const double speed0_sq = v0.x() * v0.x() + v0.z() * v0.z();
  if (speed0_sq == 0.0) return -1;
  for (int i = from; i < static_cast<int>(motion.size()); ++i) {
    const softbody::Vec3& v = motion[i].com_velocity;
    if (v.x() * v0.x() + v.z() * v0.z() < 0.0) return i;
  }
  return -1;
}

// The frame at or after `from` whose box centre lies farthest back along frame 0's horizontal velocity: where
// the going back ends. -1 when frame 0 has no horizontal velocity.
int farthest_back(const Motion& motion, int from) {
  const softbody::Vec3& v0 = motion.front().com_velocity;
  if (v0.x() * v0.x() + v0.z() * v0.z() == 0.0) return -1;
  const auto along = [&](const MotionSample& s) {
    return (s.min.x() + s.max.x()) * v0.x() + (s.min.z() + s.max.z()) * v0.z();
  };
  int best = from;
  for (int i = from; i < static_cast<int>(motion.size()); ++i) {
    if (along(motion[i]) < along(motion[best])) best = i;
  }
  return best;
}

// Adds the frame farthest from every chosen one (the lowest such frame on ties).
void add_farthest(std::vector<int>& chosen, int last_frame) {
  int best = -1, best_distance = -1;
  for (int frame = 0; frame <= last_frame; ++frame) {
    int distance = last_frame + 1;
    for (const int c : chosen) distance = std::min(distance, std::abs(frame - c));
    if (distance > best_distance) {
      best = frame;
      best_distance = distance;
    }
  }
  if (best_distance > 0) chosen.push_back(best);
}

}  // namespace

std::vector<int> frames_from_motion(const Motion& motion, int tiles, std::optional<double> floor_height_m) {
  if (motion.empty() || tiles <= 0) return {};
  const int last = motion.back().frame;
  std::vector<int> keys = {0};
  std::vector<int> later_keys;  // after the last frame in priority
  if (floor_height_m) {
    const double tolerance = kContactTolerance * std::max(motion.front().height_m(), 1e-6);
    const int contact = first_contact(motion, *floor_height_m, tolerance, 0);
    if (contact >= 0) {
      const int lift_off = end_of_contact(motion, *floor_height_m, tolerance, contact);
      keys.push_back(motion[contact].frame);
      keys.push_back(motion[smallest_height(motion, contact, lift_off)].frame);
      if (const int rebound = highest_rebound(motion, *floor_height_m, tolerance, lift_off); rebound >= 0) {
        later_keys.push_back(motion[rebound].frame);
      }
      if (const int turn = turn_back(motion, contact); turn >= 0) {
        later_keys.push_back(motion[turn].frame);
        later_keys.push_back(motion[farthest_back(motion, turn)].frame);
      }
    }
  }
  keys.push_back(last);
  keys.insert(keys.end(), later_keys.begin(), later_keys.end());
  std::vector<int> chosen;
  for (const int key : keys) {
    if (static_cast<int>(chosen.size()) < tiles && std::find(chosen.begin(), chosen.end(), key) == chosen.end()) {
      chosen.push_back(key);
    }
  }
  while (static_cast<int>(chosen.size()) < std::min(tiles, last + 1)) add_farthest(chosen, last);
  std::sort(chosen.begin(), chosen.end());
  return chosen;
}

}  // namespace output
