// Signal handlers that only record the signal; the frame loops poll it between steps, setup between phases.
#include "frames/stop_request.hpp"

#include <atomic>
#include <csignal>
#include <string>

#include <signal.h>
#include <time.h>

namespace frames {
namespace {

// Written by the handler (whichever thread the signal lands on), read by the stepping threads: a lock-free
// atomic is both async-signal-safe and free of data races between threads ([support.signal]); a relaxed load
// is an ordinary load on every target we build for.
std::atomic<std::sig_atomic_t> g_stop_signal{0};
static_assert(std::atomic<std::sig_atomic_t>::is_always_lock_free, "the signal handler needs a lock-free atomic");
struct timespec g_first_request {};

// The first SIGINT / SIGTERM asks to stop. Another one a second or more later (a user pressing Ctrl-C again)
// ends the process at once with the default action; one that comes sooner is the same request delivered
// twice (timeout(1) signals both the process and its process group) and is ignored.
// Only async-signal-safe calls here: clock_gettime, sigaction, raise, lock-free atomics.
extern "C" void record_stop_signal(int signal) {
  struct timespec now {};
  clock_gettime(CLOCK_MONOTONIC, &now);
  if (g_stop_signal.load(std::memory_order_relaxed) == 0) {
    g_first_request = now;
    g_stop_signal.store(signal, std::memory_order_relaxed);
    return;
  }
  if (now.tv_sec - g_first_request.tv_sec < 1) return;
  struct sigaction default_action {};
  default_action.sa_handler = SIG_DFL;
  sigemptyset(&default_action.sa_mask);
  sigaction(signal, &default_action, nullptr);
  raise(signal);
}

std::string signal_name(int signal) { return signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : "a signal"; }

}  // namespace

void stop_on_signals() {
  struct sigaction action {};
  action.sa_handler = record_stop_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = 0;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int stop_signal() { return g_stop_signal.load(std::memory_order_relaxed); }

bool stop_requested() { return g_stop_signal.load(std::memory_order_relaxed) != 0; }

Interrupted::Interrupted(int signal, int complete_frames)
    : Interrupted(signal, signal_name(signal) + ": stopped after " + std::to_string(complete_frames) +
                              " complete frames (the outputs hold those frames only)") {
  complete_frames_ = complete_frames;
}

Interrupted::Interrupted(int signal, const std::string& what) : std::runtime_error(what), signal_(signal) {}

Interrupted Interrupted::during_setup(int signal, const std::string& phase_done) {
  return Interrupted(signal,
                     signal_name(signal) + ": stopped during setup, after " + phase_done + "; nothing was written");
}

Interrupted Interrupted::while_writing(int signal, const std::string& output) {
  return Interrupted(signal, signal_name(signal) + ": stopped while " + output +
                                 " (a FIFO or device) waited for its reader; it was not written whole");
}

void throw_if_stop_requested(int complete_frames) {
  if (const int signal = stop_signal(); signal != 0) throw Interrupted(signal, complete_frames);
}

void throw_if_stop_requested_after(const std::string& phase_done) {
  if (const int signal = stop_signal(); signal != 0) throw Interrupted::during_setup(signal, phase_done);
}

}  // namespace frames
