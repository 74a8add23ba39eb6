// Parsing frame ranges.
#include "frames/frame_selection.hpp"

#include <cctype>

#include "core/errors.hpp"

namespace frames {
namespace {

// A frame number of at most 9 digits, or nothing when `text` is empty.
bool parse_frame(const std::string& text, int& frame) {
  if (text.empty() || text.size() > 9) return false;
  for (char c : text) {
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  }
  frame = std::stoi(text);
  return true;
}

}  // namespace

FrameSelection FrameSelection::all(int last_frame) {
  FrameSelection selection;
  selection.chosen_.assign(static_cast<std::size_t>(last_frame) + 1, true);
  selection.first_ = 0;
  selection.last_ = last_frame;
  selection.count_ = last_frame + 1;
  selection.everything_ = true;
  return selection;
}

FrameSelection FrameSelection::parse(const std::string& text, int last_frame, const std::string& option) {
  FrameSelection selection;
  selection.chosen_.assign(static_cast<std::size_t>(last_frame) + 1, false);
  const std::string expected =
      "expected frame ranges such as 10-20, 10, 10-, -20 or 0-9,20-29 within 0.." + std::to_string(last_frame);
  auto fail = [&](const std::string& why) -> softbody::InputError {
    return softbody::InputError(option + " " + text + ": " + why + " (" + expected + ")");
  };
  if (text.empty()) throw fail("no frames");
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = text.find(',', start);
    const std::string part = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const std::size_t dash = part.find('-');
    int a = 0, b = last_frame;
    if (dash == std::string::npos) {
      if (!parse_frame(part, a)) throw fail("'" + part + "' is not a frame number");
      b = a;
    } else {
      const std::string left = part.substr(0, dash), right = part.substr(dash + 1);
      if (left.empty() && right.empty()) throw fail("'-' names no frame");
      if (!left.empty() && !parse_frame(left, a)) throw fail("'" + left + "' is not a frame number");
      if (!right.empty() && !parse_frame(right, b)) throw fail("'" + right + "' is not a frame number");
    }
    if (a > b) throw fail("range " + part + " runs backwards");
    if (b > last_frame) throw fail("frame " + std::to_string(b) + " is past the run's last frame");
    for (int f = a; f <= b; ++f) selection.chosen_[static_cast<std::size_t>(f)] = true;
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  selection.count_ = 0;
  selection.first_ = -1;
  for (int f = 0; f <= last_frame; ++f) {
    if (!selection.chosen_[static_cast<std::size_t>(f)]) continue;
    if (selection.first_ < 0) selection.first_ = f;
    selection.last_ = f;
    ++selection.count_;
  }
  selection.everything_ = selection.count_ == last_frame + 1;
  return selection;
}

}  // namespace frames
