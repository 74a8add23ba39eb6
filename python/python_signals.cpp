// Python's signal handlers, asked between steps at most every 20 ms.
#include "python_signals.hpp"

#include <chrono>

#include <pybind11/pybind11.h>

namespace softbody_python {
namespace {

// How often the steps take Python's lock back to run its signal handlers: Ctrl-C acts within this (and one step),
// and a busy Python thread costs the stepping at most its switch interval (5 ms) per check.
constexpr std::chrono::milliseconds kSignalCheckInterval{20};

}  // namespace

bool python_signal_raised() {
  using Clock = std::chrono::steady_clock;
  thread_local Clock::time_point last_check = Clock::now();
  const Clock::time_point now = Clock::now();
  if (now - last_check < kSignalCheckInterval) return false;
  last_check = now;
  const pybind11::gil_scoped_acquire locked;
  return PyErr_CheckSignals() != 0;
}

}  // namespace softbody_python
