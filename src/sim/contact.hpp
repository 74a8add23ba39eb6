// Contact with the floor plane y = height, applied after each integration step.
#pragma once

#include <span>

#include "core/vec.hpp"

namespace sim {

using softbody::Vec3;

// The paper's collision response (Matyka & Ollila 2003, Sect. 2.5): a vertex found below the floor
// gets the impulse J = m Δv with Δv = −2v, i.e. its whole velocity is reflected (v ← −v), and it is put
// back on the floor. Returns the number of vertices that were below.
int resolve_floor_paper(double height_m, std::span<Vec3> x, std::span<Vec3> v);

}  // namespace sim
