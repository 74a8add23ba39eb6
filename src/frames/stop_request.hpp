// SIGINT and SIGTERM as a request to stop after the frame in progress: the frame loops end there, the sinks
// finish with the complete frames (the CSV keeps their rows), and the program exits 128 + the signal.
#pragma once

#include <stdexcept>

namespace frames {

// Installs the handlers (once per process; another signal a second or more after the first kills at once, the
// default action; one sooner is taken as the same request delivered twice).
void stop_on_signals();

// The signal that asked to stop (SIGINT, SIGTERM), or 0.
int stop_signal();

// Thrown by the frame loops once a stop was requested, after `complete_frames` frames were handed out.
class Interrupted : public std::runtime_error {
 public:
  Interrupted(int signal, int complete_frames);
  int signal() const { return signal_; }
  int complete_frames() const { return complete_frames_; }

 private:
  int signal_;
  int complete_frames_;
};

// Throws Interrupted when a stop was requested.
void throw_if_stop_requested(int complete_frames);

}  // namespace frames
