// Which build of the program this is, as far as simulated states go.
#pragma once

namespace setup {

// 64 hexadecimal digits: the SHA-256 of every source under src/ that can change a simulated state (all but the
// renderer) and of the compiler, its version, the build type and flags (cmake/physics_fingerprint.cmake). Two
// builds with the same fingerprint simulate a scene to the same bytes on the same machine.
const char* build_fingerprint();

}  // namespace setup
