// `softbody info SCENE [--set ...]`: mesh statistics, lumped masses, the fastest modes and, per
// integrator, the estimated stable dt and the steps per frame it implies.
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "app/commands.hpp"
#include "app/prepared_run.hpp"
#include "scene/scene_json.hpp"
#include "sim/stability.hpp"

namespace app {
namespace {

void print_body(std::size_t index, const sim::Body& body, const sim::BodyStats& s, const sim::ModeBounds& b) {
  std::printf("body %zu: %d vertices, %d springs, %d faces; valence %d..%d; edges %.4g..%.4g m; rest volume %.4g m^3\n",
              index, s.vertices, s.edges, s.faces, s.valence_min, s.valence_max, s.edge_min_m, s.edge_max_m,
              s.rest_volume_m3);
  std::printf("  lumped vertex masses %.4g..%.4g kg (total %.4g kg); k = %.4g N/m, c = %.4g N s/m, nRT = %.4g J\n",
              s.mass_min_kg, s.mass_max_kg, body.masses.total_kg, body.params.stiffness_N_per_m,
              body.params.damping_N_s_per_m, body.params.pressure_J);
  std::printf("  lambda_max(M^-1 K/k) = %.4g 1/kg (power iterations; Gershgorin bound %.4g)\n", b.lambda_max_per_kg,
              b.lambda_gershgorin_per_kg);
  std::printf("  omega_max = %.4g rad/s (springs %.4g, gas %.4g), fastest-mode damping rate %.4g 1/s\n",
              b.omega_max(), std::sqrt(b.omega2_springs), std::sqrt(b.omega2_gas), b.damping_rate);
}

void print_integrator(sim::IntegratorKind integrator, double dt, double frame_interval_s) {
  const std::string text = sim::to_string(integrator);
  const char* name = text.c_str();
  if (dt == 0.0) {
    std::printf("  %-10s  unstable at every dt (forward Euler needs dampers)\n", name);
  } else if (dt == sim::StabilityEstimate::kUnlimited) {
    std::printf("  %-10s  no limit (springs implicit, no gas term)\n", name);
  } else {
    const double steps = std::ceil(frame_interval_s / (sim::kAutoDtSafety * dt));
    std::printf("  %-10s  %-12.4g %-12.4g %.0f\n", name, dt, sim::kAutoDtSafety * dt, steps);
  }
}

struct InfoOptions {
  SceneOptions scene;
  bool plan = false;
};

int run_info(const InfoOptions& options) {
  if (options.plan) {  // for scripts (scripts/slurm-render): no world is built
    const scene::Scene scene = scene::load_scene(options.scene.scene_file, options.scene.overrides);
    std::printf("last_frame %d\nfps %d\nname %s\n",
                frames::plan_frames(scene.duration_s, scene.fps, scene.solver.dt_s, scene.source.string()).frame_count, scene.fps,
                scene.name.c_str());
    return 0;
  }
  PreparedRun run = prepare_run(options.scene);
  const sim::StabilityEstimate estimate = sim::estimate_stability(run.world.model, run.world.state);
  const auto& bodies = run.world.model.bodies;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    print_body(b, bodies[b], sim::body_stats(bodies[b], run.world.model.of(bodies[b], run.world.state.x)), estimate.bodies[b]);
  }
  std::printf("estimated stable dt (limiting body %d; auto uses %.2f x it; frame interval 1/%d s):\n",
              estimate.limiting_body, sim::kAutoDtSafety, run.scene.fps);
  if (estimate.travel_dt_s != sim::StabilityEstimate::kUnlimited) {
    std::printf("  (includes the floor-contact travel limit: dt <= %.4g s, a tenth of the shortest edge per step)\n",
                estimate.travel_dt_s);
  }
  std::printf("  %-10s  %-12s %-12s %s\n", "integrator", "stable dt/s", "auto dt/s", "steps/frame at auto dt");
  for (const sim::IntegratorInfo& integrator : sim::kIntegrators) {
    print_integrator(integrator.kind, estimate.stable_dt(integrator.kind), run.clock.frame_interval_s);
  }
  std::printf("this scene: %s, dt = %.4g s (%d steps per frame)\n", sim::to_string(run.scene.solver.integrator).c_str(),
              run.clock.dt_s, run.clock.steps_per_frame);
  return 0;
}

}  // namespace

Action register_info(CLI::App& parent) {
  auto options = std::make_shared<InfoOptions>();
  CLI::App* command = parent.add_subcommand(
      "info", "Print mesh statistics, lumped masses, the fastest modes and each integrator's stable dt");
  add_scene_options(*command, options->scene);
  command->add_flag("--plan", options->plan,
                    "Print only the run's frames, for scripts: 'last_frame N' (frame 0 is the initial state), "
                    "'fps F', 'name NAME'");
  return [options] { return run_info(*options); };
}

}  // namespace app
