// User text (file names, references read from files) inside a one-line message: control characters escaped.
#pragma once

#include <cstdio>
#include <string>
#include <string_view>

namespace softbody {

// `text` with every control character (bytes below 0x20, and 0x7f) written as \n, \r, \t or \xNN, so that a
// file name holding a line break still gives a message of one line.
inline std::string one_line(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte != 0x7f) {
      out += c;
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c == '\t') {
      out += "\\t";
    } else {
      char escaped[5];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", static_cast<unsigned>(byte));
      out += escaped;
    }
  }
  return out;
}

}  // namespace softbody
