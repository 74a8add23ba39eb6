// What `softbody --version` prints: the version, the commit and build it came from, and the licence.
#pragma once

#include <string>

namespace app {

// The git commit the program was built from, 12 hex digits ("+changes" when the work tree differed; "unknown"
// outside a checkout). Defined in a file generated at build time (cmake/source_commit.cmake).
const char* source_commit();

// The licence every artefact of softbody is distributed under (LICENSE), as an SPDX expression.
inline constexpr const char* kLicence = "GPL-3.0-or-later";

// The full --version text: "softbody 0.1.0 (commit …, build …)", the copyright and licence lines.
std::string version_text();

}  // namespace app
