// Image comparison for golden tests: decoded pixels with a per-pixel threshold and an allowed fraction
// of differing pixels, never file bytes (PNG encoders may change, pixels may not).
#pragma once

#include <filesystem>
#include <string>

#include "core/image.hpp"

namespace render_test {

struct Tolerance {
  int channel_threshold = 16;      // a pixel differs when any channel differs by more than this (of 255)
  double allowed_fraction = 0.01;  // the images match while at most this fraction of pixels differ
};

struct Comparison {
  bool same_size = false;
  long differing_pixels = 0;
  double differing_fraction = 0.0;
  int max_channel_difference = 0;
};

Comparison compare_images(const softbody::Image& actual, const softbody::Image& expected, const Tolerance& tolerance);

// A picture of where two images differ: black where they agree within the threshold, red where they
// do not (brighter for bigger differences), over a faint grey copy of `expected`.
softbody::Image difference_image(const softbody::Image& actual, const softbody::Image& expected,
                                 const Tolerance& tolerance);

// Compares `actual` with tests/golden/<name>.png. With SOFTBODY_UPDATE_GOLDEN=1 in the environment,
// (re)writes the golden file instead and passes. On a mismatch writes <name>_actual.png,
// <name>_expected.png and <name>_diff.png under the build tree and returns a message saying where;
// returns an empty string when the images match.
std::string check_against_golden(const softbody::Image& actual, const std::string& name, const Tolerance& tolerance);

}  // namespace render_test
