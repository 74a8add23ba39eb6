// Signal handlers that only record the signal; the frame loops poll it between frames.
#include "frames/stop_request.hpp"

#include <csignal>
#include <string>

#include <signal.h>

namespace frames {
namespace {

volatile std::sig_atomic_t g_stop_signal = 0;

extern "C" void record_stop_signal(int signal) { g_stop_signal = signal; }

}  // namespace

void stop_on_signals() {
  struct sigaction action {};
  action.sa_handler = record_stop_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND;  // the next one of the same signal takes the default action: ends the process
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int stop_signal() { return g_stop_signal; }

Interrupted::Interrupted(int signal, int complete_frames)
    : std::runtime_error(std::string(signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : "a signal") +
                         ": stopped after " + std::to_string(complete_frames) + " complete frames"),
      signal_(signal),
      complete_frames_(complete_frames) {}

void throw_if_stop_requested(int complete_frames) {
  if (const int signal = stop_signal(); signal != 0) throw Interrupted(signal, complete_frames);
}

}  // namespace frames
