// A picture in memory: 8-bit sRGB-encoded RGB, rows from the top, what PNG files and ffmpeg take.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace softbody {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  // width · height · 3 bytes, row 0 at the top

  Image() = default;
  Image(int width_px, int height_px)
      : width(width_px), height(height_px), rgb(static_cast<std::size_t>(width_px) * height_px * 3, 0) {}

  std::size_t row_bytes() const { return static_cast<std::size_t>(width) * 3; }
  std::uint8_t* pixel(int x, int y) { return rgb.data() + (static_cast<std::size_t>(y) * width + x) * 3; }
  const std::uint8_t* pixel(int x, int y) const { return rgb.data() + (static_cast<std::size_t>(y) * width + x) * 3; }
};

}  // namespace softbody
