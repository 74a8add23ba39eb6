// figure.png, the paper's Figure 1 as a contact sheet: a few frames of the run side by side, read left
// to right, top to bottom, showing the fall, the landing and the bounce.
#pragma once

#include <string_view>
#include <vector>

#include "core/image.hpp"

namespace output {

// The frames shown when the motion is not known beforehand: `tiles` frame indices spread evenly over
// 0 .. last_frame, first and last included (output/figure_frames.hpp chooses them from the motion).
std::vector<int> evenly_spaced_frames(int tiles, int last_frame);

class ContactSheet {
 public:
  // A sheet for `frames` (indices, in reading order) of frame_width × frame_height images. Tiles are
  // the frames shrunk by a whole factor so that a row stays within about 2560 pixels.
  ContactSheet(std::vector<int> frames, int frame_width_px, int frame_height_px);

  // True when frame `index` belongs on the sheet.
  bool wants(int index) const;
  // Shrinks `frame` into the tile of frame `index` (a box filter in linear light, so edges keep their
  // brightness) and writes `label` (its time) into the tile's top-left corner. Ignores frames the sheet
  // does not want.
  void add(int index, const softbody::Image& frame, std::string_view label = {});
  // True when every tile has been filled.
  bool complete() const;

  const softbody::Image& image() const { return sheet_; }
  int columns() const { return columns_; }
  int shrink_factor() const { return shrink_; }

 private:
  std::vector<int> frames_;
  std::vector<bool> filled_;
  int columns_ = 1;
  int shrink_ = 1;
  int tile_width_ = 0;
  int tile_height_ = 0;
  softbody::Image sheet_;
};

}  // namespace output
