// Golden image comparison and its failure artefacts.
#include "image_compare.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "output/atomic_file.hpp"
#include "output/png_codec.hpp"

namespace render_test {
namespace {

int max_channel_difference(const std::uint8_t* a, const std::uint8_t* b) {
  int largest = 0;
  for (int c = 0; c < 3; ++c) largest = std::max(largest, std::abs(int(a[c]) - int(b[c])));
  return largest;
}

bool updating_goldens() {
  const char* flag = std::getenv("SOFTBODY_UPDATE_GOLDEN");
  return flag != nullptr && std::strcmp(flag, "1") == 0;
}

}  // namespace

Comparison compare_images(const softbody::Image& actual, const softbody::Image& expected, const Tolerance& tolerance) {
  Comparison result;
  result.same_size = actual.width == expected.width && actual.height == expected.height;
  if (!result.same_size) return result;
  for (int y = 0; y < actual.height; ++y) {
    for (int x = 0; x < actual.width; ++x) {
      const int difference = max_channel_difference(actual.pixel(x, y), expected.pixel(x, y));
      result.max_channel_difference = std::max(result.max_channel_difference, difference);
      if (difference > tolerance.channel_threshold) ++result.differing_pixels;
    }
  }
  result.differing_fraction = static_cast<double>(result.differing_pixels) / (double(actual.width) * actual.height);
  return result;
}

softbody::Image difference_image(const softbody::Image& actual, const softbody::Image& expected,
                                 const Tolerance& tolerance) {
  softbody::Image diff(expected.width, expected.height);
  for (int y = 0; y < expected.height; ++y) {
    for (int x = 0; x < expected.width; ++x) {
      const std::uint8_t* e = expected.pixel(x, y);
      std::uint8_t* d = diff.pixel(x, y);
      const auto grey = static_cast<std::uint8_t>((e[0] + e[1] + e[2]) / 12);  // a faint guide
      d[0] = d[1] = d[2] = grey;
      const int difference = max_channel_difference(actual.pixel(x, y), e);
      if (difference > tolerance.channel_threshold) {
        d[0] = static_cast<std::uint8_t>(std::min(255, 128 + difference));
        d[1] = d[2] = 0;
      }
    }
  }
  return diff;
}

std::string check_against_golden(const softbody::Image& actual, const std::string& name, const Tolerance& tolerance) {
  const std::filesystem::path golden = std::filesystem::path(SOFTBODY_GOLDEN_DIR) / (name + ".png");
  if (updating_goldens()) {
    output::write_file_atomically(golden, output::encode_png(actual));
    std::printf("updated golden image %s\n", golden.string().c_str());
    return "";
  }
  if (!std::filesystem::exists(golden)) {
    return "no golden image " + golden.string() + " (run the test with SOFTBODY_UPDATE_GOLDEN=1 to create it)";
  }
  const softbody::Image expected = output::read_png(golden);
  const Comparison comparison = compare_images(actual, expected, tolerance);
  const bool matches = comparison.same_size && comparison.differing_fraction <= tolerance.allowed_fraction;
  if (matches) return "";

  const std::filesystem::path dir = std::filesystem::path(SOFTBODY_TEST_OUTPUT_DIR) / "golden_failures";
  output::write_file_atomically(dir / (name + "_actual.png"), output::encode_png(actual));
  output::write_file_atomically(dir / (name + "_expected.png"), output::encode_png(expected));
  if (comparison.same_size) {
    output::write_file_atomically(dir / (name + "_diff.png"),
                                  output::encode_png(difference_image(actual, expected, tolerance)));
  }
  char summary[256];
  if (comparison.same_size) {
    std::snprintf(summary, sizeof summary,
                  "%ld pixels (%.2f %%) differ by more than %d levels (allowed %.2f %%), largest difference %d",
                  comparison.differing_pixels, 100.0 * comparison.differing_fraction, tolerance.channel_threshold,
                  100.0 * tolerance.allowed_fraction, comparison.max_channel_difference);
  } else {
    std::snprintf(summary, sizeof summary, "size %dx%d, expected %dx%d", actual.width, actual.height, expected.width,
                  expected.height);
  }
  return name + " does not match " + golden.string() + ": " + summary + "; see " + (dir / name).string() +
         "_{actual,expected,diff}.png (SOFTBODY_UPDATE_GOLDEN=1 accepts the new image)";
}

}  // namespace render_test
