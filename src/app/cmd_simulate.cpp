// `softbody simulate SCENE [--csv FILE] [--set ...]`: run without rendering, write the CSV.
#include <cstdio>
#include <iostream>
#include <memory>
#include <utility>

#include "app/commands.hpp"
#include "frames/frame_clock.hpp"
#include "frames/frame_loop.hpp"
#include "output/csv_sink.hpp"
#include "scene/scene_json.hpp"
#include "sim/world.hpp"

namespace app {
namespace {

struct SimulateOptions {
  SceneOptions scene;
  std::string csv_file;
};

void print_notes(const std::vector<std::string>& notes) {
  for (const std::string& note : notes) std::cerr << "note: " << note << "\n";
}

int run_simulate(const SimulateOptions& options) {
  const scene::Scene scene = scene::load_scene(options.scene.scene_file, options.scene.overrides);
  const frames::FrameClock clock = frames::plan_frames(scene.duration_s, scene.fps, scene.solver.dt_s);
  std::vector<std::string> notes;
  const bool adaptive = scene.solver.integrator == scene::Integrator::Rk45;  // chooses its own steps
  if (!clock.dt_note.empty() && !adaptive) notes.push_back(clock.dt_note);
  sim::World world = sim::build_world(scene, notes);
  print_notes(notes);

  const std::filesystem::path csv = options.csv_file.empty() ? scene.output.dir / "simulation.csv"
                                                             : std::filesystem::path(options.csv_file);
  output::CsvSink csv_sink(csv);
  frames::FrameSink* sinks[] = {&csv_sink};
  const frames::RunStats stats = frames::run_frames(world, clock, sinks);

  std::size_t vertices = std::as_const(world).state().x.size();
  char steps[160];
  if (adaptive) {
    std::snprintf(steps, sizeof steps, "%lld accepted + %lld rejected steps (rk45, tolerance %.3g)", stats.steps,
                  stats.rejected_steps, scene.solver.tolerance);
  } else {
    std::snprintf(steps, sizeof steps, "%lld steps of %.4g s (%s)", stats.steps, clock.dt_s,
                  scene::to_string(scene.solver.integrator).c_str());
  }
  std::printf("%s: %d frames, %s, %zu vertices, in %.3f s: %.0f steps/s; wrote %s\n", scene.name.c_str(),
              stats.frames, steps, vertices, stats.wall_s,
              static_cast<double>(stats.steps) / std::max(stats.step_wall_s, 1e-12), csv.string().c_str());
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
