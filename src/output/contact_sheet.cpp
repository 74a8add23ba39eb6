// Contact sheet layout and tile shrinking.
#include "output/contact_sheet.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "output/tile_label.hpp"

namespace output {
namespace {

constexpr int kMaxColumns = 4;
constexpr int kMaxSheetWidth_px = 2560;
constexpr int kGap_px = 8;  // white space between and around the tiles
constexpr std::uint8_t kPaper = 255;
constexpr int kLabelRowsPerFontPixel = 120;  // a 120 px tall tile gets a 1 px font pixel, 360 px gets 3

// sRGB transfer function (IEC 61966-2-1), both ways.
float srgb_to_linear(float encoded) {
  return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}
float linear_to_srgb(float linear) {
  return linear <= 0.0031308f ? linear * 12.92f : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

const std::array<float, 256>& decoding_table() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> values{};
    for (int i = 0; i < 256; ++i) values[i] = srgb_to_linear(static_cast<float>(i) / 255.0f);
    return values;
  }();
  return table;
}

std::uint8_t encode(float linear) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(linear_to_srgb(linear), 0.0f, 1.0f) * 255.0f));
}

}  // namespace

std::vector<int> evenly_spaced_frames(int tiles, int last_frame) {
  std::vector<int> frames;
  if (tiles <= 0) return frames;
  if (tiles == 1) return {0};
  for (int k = 0; k < tiles; ++k) {
    const double at = static_cast<double>(k) * last_frame / (tiles - 1);
    const int frame = static_cast<int>(std::lround(at));
    if (frames.empty() || frame != frames.back()) frames.push_back(frame);  // fewer frames than tiles
  }
  return frames;
}

ContactSheet::ContactSheet(std::vector<int> frames, int frame_width_px, int frame_height_px)
    : frames_(std::move(frames)), filled_(frames_.size(), false) {
  const int count = std::max<int>(static_cast<int>(frames_.size()), 1);
  const int rows = (count + kMaxColumns - 1) / kMaxColumns;
  columns_ = (count + rows - 1) / rows;  // balanced rows: 8 → 4 × 2, 6 → 3 × 2, 9 → 3 × 3
  shrink_ = std::max(1, (columns_ * frame_width_px + kMaxSheetWidth_px - 1) / kMaxSheetWidth_px);
  tile_width_ = frame_width_px / shrink_;
  tile_height_ = frame_height_px / shrink_;
  sheet_ = softbody::Image(kGap_px + columns_ * (tile_width_ + kGap_px), kGap_px + rows * (tile_height_ + kGap_px));
  std::fill(sheet_.rgb.begin(), sheet_.rgb.end(), kPaper);
}

bool ContactSheet::wants(int index) const { return std::find(frames_.begin(), frames_.end(), index) != frames_.end(); }

bool ContactSheet::complete() const {
  return std::all_of(filled_.begin(), filled_.end(), [](bool filled) { return filled; });
}

void ContactSheet::add(int index, const softbody::Image& frame, std::string_view label) {
  const auto found = std::find(frames_.begin(), frames_.end(), index);
  if (found == frames_.end()) return;
  const int tile = static_cast<int>(found - frames_.begin());
  const int left = kGap_px + (tile % columns_) * (tile_width_ + kGap_px);
  const int top = kGap_px + (tile / columns_) * (tile_height_ + kGap_px);
  const std::array<float, 256>& linear = decoding_table();
  const float samples = static_cast<float>(shrink_ * shrink_);
  for (int y = 0; y < tile_height_; ++y) {
    for (int x = 0; x < tile_width_; ++x) {
      std::array<float, 3> sum{};
      for (int dy = 0; dy < shrink_; ++dy) {
        for (int dx = 0; dx < shrink_; ++dx) {
          const std::uint8_t* source = frame.pixel(x * shrink_ + dx, y * shrink_ + dy);
          for (int c = 0; c < 3; ++c) sum[c] += linear[source[c]];
        }
      }
      std::uint8_t* target = sheet_.pixel(left + x, top + y);
      for (int c = 0; c < 3; ++c) target[c] = encode(sum[c] / samples);
    }
  }
  if (!label.empty()) {
    const int scale = std::max(1, tile_height_ / kLabelRowsPerFontPixel);
    draw_label(sheet_, left + scale * 2, top + scale * 2, label, scale);
  }
  filled_[tile] = true;
}

}  // namespace output
