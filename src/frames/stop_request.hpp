// SIGINT and SIGTERM as a request to stop: the frame loops end within one step (the frame in progress is
// discarded), setup ends when the phase in progress ends; the sinks finish with the complete frames (the CSV
// keeps their rows), and the program exits 128 + the signal.
#pragma once

#include <stdexcept>
#include <string>

namespace frames {

// Installs the handlers (once per process; another signal a second or more after the first kills at once, the
// default action; one sooner is taken as the same request delivered twice).
void stop_on_signals();

// The signal that asked to stop (SIGINT, SIGTERM), or 0.
int stop_signal();

// True once a stop was requested: one relaxed atomic load, cheap enough for every step.
bool stop_requested();

// Thrown by the frame loops once a stop was requested, after `complete_frames` frames were handed out, or
// (during_setup) between two setup phases, before anything was written.
class Interrupted : public std::runtime_error {
 public:
  Interrupted(int signal, int complete_frames);
  // Setup stopped after the phase `phase_done` ("repairing meshes/bunny.obj"): no frame, no output.
  static Interrupted during_setup(int signal, const std::string& phase_done);
  // A write through a FIFO or device (`output`) that waited for its reader was stopped: not written whole.
  static Interrupted while_writing(int signal, const std::string& output);
  int signal() const { return signal_; }
  int complete_frames() const { return complete_frames_; }

 private:
  Interrupted(int signal, const std::string& what);
  int signal_;
  int complete_frames_ = 0;
};

// Throws Interrupted when a stop was requested.
void throw_if_stop_requested(int complete_frames);

// Between setup phases (a softbody::AfterPhase): throws Interrupted::during_setup naming the phase just done
// when a stop was requested.
void throw_if_stop_requested_after(const std::string& phase_done);

}  // namespace frames
