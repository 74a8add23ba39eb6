// The divergence report's message.
#include "sim/step/diverged.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace sim {
namespace {

std::string stable_dt_words(double dt) {
  if (dt == 0.0) return "no stable dt (needs damping)";
  if (std::isinf(dt)) return "any dt";
  char text[64];
  std::snprintf(text, sizeof text, "dt <= %.3g s", dt);
  return text;
}

}  // namespace

std::string describe(const DivergenceReport& report) {
  std::ostringstream message;
  if (report.finding.kind == DivergenceKind::StepUnderflow) {
    message << "diverged at t = " << report.time_s << " s (step " << report.step << "): " << report.finding.what;
    return message.str();
  }
  message << "diverged at t = " << report.time_s << " s (step " << report.step << ", dt = " << report.dt_s << " s, "
          << to_string(report.integrator) << "): body " << report.finding.body;
  if (report.finding.vertex >= 0) message << ", vertex " << report.finding.vertex;
  message << " " << report.finding.what << "; estimated stable: " << stable_dt_words(report.stable_dt_s) << " for "
          << to_string(report.integrator);
  if (report.travel_dt_exceeded_s > 0.0) {
    char text[200];
    std::snprintf(text, sizeof text,
                  "; its given substeps are longer than the contact travel limit dt <= %.3g s that a contact after "
                  "the step needs (solver.substeps \"auto\" keeps it)",
                  report.travel_dt_exceeded_s);
    message << text;
  }
  if (integrator_info(report.integrator).explicit_springs) {
    message << "; vbd takes every force implicitly, at any dt";
  }
  message << " (softbody info SCENE prints the estimate)";
  return message.str();
}

}  // namespace sim
