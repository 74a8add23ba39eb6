// Measuring the largest stable time step of a world by bisection: the number the estimate is checked against.
#pragma once

#include <functional>

#include "sim/step/world.hpp"

namespace analysis {

// Gives every vertex a deterministic, non-smooth velocity of about `amplitude` m/s, so every mode is excited.
void shake(sim::World& world, double amplitude_m_per_s);

// True when `steps` fixed steps of dt run without the guard stopping them and the total energy at the end
// is at most twice the start's (a slowly growing mode that has not yet tripped the guard counts as unstable).
bool runs_stable(sim::World& world, double dt, int steps);

struct StableDtMeasurement {
  double stable_dt_s = 0.0;    // the largest dt found stable
  double unstable_dt_s = 0.0;  // the smallest dt found unstable (stable_dt_s < it, within the tolerance)
};

// Bisection in log dt between `low` (must be stable) and `high` (must be unstable; doubled until it is)
// to a relative width of `relative_tolerance`; `make_world` builds a fresh (shaken) world per trial.
StableDtMeasurement measure_stable_dt(const std::function<sim::World()>& make_world, double low, double high, int steps,
                                      double relative_tolerance = 0.03);

}  // namespace analysis
