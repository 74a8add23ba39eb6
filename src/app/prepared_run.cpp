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
  if (!clock.dt_note.empty()) notes.push_back(clock.dt_note);
  sim::World world = sim::build_world(scene, notes);
  for (const std::string& note : notes) std::cerr << "note: " << note << "\n";
  return PreparedRun{std::move(scene), clock, std::move(world)};
}

void print_run_summary(const PreparedRun& run, const frames::RunStats& stats, const std::string& what_was_written) {
  std::printf("%s: %d frames, %lld steps of %.4g s (%s), %zu vertices, in %.3f s: %.0f steps/s; %s\n",
              run.scene.name.c_str(), stats.frames, stats.steps, run.clock.dt_s,
              scene::to_string(run.scene.solver.integrator).c_str(), run.world.state().x.size(), stats.wall_s,
              static_cast<double>(stats.steps) / std::max(stats.step_wall_s, 1e-12), what_was_written.c_str());
}

}  // namespace app
