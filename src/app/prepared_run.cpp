// Shared start and summary of the scene commands.
#include "app/prepared_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

#include "frames/stop_request.hpp"
#include "scene/scene_json.hpp"
#include "setup/build_world.hpp"
#include "sim/integrators/vertex_block_descent.hpp"
#include "sim/step/breathing_mode.hpp"
#include "sim/step/stability.hpp"
#include "sim/step/step_plan.hpp"

namespace app {

namespace {

// With vbd's "iterations": "auto", a note per body whose lightly damped breathing vbd's steps of h damp out
// (sim::damped_out_by_bdf2): "auto" holds the volume's local error, but not a swing its steps take out from the start.
void add_vbd_auto_breathing_notes(const sim::World& world, double h, std::vector<std::string>& notes) {
  const sim::Model& model = world.model;
  if (model.solver.integrator != sim::IntegratorKind::Vbd || model.solver.sweep_control != sim::SweepControl::Auto)
    return;
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const sim::BreathingMode mode = sim::breathing_mode(model.bodies[b], model.of(model.bodies[b], world.state.x));
    if (!sim::damped_out_by_bdf2(mode, h)) continue;
    char note[320];
    std::snprintf(note, sizeof note,
                  "solver.iterations = auto: vbd's steps of %.4g s damp body %zu's breathing out (omega h = %.2g, the "
                  "model's damping ratio %.2g), so \"auto\" holds the volume's error but not that swing; to follow "
                  "it take rk4 or rk45 (softbody info)",
                  h, b, mode.omega * h, mode.damping_ratio);
    notes.emplace_back(note);
  }
}

}  // namespace

PreparedRun prepare_run(const SceneOptions& options, int threads_when_auto) {
  return prepare_run(scene::load_scene(options.scene_file, options.overrides), threads_when_auto);
}

PreparedRun prepare_run(scene::Scene scene, int threads_when_auto) {
  std::vector<std::string> notes;
  for (const std::string& note : scene.notes) notes.push_back(scene.source.string() + ": " + note);
  std::vector<int> bodies_per_scene_body;
  // SIGINT / SIGTERM during setup (a long mesh repair, remesh, ...) end it when that phase ends.
  const softbody::AfterPhase after_phase = frames::throw_if_stop_requested_after;
  sim::World world = setup::build_world(scene, notes, &bodies_per_scene_body, after_phase, threads_when_auto);
  // A split body is several bodies from here on: one scene body each, so that colours and patterns follow.
  std::vector<scene::Body> bodies;
  for (std::size_t b = 0; b < scene.bodies.size(); ++b)
    bodies.insert(bodies.end(), static_cast<std::size_t>(bodies_per_scene_body[b]), scene.bodies[b]);
  scene.bodies = std::move(bodies);
  const sim::StepPlan step =
      sim::resolve_step(world.model, world.state, 1.0 / scene.fps, scene.source.string(), after_phase);
  if (step.substeps_chosen) {
    const bool vbd = world.model.solver.integrator == sim::IntegratorKind::Vbd;
    const char* steps = vbd ? (step.substeps == 1 ? "step" : "steps") : (step.substeps == 1 ? "substep" : "substeps");
    char head[96], limit[32];
    std::snprintf(head, sizeof head, "solver.substeps = auto: %d %s per frame (h = %.4g s", step.substeps, steps,
                  step.dt_s);
    std::snprintf(limit, sizeof limit, "%.4g s", step.travel_dt_s);
    // No contact that acts after the step (no floor, collider or contact between bodies): no travel limit to name.
    const bool travel_limited = std::isfinite(step.travel_dt_s);
    std::string why;
    if (vbd) {
      why = travel_limited ? std::string("; the contact travel limit ") + limit +
                                 " applies where a contact acts after the step: a paper or friction floor, a keyframed"
                                 " collider, the impulse contact between bodies; vbd shrinks its steps itself around"
                                 " smooth impacts)"
                           : std::string("; no contact in the scene limits it)");
    } else {
      why = travel_limited
                ? std::string(": within the carried form's limit and the contact travel limit ") + limit + ")"
                : std::string(": within the carried form's limit; no contact in the scene limits it)");
    }
    notes.insert(notes.begin(), head + why);
  } else if (step.travel_substeps > 0) {
    char note[480];
    std::snprintf(note, sizeof note,
                  "solver.substeps = %d: steps of %.4g s, longer than the contact travel limit %.4g s (a tenth of the "
                  "shortest edge per step) that a contact after the step needs (a paper or friction floor, a "
                  "keyframed collider, the impulse contact between bodies): vertices can pass through or be "
                  "crushed; it takes %d, as \"auto\" would",
                  step.substeps, step.dt_s, step.travel_dt_s, step.travel_substeps);
    notes.insert(notes.begin(), note);
  } else if (step.dt_chosen) {
    const sim::IntegratorKind integrator = world.model.solver.integrator;
    char note[200];
    std::snprintf(note, sizeof note, "solver.dt = auto: %.4g s (%.2f x the estimated stable dt of %s, %.4g s)",
                  step.dt_s, sim::kAutoDtSafety, sim::to_string(integrator).c_str(), step.stable_dt_s);
    notes.insert(notes.begin(), note);
  }
  add_vbd_auto_breathing_notes(world, step.dt_s, notes);
  const frames::FrameClock clock = frames::plan_frames(scene.duration_s, scene.fps, step.dt_s, scene.source.string());
  const bool adaptive = world.adaptive();  // rk45 chooses its own steps
  if (!clock.dt_note.empty() && !adaptive && step.dt_requested()) notes.push_back(clock.dt_note);
  if (!clock.duration_note.empty()) notes.push_back(clock.duration_note);
  for (const std::string& note : notes) std::cerr << "note: " << note << "\n";
  return PreparedRun{std::move(scene), clock, std::move(world)};
}

