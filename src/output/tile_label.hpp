// Small text burnt into a picture: the time of each tile of figure.png ("t = 0.63 s"), in a 5×7 pixel font.
#pragma once

#include <string_view>

#include "core/image.hpp"

namespace output {

// Draws `text` (digits, '.', '-', 's', 't', '=', ' '; other characters as blanks) dark on a white box whose
// top-left corner is (left, top), each font pixel `scale` × `scale` image pixels; clipped to the image.
void draw_label(softbody::Image& image, int left, int top, std::string_view text, int scale);

// The size draw_label covers for `length` characters at `scale` (box included).
int label_width_px(int length, int scale);
int label_height_px(int scale);

}  // namespace output
