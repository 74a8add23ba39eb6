// figure.png's frames from the motion, on a made-up bounce whose moments are known, and the time labels.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "output/figure_frames.hpp"
#include "output/tile_label.hpp"

namespace {

// 21 frames of a 1 m tall body thrown along +x: falls until frame 5, touches the floor (y = 0) from frame 5
// to frame 8 and is squashed most at frame 7, flies again and is highest at frame 13, touches again from 17;
// its horizontal velocity turns negative at frame 8.
std::vector<output::MotionSample> made_up_bounce() {
  std::vector<output::MotionSample> motion;
  const double lowest[] = {3.0, 2.6, 2.0,  1.3, 0.6, 0.0, 0.0, 0.0, 0.0, 0.2, 0.5,
                           0.7, 0.8, 0.85, 0.8, 0.6, 0.3, 0.0, 0.0, 0.0, 0.0};
  const double height[] = {1, 1, 1, 1, 1, 0.9, 0.8, 0.7, 0.85, 1, 1, 1, 1, 1, 1, 1, 1, 0.95, 0.9, 0.95, 0.95};
  for (int i = 0; i <= 20; ++i) {
    output::MotionSample s;
    s.frame = i;
    s.time_s = i / 30.0;
    s.min = {0.1 * i, lowest[i], -0.5};
    s.max = {0.1 * i + 1.0, lowest[i] + height[i], 0.5};
    s.com_velocity = {i < 8 ? 2.0 : -0.5, 0.0, 0.0};
    motion.push_back(s);
  }
  return motion;
}

TEST(FigureFrames, TheBouncesMomentsAreChosen) {
  // 0, first contact 5, deepest compression 7, rest 20, highest rebound 13, turn back 8.
  EXPECT_EQ(output::frames_from_motion(made_up_bounce(), 6, 0.0), (std::vector<int>{0, 5, 7, 8, 13, 20}));
  // Fewer tiles keep the first moments in priority: 0, contact, compression, rest.
  EXPECT_EQ(output::frames_from_motion(made_up_bounce(), 4, 0.0), (std::vector<int>{0, 5, 7, 20}));
}

TEST(FigureFrames, TheEndOfTheGoingBackIsChosen) {
  // The body moves +x until frame 8, then back until frame 15 (its box centre smallest there), then on again.
  std::vector<output::MotionSample> motion = made_up_bounce();
  for (output::MotionSample& s : motion) {
    const double x = s.frame <= 8    ? 0.1 * s.frame
                     : s.frame <= 15 ? 0.8 - 0.05 * (s.frame - 8)
                                     : 0.45 + 0.01 * (s.frame - 15);
    s.min.x() = x;
    s.max.x() = x + 1.0;
  }
  // 0, contact 5, compression 7, rest 20, rebound 13, turn back 8, farthest back 15.
  EXPECT_EQ(output::frames_from_motion(motion, 7, 0.0), (std::vector<int>{0, 5, 7, 8, 13, 15, 20}));
}

TEST(FigureFrames, SpareTilesGoWhereTheSheetHasTheLongestGap) {
  // The key frames 0, 5, 7, 8, 13, 20, then 16 (3 frames from 13 and from 20: the longest gap split), then 2
  // (the lowest of the frames 2 away from every chosen one).
  EXPECT_EQ(output::frames_from_motion(made_up_bounce(), 8, 0.0), (std::vector<int>{0, 2, 5, 7, 8, 13, 16, 20}));
}

TEST(FigureFrames, WithoutAFloorOnlyFirstLastAndSpreadFrames) {
  EXPECT_EQ(output::frames_from_motion(made_up_bounce(), 3, std::nullopt), (std::vector<int>{0, 10, 20}));
}

TEST(TileLabel, InkInsideItsBoxOnly) {
  softbody::Image image(80, 30);
  std::fill(image.rgb.begin(), image.rgb.end(), 128);
  output::draw_label(image, 3, 4, "t = 0.63 s", 1);
  const int width = output::label_width_px(10, 1), height = output::label_height_px(1);
  int ink = 0, outside_changed = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const bool inside = x >= 3 && x < 3 + width && y >= 4 && y < 4 + height;
      const std::uint8_t value = image.pixel(x, y)[0];
      if (inside && value < 64) ++ink;
      if (!inside && value != 128) ++outside_changed;
    }
  }
  EXPECT_GT(ink, 40);  // 8 glyphs of 7-19 pixels each
  EXPECT_EQ(outside_changed, 0);
}

}  // namespace
