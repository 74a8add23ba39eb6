// The program's error types and the exit status each maps to (documented in --help and docs/guide/errors.md).
#pragma once

#include <stdexcept>
#include <string>

namespace softbody {

// Process exit statuses: 0 ok, 1 anything else, 2 bad input, 3 the simulation diverged.
enum ExitStatus : int { kExitOk = 0, kExitFailure = 1, kExitBadInput = 2, kExitDiverged = 3 };

// Bad input: a scene, mesh file or command-line value that cannot be used.
// The message already names the file, the key path and what was expected.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The simulation left its stable range (non-finite values, collapsed volume, runaway energy).
class DivergedError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace softbody
