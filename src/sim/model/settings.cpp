// Names of the solver's settings, from the one list of integrators, and the defaults that depend on other settings.
#include "sim/model/settings.hpp"

namespace sim {

std::string to_string(IntegratorKind integrator) { return std::string(integrator_info(integrator).name); }

std::optional<IntegratorKind> integrator_named(std::string_view name) {
  for (const IntegratorInfo& integrator : kIntegrators) {
    if (integrator.name == name) return integrator.kind;
  }
  return std::nullopt;
}

std::string to_string(FloorContact contact) {
  switch (contact) {
    case FloorContact::Paper: return "paper";
    case FloorContact::Friction: return "friction";
    case FloorContact::Smooth: return "smooth";
  }
  return "?";
}

std::string to_string(SweepControl control) {
  switch (control) {
    case SweepControl::Count: return "count";
    case SweepControl::Converge: return "converge";
    case SweepControl::Auto: return "auto";
  }
  return "?";
}

double vbd_impact_phase(const Solver& solver) {
  if (solver.impact_phase) return *solver.impact_phase;
  return solver.sweep_control == SweepControl::Auto ? kVbdAutoImpactPhase : kVbdImpactPhase;
}

std::string to_string(BodyContactModel contact) { return contact == BodyContactModel::Smooth ? "smooth" : "impulse"; }

}  // namespace sim
