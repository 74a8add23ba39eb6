// The progress line of long commands: "frame 42/90  24.1 fps  2.0 s left", redrawn in place on stderr
// when stderr is a terminal, silent otherwise (logs and pipes get only the final summary).
#pragma once

#include <chrono>

namespace app {

class ProgressLine {
 public:
  ProgressLine();  // enabled when stderr is a terminal
  // Frame `done` (0-based index of the frame just finished) of frames 0 .. `last`.
  void update(int done, int last);
  // Clears the line, so that what is printed next starts on a clean line.
  void clear();

 private:
  bool enabled_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace app
