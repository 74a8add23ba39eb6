// `softbody simulate SCENE [--csv FILE] [--set ...]`: run without rendering, write the CSV.
#include <memory>

#include "app/commands.hpp"
#include "app/prepared_run.hpp"
#include "output/csv_sink.hpp"

namespace app {
namespace {

struct SimulateOptions {
  SceneOptions scene;
  std::string csv_file;
};

int run_simulate(const SimulateOptions& options) {
  PreparedRun run = prepare_run(options.scene);
  const std::filesystem::path csv = options.csv_file.empty() ? run.scene.output.dir / "simulation.csv"
                                                             : std::filesystem::path(options.csv_file);
  output::CsvSink csv_sink(csv);
  frames::FrameSink* sinks[] = {&csv_sink};
  const frames::RunStats stats = frames::run_frames(run.world, run.clock, sinks);
  print_run_summary(run, stats, "wrote " + csv.string());
  return 0;
}

}  // namespace

Action register_simulate(CLI::App& parent) {
  auto options = std::make_shared<SimulateOptions>();
  CLI::App* command = parent.add_subcommand(
      "simulate", "Run a scene without rendering and write one CSV row per body per frame");
  add_scene_options(*command, options->scene);
  command->add_option("--csv", options->csv_file, "CSV output file (default: <output.dir>/simulation.csv)")
      ->type_name("FILE");
  command->footer(
      "CSV columns: frame,time,body,com_x,com_y,com_z,vel_x,vel_y,vel_z,volume,kinetic_energy,total_energy,min_y\n"
      "  vel_* is the centre-of-mass velocity; total_energy = kinetic + gravitational (y relative to 0)\n"
      "  + spring + gas (-nRT ln(V/V0)). Frame 0 is the initial state.");
  return [options] { return run_simulate(*options); };
}

}  // namespace app
