// What every scene command does first: read the scene, plan the frames, build the world, print notes.
#pragma once

#include <cstdio>
#include <string>

#include "app/commands.hpp"
#include "frames/frame_clock.hpp"
#include "frames/frame_loop.hpp"
#include "scene/scene.hpp"
#include "sim/step/world.hpp"

namespace app {

struct PreparedRun {
  scene::Scene scene;
  frames::FrameClock clock;
  sim::World world;
};

// Loads and validates the scene (with --set), plans the frame clock, builds the world, and prints
// every note (rounded dt, fixed meshes) to stderr. Throws softbody::InputError on bad input, and
// frames::Interrupted (nothing written) when a stop was requested, at the end of the setup phase in progress.
// `threads_when_auto`: the force threads when the scene leaves solver.threads at 0 (0: one per core);
// render passes 1, because there the second core renders while the simulation runs beside it.
PreparedRun prepare_run(const SceneOptions& options, int threads_when_auto = 0);
// The same from a scene already loaded (scene::load_scene): the Python module's Simulation.
PreparedRun prepare_run(scene::Scene scene, int threads_when_auto = 0);

// One summary line on stdout: frames, steps, dt, integrator, vertices, wall time, steps per second,
// then `what_was_written`.
// To standard output, or `out` (standard error when the CSV goes to standard output).
void print_run_summary(const PreparedRun& run, const frames::RunStats& stats, const std::string& what_was_written,
                       std::FILE* out = stdout);

}  // namespace app
