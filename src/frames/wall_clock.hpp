// Wall-clock timing shared by the frame loops.
#pragma once

#include <chrono>

namespace frames {

using WallClock = std::chrono::steady_clock;

// Seconds elapsed since `start`.
inline double seconds_since(WallClock::time_point start) {
  return std::chrono::duration<double>(WallClock::now() - start).count();
}

}  // namespace frames
