// How long a gas-filled body's impact on a flat contact lasts: for `softbody info`, which prices vbd's small steps
// through an impact per impact.
#pragma once

#include "sim/model/body.hpp"

namespace sim {

// The gas presses the flattened cap with its pressure, F = P A, and a sphere of radius R sunk by δ touches a disc of
// A = π (2 R δ − δ²) ≈ 2π R δ, so the body bounces on a spring of 2π R P and stays down for half its period:
//   t = π √(m / (2π R P)),  R = (3 V₀ / 4π)^(1/3),  P = nRT / V₀                          [s]
// (V₀ the rest volume, m the body's mass). The ball of scenes/bounce_smooth.json (1 kg, nRT 200 J): 0.181 s, where
// it is within 1 cm of the floor for 0.175 s; 0.256 s at nRT 100 J (0.244 measured); at 800 J 0.090 s against 0.130 s,
// the springs' and the contact's share growing (docs/notes/2026-12-07-vbd-vertex-order.md). 0 without gas.
double gas_impact_duration(const Body& body);

}  // namespace sim
