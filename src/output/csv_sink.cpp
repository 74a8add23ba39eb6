// CSV rows from per-body diagnostics.
#include "output/csv_sink.hpp"

#include <cstdio>

#include "output/atomic_file.hpp"
#include "sim/diagnostics.hpp"

namespace output {

CsvSink::CsvSink(std::filesystem::path path) : path_(std::move(path)) { text_ = std::string(kCsvHeader) + "\n"; }

void CsvSink::on_frame(int index, double time_s, const sim::World& world) {
  for (std::size_t b = 0; b < world.model.bodies.size(); ++b) {
    const sim::BodyDiagnostics d = sim::diagnose(world.model, world.state, b);
    char row[512];
    // %.17g round-trips doubles exactly.
    std::snprintf(row, sizeof row, "%d,%.17g,%zu,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", index,
                  time_s, b, d.com_m.x(), d.com_m.y(), d.com_m.z(), d.com_velocity_m_per_s.x(),
                  d.com_velocity_m_per_s.y(), d.com_velocity_m_per_s.z(), d.volume_m3, d.kinetic_J, d.total_J(),
                  d.min_y_m);
    text_ += row;
  }
}

void CsvSink::finish(bool /*complete*/) { write_file_atomically(path_, text_); }

}  // namespace output
