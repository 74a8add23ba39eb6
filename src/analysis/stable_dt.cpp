// Stable-dt measurement by bisection.
#include "analysis/stable_dt.hpp"

#include <cmath>

#include "core/errors.hpp"
#include "sim/step/diagnostics.hpp"

namespace analysis {
namespace {

double total_energy(const sim::World& world) {
  double energy = 0.0;
  for (std::size_t b = 0; b < world.model.bodies.size(); ++b)
    energy += sim::diagnose(world.model, world.state, b).total_J();
  return energy;
}

}  // namespace

void shake(sim::World& world, double amplitude_m_per_s) {
  std::vector<sim::Vec3>& v = world.state.v;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const double s = static_cast<double>(i);
    v[i] += amplitude_m_per_s * sim::Vec3(std::sin(7.1 * s), std::cos(3.3 * s), std::sin(5.7 * s + 1.0));
  }
}

bool runs_stable(sim::World& world, double dt, int steps) {
  const double start = total_energy(world);
  try {
    for (int s = 0; s < steps; ++s) world.step(dt);
  } catch (const softbody::DivergedError&) {
    return false;
  }
  const double end = total_energy(world);
  return std::isfinite(end) && end <= start + std::abs(start);
}

StableDtMeasurement measure_stable_dt(const std::function<sim::World()>& make_world, double low, double high, int steps,
                                      double relative_tolerance) {
  auto stable = [&](double dt) {
    sim::World world = make_world();
    return runs_stable(world, dt, steps);
  };
  for (int doubling = 0; doubling < 20 && stable(high); ++doubling) low = high, high *= 2.0;
  while (high / low > 1.0 + relative_tolerance) {
    const double mid = std::sqrt(low * high);
    (stable(mid) ? low : high) = mid;
  }
  return {low, high};
}

}  // namespace analysis
