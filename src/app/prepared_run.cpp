// Shared start and summary of the scene commands.
#include "app/prepared_run.hpp"

#include <algorithm>
#include <cstdio>
#include <iostream>

#include "scene/scene_json.hpp"

namespace app {

PreparedRun prepare_run(const SceneOptions& options) {
  scene::Scene scene = scene::load_scene(options.scene_file, options.overrides);
  const frames::FrameClock clock = frames::plan_frames(scene.duration_s, scene.fps, scene.solver.dt_s);
  std::vector<std::string> notes;
  const bool adaptive = scene.solver.integrator == scene::Integrator::Rk45;  // chooses its own steps
  if (!clock.dt_note.empty() && !adaptive) notes.push_back(clock.dt_note);
  sim::World world = sim::build_world(scene, notes);
  for (const std::string& note : notes) std::cerr << "note: " << note << "\n";
  return PreparedRun{std::move(scene), clock, std::move(world)};
}

void print_run_summary(const PreparedRun& run, const frames::RunStats& stats, const std::string& what_was_written) {
  const scene::Solver& solver = run.scene.solver;
  char steps[160];
  if (solver.integrator == scene::Integrator::Rk45) {
    std::snprintf(steps, sizeof steps, "%lld accepted + %lld rejected steps (rk45, tolerance %.3g)", stats.steps,
                  stats.rejected_steps, solver.tolerance);
  } else {
    std::snprintf(steps, sizeof steps, "%lld steps of %.4g s (%s)", stats.steps, run.clock.dt_s,
                  scene::to_string(solver.integrator).c_str());
  }
  std::printf("%s: %d frames, %s, %zu vertices, in %.3f s: %.0f steps/s; %s\n", run.scene.name.c_str(), stats.frames,
              steps, run.world.state().x.size(), stats.wall_s,
              static_cast<double>(stats.steps) / std::max(stats.step_wall_s, 1e-12), what_was_written.c_str());
}

}  // namespace app
