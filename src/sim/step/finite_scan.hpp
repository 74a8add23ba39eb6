// A fast yes/no test that every coordinate of a state array is finite (the guard's common case).
#pragma once

#include <span>

#include "core/vec.hpp"

namespace sim {

// True when no coordinate is NaN or ±∞. One branch-free pass that the compiler vectorises; the caller
// looks for the culprit only when it is false.
bool all_finite(std::span<const softbody::Vec3> values);

}  // namespace sim
