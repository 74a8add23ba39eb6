// Expanding frame file name patterns.
#include "output/frame_pattern.hpp"

#include <cstdio>

namespace output {

std::string frame_file_name(const std::string& pattern, int index) {
  char name[512];
  // The pattern was checked to hold exactly one integer conversion.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wformat-nonliteral"
  std::snprintf(name, sizeof name, pattern.c_str(), index);
#pragma GCC diagnostic pop
  return name;
}

}  // namespace output
