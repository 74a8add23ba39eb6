// figure.png's frames chosen from the motion (render.figure_frames as a count): the moments a bounce is
// told by, rather than evenly spaced ones.
#pragma once

#include <optional>
#include <vector>

#include "output/motion_track.hpp"

namespace output {

// The key frames, in this order of priority: frame 0, the first contact with the floor (the lowest vertex
// within kContactTolerance of the height at frame 0 above the floor), the deepest compression during that
// first contact (the smallest height of the bodies' box), the last frame (rest), the highest rebound after
// the contact (the highest lowest vertex once off the floor, before touching again), and the turn back
// (the first frame after the contact whose horizontal centre-of-mass velocity points against frame 0's), and the
// end of the going back (after the turn, the frame whose box centre lies farthest back along frame 0's
// horizontal velocity). Those that exist
// and fit in `tiles`; the tiles left over take, one by one, the frame farthest from every frame chosen.
// Sorted. Without a floor only frame 0, the last and the spread-out frames.
std::vector<int> frames_from_motion(const std::vector<MotionSample>& motion, int tiles,
                                    std::optional<double> floor_height_m);

// Fraction of the bodies' height at frame 0: the lowest vertex this close to the floor touches it.
constexpr double kContactTolerance = 0.01;

}  // namespace output
