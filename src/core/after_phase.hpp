// The call a long setup stage makes when one of its phases is done, so that a stop request can end setup there.
#pragma once

#include <functional>
#include <string>

namespace softbody {

// Called with the phase just done, in words that follow "after" ("repairing meshes/bunny.obj"). The CLI's
// throws frames::Interrupted when SIGINT / SIGTERM came during the phase (frames::throw_if_stop_requested_after),
// so that the run ends before the next phase starts; empty: nothing is called.
using AfterPhase = std::function<void(const std::string& phase_done)>;

}  // namespace softbody