namespace {

// vbd's statistics (sim/integrators/vertex_block_descent.hpp); nullptr for the other integrators.
const sim::VertexBlockDescent::Statistics* vbd_statistics(const PreparedRun& run) {
  const auto* vbd = dynamic_cast<const sim::VertexBlockDescent*>(run.world.workspace.integrator.get());
  return vbd ? &vbd->statistics() : nullptr;
}

}  // namespace

void print_run_summary(const PreparedRun& run, const frames::RunStats& stats, const std::string& what_was_written,
                       std::FILE* out) {
  const sim::Solver& solver = run.world.model.solver;
  const bool automatic = solver.sweep_control == sim::SweepControl::Auto;
  const bool until_still = solver.sweep_control != sim::SweepControl::Count;
  char steps[256];
  if (solver.integrator == sim::IntegratorKind::Rk45) {
    std::snprintf(steps, sizeof steps, "%lld accepted + %lld rejected steps (rk45, tolerance %.3g)", stats.steps,
                  stats.rejected_steps, solver.tolerance);
  } else if (const auto* vbd = vbd_statistics(run); vbd && (vbd->steps > stats.steps || until_still)) {
    // Its own steps (shorter at its start and around impacts, with "iterations": "auto" also where the volume's error
    // needed it) and, with "iterations": "converge" or "auto", its sweeps per step.
    char own[128] = "", sweeps[64] = "";
    if (vbd->steps > stats.steps) {
      std::snprintf(own, sizeof own, "; %lld of its own: shorter at its start%s", vbd->steps,
                    automatic ? ", around impacts and where the volume's error needed it" : " and around impacts");
    }
    if (until_still && vbd->steps > 0) {
      const double per_step = static_cast<double>(vbd->sweeps) /
                              (static_cast<double>(vbd->steps) * static_cast<double>(run.world.model.bodies.size()));
      std::snprintf(sweeps, sizeof sweeps, "; %.3g sweeps per step (%s)", per_step,
                    sim::to_string(solver.sweep_control).c_str());
    }
    std::snprintf(steps, sizeof steps, "%lld steps of %.4g s (vbd%s%s)", stats.steps, run.clock.dt_s, own, sweeps);
  } else {
    std::snprintf(steps, sizeof steps, "%lld steps of %.4g s (%s)", stats.steps, run.clock.dt_s,
                  sim::to_string(solver.integrator).c_str());
  }
  std::fprintf(out, "%s: %d frames, %s, %zu vertices, in %.3f s: %.0f steps/s; %s\n", run.scene.name.c_str(),
               stats.frames, steps, run.world.state.x.size(), stats.wall_s,
               static_cast<double>(stats.steps) / std::max(stats.step_wall_s, 1e-12), what_was_written.c_str());
}

}  // namespace app
