// One row of the simulation CSV as numbers: a body's diagnostics at one frame, by column. The CSV writer formats
// them; the Python module's Simulation.row() hands them out, so that both carry the same bits.
#pragma once

#include <array>
#include <cstddef>
#include <string_view>

#include "sim/step/world.hpp"

namespace output {

// The columns after frame, time and body, in the CSV's order (output/csv_sink.hpp's kCsvHeader).
inline constexpr std::array<std::string_view, 10> kCsvBodyColumns = {
    "com_x", "com_y", "com_z", "vel_x", "vel_y", "vel_z", "volume", "kinetic_energy", "total_energy", "min_y"};

struct CsvRow {
  int frame = 0;        // 0 is the initial state
  double time_s = 0.0;  // s
  std::size_t body = 0;
  // m, m/s, m³, J, J, m: centre of mass, its velocity, volume, kinetic and total energy, lowest vertex height
  std::array<double, kCsvBodyColumns.size()> values{};
};

// Body `body`'s row of frame `frame` at time `time_s`, from the world's current state.
CsvRow csv_row(int frame, double time_s, const sim::World& world, std::size_t body);

}  // namespace output
