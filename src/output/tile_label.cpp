// A 5×7 bitmap font for digits and the few letters of a time label.
#include "output/tile_label.hpp"

#include <array>
#include <cstdint>

namespace output {
namespace {

constexpr int kGlyphWidth = 5, kGlyphHeight = 7, kAdvance = 6, kPadding = 2;
constexpr std::uint8_t kInk = 20, kBox = 255;

// Rows top to bottom, the 5 low bits left to right.
using Glyph = std::array<std::uint8_t, kGlyphHeight>;

Glyph glyph_of(char c) {
  switch (c) {
    case '0': return {0x0E, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0E};
    case '1': return {0x04, 0x0C, 0x04, 0x04, 0x04, 0x04, 0x0E};
    case '2': return {0x0E, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1F};
    case '3': return {0x1F, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0E};
    case '4': return {0x02, 0x06, 0x0A, 0x12, 0x1F, 0x02, 0x02};
    case '5': return {0x1F, 0x10, 0x1E, 0x01, 0x01, 0x11, 0x0E};
    case '6': return {0x06, 0x08, 0x10, 0x1E, 0x11, 0x11, 0x0E};
    case '7': return {0x1F, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08};
    case '8': return {0x0E, 0x11, 0x11, 0x0E, 0x11, 0x11, 0x0E};
    case '9': return {0x0E, 0x11, 0x11, 0x0F, 0x01, 0x02, 0x0C};
    case '.': return {0x00, 0x00, 0x00, 0x00, 0x00, 0x0C, 0x0C};
    case '-': return {0x00, 0x00, 0x00, 0x1F, 0x00, 0x00, 0x00};
    case 's': return {0x00, 0x00, 0x0E, 0x10, 0x0E, 0x01, 0x1E};
    case 't': return {0x08, 0x08, 0x1C, 0x08, 0x08, 0x09, 0x06};
    case '=': return {0x00, 0x00, 0x1F, 0x00, 0x1F, 0x00, 0x00};
    default: return {};
  }
}

void fill(softbody::Image& image, int x, int y, int size, std::uint8_t value) {
  for (int dy = 0; dy < size; ++dy) {
    for (int dx = 0; dx < size; ++dx) {
      const int px = x + dx, py = y + dy;
      if (px < 0 || py < 0 || px >= image.width || py >= image.height) continue;
      std::uint8_t* rgb = image.pixel(px, py);
      rgb[0] = rgb[1] = rgb[2] = value;
    }
  }
}

}  // namespace

int label_width_px(int length, int scale) { return (2 * kPadding + length * kAdvance - 1) * scale; }
int label_height_px(int scale) { return (2 * kPadding + kGlyphHeight) * scale; }

void draw_label(softbody::Image& image, int left, int top, std::string_view text, int scale) {
  const int width = label_width_px(static_cast<int>(text.size()), scale) / scale;
  const int height = label_height_px(scale) / scale;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) fill(image, left + x * scale, top + y * scale, scale, kBox);
  }
  for (std::size_t i = 0; i < text.size(); ++i) {
    const Glyph glyph = glyph_of(text[i]);
    const int glyph_left = left + (kPadding + static_cast<int>(i) * kAdvance) * scale;
    for (int row = 0; row < kGlyphHeight; ++row) {
      for (int column = 0; column < kGlyphWidth; ++column) {
        if ((glyph[row] >> (kGlyphWidth - 1 - column)) & 1) {
          fill(image, glyph_left + column * scale, top + (kPadding + row) * scale, scale, kInk);
        }
      }
    }
  }
}

}  // namespace output
