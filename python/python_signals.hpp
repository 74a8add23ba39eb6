// Python's signal handlers, asked from C++ work that runs with Python's lock released: Ctrl-C (SIGINT) in Python
// stops the steps of frames() and of render()'s framing pass between two steps.
#pragma once

namespace softbody_python {

// A sim::StopQuery, asked before every step with Python's lock released: every 20 ms it takes the lock and runs
// Python's signal handlers (in the main thread; elsewhere Python runs none); true when one raised (SIGINT's
// KeyboardInterrupt), which then stays set for the caller to raise with pybind11::error_already_set.
bool python_signal_raised();

}  // namespace softbody_python
