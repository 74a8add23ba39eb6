// The divergence guard: cheap checks after a step that the state is still a physical one.
#pragma once

#include <optional>
#include <string>

#include "sim/model/model.hpp"
#include "sim/model/state.hpp"

namespace sim {

// What the guard can find wrong.
enum class DivergenceKind {
  NonFinitePosition,
  NonFiniteVelocity,
  RunawayEnergy,
  VolumeInverted,
  VolumeCollapsed,
  StepUnderflow,  // an adaptive integrator's step fell below what the time can resolve
};

// What the guard found, and where.
struct Divergence {
  DivergenceKind kind = DivergenceKind::NonFinitePosition;
  int body = 0;
  int vertex = -1;   // -1 when the finding is about the whole body (its volume)
  std::string what;  // e.g. "has a non-finite velocity", "volume inverted (V = -0.1 m^3, rest volume V0 = 4.1 m^3)"
};

// The guard's thresholds.
inline constexpr double kRunawayFactor = 10.0;     // internal kinetic energy over the energy budget
inline constexpr double kCollapseFraction = 0.01;  // of the rest volume
inline constexpr int kFullCheckInterval = 8;       // steps between the full checks of a fixed-step run

// Check 1 alone, every position and velocity finite (one vectorised pass in the common case): what a step
// runs between full checks.
std::optional<Divergence> check_finite(const Model& model, const State& state);

// Every check, per body, in two passes (vertices, then faces):
//   1. every position and velocity finite;
//   2. internal kinetic energy (relative to the centre of mass) ≤ kRunawayFactor × the energy budget the
//      body started with: its kinetic energy, its spring energy, the gas's work down to the collapse
//      limit nRT ln(V / (kCollapseFraction V0)), and its fall to the floor M |g| (y_com − y_floor).
//      Gravity alone does not change internal motion, so only numerical energy gain can exceed it;
//   3. for a body with gas: enclosed volume > 0 (not inverted) and > kCollapseFraction V0 (collapsed).
// The budget is taken from the state at the first full check after it was forgotten (State::guard, e.g.
// State::forget_carry()), and kept in the state.
std::optional<Divergence> check_all(const Model& model, State& state);

}  // namespace sim
