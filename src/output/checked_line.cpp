// Checksummed lines.
#include "output/checked_line.hpp"

#include <cstdio>

#include <xxhash.h>

namespace output {
namespace {

constexpr std::size_t kChecksumDigits = 16;

}  // namespace

std::string checksum_hex(std::string_view bytes) {
  char text[kChecksumDigits + 1];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(XXH3_64bits(bytes.data(), bytes.size())));
  return text;
}

std::string checked_line(std::string_view text) {
  std::string line(text);
  line += ' ';
  line += checksum_hex(text);
  line += '\n';
  return line;
}

std::optional<std::string_view> checked_text(std::string_view line) {
  if (line.size() < kChecksumDigits + 1 || line[line.size() - kChecksumDigits - 1] != ' ') return std::nullopt;
  const std::string_view text = line.substr(0, line.size() - kChecksumDigits - 1);
  if (line.substr(line.size() - kChecksumDigits) != checksum_hex(text)) return std::nullopt;
  return text;
}

}  // namespace output
