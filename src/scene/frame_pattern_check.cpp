// Checking frame file name patterns.
#include "scene/frame_pattern_check.hpp"

#include <cctype>

#include "core/errors.hpp"

namespace scene {

bool is_frame_pattern(const std::string& pattern, const std::string& extension) {
  int conversions = 0;
  bool well_formed = pattern.find('/') == std::string::npos && pattern.size() > extension.size() &&
                     pattern.compare(pattern.size() - extension.size(), extension.size(), extension) == 0;
  for (std::size_t i = 0; well_formed && i < pattern.size(); ++i) {
    if (pattern[i] != '%') continue;
    if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
      ++i;
      continue;
    }
    std::size_t j = i + 1;
    if (j < pattern.size() && pattern[j] == '0') ++j;
    for (int digits = 0; j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j])) && digits < 2;
         ++digits)
      ++j;
    well_formed = j < pattern.size() && pattern[j] == 'd';
    ++conversions;
    i = j;
  }
  return well_formed && conversions == 1;
}

void check_frame_pattern(const std::string& pattern, const std::string& scene_file) {
  if (!is_frame_pattern(pattern, ".png")) {
    throw softbody::InputError(scene_file +
                               ": output.pattern: expected a file name ending in .png with one frame "
                               "number conversion such as %04d (and no '/'), got \"" +
                               pattern + "\"");
  }
}

}  // namespace scene
