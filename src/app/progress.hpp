// The progress line of long commands: "frame 42/90  24.1 fps  2.0 s left", redrawn in place on stderr
// when stderr is a terminal, silent otherwise (logs and pipes get only the final summary); and the
// machine-readable progress lines that programs driving softbody ask for (--progress-lines).
#pragma once

#include <chrono>

#include "frames/frame_loop.hpp"

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

// "progress DONE TOTAL" on stdout after each frame (DONE frames of TOTAL delivered), one line each, flushed at
// once: what a program that runs softbody in a pipe (the Blender add-on) reads to show its progress bar.
frames::Progress progress_lines();

}  // namespace app
