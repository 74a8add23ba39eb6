// Expanding frame file name patterns, and finding the files one names.
#include "output/frame_pattern.hpp"

#include <cstdio>
#include <vector>

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

namespace {

// The text a pattern's part before its conversion expands to ("%%" is one '%').
std::string literal_prefix(const std::string& pattern) {
  std::string text;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] != '%') {
      text += pattern[i];
    } else if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
      text += '%';
      ++i;
    } else {
      break;
    }
  }
  return text;
}

}  // namespace

std::optional<int> frame_index_of(const std::string& pattern, const std::string& name) {
  // The number follows the pattern's literal prefix; whatever the width and padding, expanding it must give
  // `name` back.
  const std::string prefix = literal_prefix(pattern);
  if (name.compare(0, prefix.size(), prefix) != 0) return std::nullopt;
  std::size_t end = prefix.size();
  while (end < name.size() && end - prefix.size() < 9 && name[end] >= '0' && name[end] <= '9') ++end;
  if (end == prefix.size()) return std::nullopt;
  const int index = std::stoi(name.substr(prefix.size(), end - prefix.size()));
  if (frame_file_name(pattern, index) != name) return std::nullopt;
  return index;
}

int remove_frame_files(const std::filesystem::path& dir, const std::string& pattern) {
  std::error_code ec;
  std::vector<std::filesystem::path> frames;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    if (frame_index_of(pattern, entry.path().filename().string()) && entry.is_regular_file(ec))
      frames.push_back(entry.path());
  }
  int removed = 0;
  for (const std::filesystem::path& frame : frames) removed += std::filesystem::remove(frame, ec) ? 1 : 0;
  return removed;
}

}  // namespace output
