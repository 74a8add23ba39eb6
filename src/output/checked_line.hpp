// Lines that carry their own checksum, for files appended to as a run goes (the CSV journal, the run manifest):
// a line damaged on disk (bytes overwritten, cut short by a kill) is found and dropped, never trusted.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace output {

// `text` (no '\n'), a space and the XXH3-64 of `text` in 16 hexadecimal digits, then '\n'.
std::string checked_line(std::string_view text);

// The text of a line checked_line() made (without its '\n'), or nothing when its checksum does not hold.
std::optional<std::string_view> checked_text(std::string_view line);

// The XXH3-64 of `bytes` in 16 hexadecimal digits.
std::string checksum_hex(std::string_view bytes);

}  // namespace output
