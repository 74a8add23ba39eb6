// Which frames a run hands to its outputs: all, or the ranges of `--frames` ("A-B", "A", "A-", "-B", and
// lists such as "0-9,20-29"), so that chunks of a sequence can be rendered on different machines.
#pragma once

#include <string>
#include <vector>

namespace frames {

class FrameSelection {
 public:
  // Every frame 0 .. last_frame.
  static FrameSelection all(int last_frame);
  // Parses `text` for a run whose frames are 0 .. last_frame. Throws softbody::InputError naming `option`
  // and what is wrong (syntax, a frame past the last, an empty or reversed range).
  static FrameSelection parse(const std::string& text, int last_frame, const std::string& option = "--frames");

  bool contains(int frame) const { return frame >= 0 && frame < static_cast<int>(chosen_.size()) && chosen_[frame]; }
  // The first and last chosen frames.
  int first() const { return first_; }
  int last() const { return last_; }
  // True when every frame 0 .. last_frame is chosen.
  bool everything() const { return everything_; }
  int count() const { return count_; }

 private:
  std::vector<bool> chosen_;  // per frame 0 .. last_frame
  int first_ = 0, last_ = 0, count_ = 0;
  bool everything_ = true;
};

}  // namespace frames
