// What a diverged run reports, as data (for the analysis tools) and as the message a user reads.
#pragma once

#include <string>

#include "core/errors.hpp"
#include "sim/model/settings.hpp"
#include "sim/step/guard.hpp"

namespace sim {

struct DivergenceReport {
  Divergence finding;   // what the guard found, in which body and vertex
  double time_s = 0.0;  // the time of the state found diverged
  long long step = 0;   // the step that produced it (counting from 1)
  double dt_s = 0.0;    // the step size that produced it
  IntegratorKind integrator = IntegratorKind::Euler;
  // The stable-dt estimate at the model's initial state (sim/step/stability.hpp) for `integrator` (0: no stable dt;
  // infinite: any dt).
  double stable_dt_s = 0.0;
  // The contact travel limit that the run's given substeps exceed (Solver::travel_dt_exceeded_s) [s]; 0: none.
  double travel_dt_exceeded_s = 0.0;
};

// "diverged at t = 0.0954 s (step 478, dt = 0.0002 s, euler): body 0, vertex 637 runaway speed: ...;
// estimated stable: dt <= 0.000125 s for euler; vbd takes every force implicitly, at any dt (softbody info SCENE
// prints the estimate)"
std::string describe(const DivergenceReport& report);

// The error a step throws when the guard stops a run: softbody::DivergedError (exit status 3) with the
// report kept as data.
class DivergedError : public softbody::DivergedError {
 public:
  explicit DivergedError(DivergenceReport report) : softbody::DivergedError(describe(report)), report_(report) {}
  const DivergenceReport& report() const { return report_; }

 private:
  DivergenceReport report_;
};

}  // namespace sim
