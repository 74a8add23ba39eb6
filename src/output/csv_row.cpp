// A CSV row from a body's diagnostics.
#include "output/csv_row.hpp"

#include "sim/step/diagnostics.hpp"

namespace output {

CsvRow csv_row(int frame, double time_s, const sim::World& world, std::size_t body) {
  const sim::BodyDiagnostics d = sim::diagnose(world.model, world.state, body);
  return {frame,
          time_s,
          body,
          {d.com_m.x(), d.com_m.y(), d.com_m.z(), d.com_velocity_m_per_s.x(), d.com_velocity_m_per_s.y(),
           d.com_velocity_m_per_s.z(), d.volume_m3, d.kinetic_J, d.total_J(), d.min_y_m}};
}

}  // namespace output
