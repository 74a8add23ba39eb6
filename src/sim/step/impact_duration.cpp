// A gas-filled body's impact duration.
#include "sim/step/impact_duration.hpp"

#include <cmath>
#include <numbers>

namespace sim {

double gas_impact_duration(const Body& body) {
  const double volume = body.rest.volume_m3;
  if (body.params.pressure_J <= 0.0 || volume <= 0.0 || body.masses.total_kg <= 0.0) return 0.0;
  const double radius = std::cbrt(3.0 * volume / (4.0 * std::numbers::pi));  // [m]
  const double pressure = body.params.pressure_J / volume;                   // [Pa]
  const double stiffness = 2.0 * std::numbers::pi * radius * pressure;       // [N/m]
  return std::numbers::pi * std::sqrt(body.masses.total_kg / stiffness);
}

}  // namespace sim
