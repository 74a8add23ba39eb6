// Signal handlers that only record the signal; the frame loops poll it between frames.
#include "frames/stop_request.hpp"

#include <csignal>
#include <string>

#include <signal.h>
#include <time.h>

namespace frames {
namespace {

volatile std::sig_atomic_t g_stop_signal = 0;
struct timespec g_first_request {};

// The first SIGINT / SIGTERM asks to stop after the frame in progress. Another one a second or more later (a
// user pressing Ctrl-C again) ends the process at once with the default action; one that comes sooner is the
// same request delivered twice (timeout(1) signals both the process and its process group) and is ignored.
// Only async-signal-safe calls here: clock_gettime, sigaction, raise.
extern "C" void record_stop_signal(int signal) {
  struct timespec now {};
  clock_gettime(CLOCK_MONOTONIC, &now);
  if (g_stop_signal == 0) {
    g_first_request = now;
    g_stop_signal = signal;
    return;
  }
  if (now.tv_sec - g_first_request.tv_sec < 1) return;
  struct sigaction default_action {};
  default_action.sa_handler = SIG_DFL;
  sigemptyset(&default_action.sa_mask);
  sigaction(signal, &default_action, nullptr);
  raise(signal);
}

}  // namespace

void stop_on_signals() {
  struct sigaction action {};
  action.sa_handler = record_stop_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = 0;
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
