// `softbody info SCENE [--set ...]`: mesh statistics, lumped masses, the fastest modes and, per
// integrator, the estimated stable dt and the steps per frame it implies.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "app/commands.hpp"
#include "app/prepared_run.hpp"
#include "scene/scene_json.hpp"
#include "sim/contact/body_collision.hpp"
#include "sim/contact/smooth_collider.hpp"
#include "sim/contact/smooth_contact.hpp"
#include "sim/integrators/coarse_space.hpp"
#include "sim/integrators/vertex_block_descent.hpp"
#include "sim/step/breathing_mode.hpp"
#include "sim/step/impact_duration.hpp"
#include "sim/step/stability.hpp"

namespace app {
namespace {

void print_body(std::size_t index, const sim::Body& body, const sim::BodyStats& s, const sim::ModeBounds& b,
                const sim::BreathingMode& breathing) {
  std::printf("body %zu: %d vertices, %d springs, %d faces; valence %d..%d; edges %.4g..%.4g m; rest volume %.4g m^3\n",
              index, s.vertices, s.edges, s.faces, s.valence_min, s.valence_max, s.edge_min_m, s.edge_max_m,
              s.rest_volume_m3);
  std::printf("  lumped vertex masses %.4g..%.4g kg (total %.4g kg); k = %.4g N/m, c = %.4g N s/m, nRT = %.4g J\n",
              s.mass_min_kg, s.mass_max_kg, body.masses.total_kg, body.params.stiffness_N_per_m,
              body.params.damping_N_s_per_m, body.params.pressure_J);
  if (!body.topology.bending_links.empty()) {
    std::printf("  %zu bending links (one across each edge); k_b = %.4g N/m, c_b = %.4g N s/m\n",
                body.topology.bending_links.size(), body.params.bending_N_per_m, body.params.bending_damping_N_s_per_m);
  }
  std::printf("  lambda_max(M^-1 K/k) = %.4g 1/kg (%d power iterations, a fixed count; Gershgorin bound %.4g)\n",
              b.lambda_max_per_kg, sim::kPowerIterations, b.lambda_gershgorin_per_kg);
  std::printf("  omega_max = %.4g rad/s (springs %.4g, gas %.4g", b.omega_max(), std::sqrt(b.omega2_springs),
              std::sqrt(b.omega2_gas));
  if (b.omega2_contact > 0.0) std::printf(", smooth floor contact %.4g", std::sqrt(b.omega2_contact));
  std::printf("), fastest-mode damping rate %.4g 1/s\n", b.damping_rate);
  if (breathing.omega > 0.0) {
    std::printf("  breathing mode (the whole body swelling) %.4g rad/s, period %.3g s, damping ratio %.3g\n",
                breathing.omega, 2.0 * std::numbers::pi / breathing.omega, breathing.damping_ratio);
  }
}

// What one step costs per vertex, one thread, a body resting on the floor (docs/perf_step.csv, icosphere:3;
// bench/run_performance.sh): the explicit methods' force evaluations per step set it. 0: not estimated here (xpbd
// and vbd print their own cost lines).
double step_ns_per_vertex(sim::IntegratorKind integrator) {
  switch (integrator) {
    case sim::IntegratorKind::Euler: return 26.0;
    case sim::IntegratorKind::Symplectic: return 26.0;
    case sim::IntegratorKind::Verlet: return 35.0;
    case sim::IntegratorKind::Rk4: return 109.0;
    case sim::IntegratorKind::Rk45: return 166.0;  // per accepted step at the auto dt; rejected steps add to it
    default: return 0.0;
  }
}

// "about X s", the wall time per simulated second of `steps_per_s` steps on `vertices` vertices.
std::string expected_cost(sim::IntegratorKind integrator, double steps_per_s, std::size_t vertices) {
  const double ns = step_ns_per_vertex(integrator);
  if (ns == 0.0) return "not estimated (solver iterations vary)";
  char text[64];
  std::snprintf(text, sizeof text, "about %.3g s", steps_per_s * static_cast<double>(vertices) * ns * 1e-9);
  return text;
}

void print_integrator(sim::IntegratorKind integrator, double dt, double frame_interval_s, std::size_t vertices) {
  const std::string text = sim::to_string(integrator);
  const char* name = text.c_str();
  if (dt == 0.0) {
    std::printf("  %-10s  unstable at every dt (forward Euler needs dampers)\n", name);
  } else if (dt == sim::StabilityEstimate::kUnlimited) {
    const bool every_force_implicit = integrator == sim::IntegratorKind::Vbd;
    std::printf("  %-10s  no limit (%s)\n", name,
                every_force_implicit ? "every force implicit" : "springs implicit, no gas term");
  } else {
    const double steps = std::ceil(frame_interval_s / (sim::kAutoDtSafety * dt));
    std::printf("  %-10s  %-12.4g %-12.4g %-22.0f %s\n", name, dt, sim::kAutoDtSafety * dt, steps,
                expected_cost(integrator, steps / frame_interval_s, vertices).c_str());
  }
}

// What one xpbd substep costs per vertex, one thread (predict with gravity, the gas and, in the carried form that
// auto picks, the constraints' carried forces; the edge pass, the velocities, the floor) [ns of CPU time]: about
// 100 on the bounce at icosphere:3 and :5 (measurements: docs/notes/2026-12-05-header-derivations.md).
constexpr double kXpbdSubstepNsPerVertex = 105.0;

// xpbd's line: the substeps per frame `substeps: auto` picks, and the wall time per simulated second they cost.
void print_xpbd(const sim::Model& model, const sim::StabilityEstimate& estimate, double frame_interval_s,
                std::size_t vertices) {
  const double dt = estimate.stable_dt(sim::IntegratorKind::Xpbd);
  const int substeps = sim::auto_substeps(sim::IntegratorKind::Xpbd, model, estimate, frame_interval_s);
  const double substeps_per_s = substeps / frame_interval_s;
  const double cost = substeps_per_s * static_cast<double>(vertices) * kXpbdSubstepNsPerVertex * 1e-9;
  char per_frame[32];
  std::snprintf(per_frame, sizeof per_frame, "%d substeps", substeps);
  std::printf("  %-10s  %-12.4g %-12.4g %-22s about %.3g s (%.0f substeps/s x %zu vertices x %.0f ns)\n", "xpbd", dt,
              frame_interval_s / substeps, per_frame, cost, substeps_per_s, vertices, kXpbdSubstepNsPerVertex);
}

// What one vbd sweep costs per vertex, one thread, the affine correction included [ns of CPU time]: 155 in flight on
// scenes/bounce_smooth.json's ball at icosphere:3 with the lanes (bench_vbd_sweep; 162 at icosphere:5; without the
// lanes 218 and 229: docs/notes/2026-12-05-vbd-lanes.md).
constexpr double kVbdSweepNsPerVertex = 155.0;

// The ω [1/s] of the stiffest smooth contact (floor, collider or between bodies) of `model`; 0 for none.
double stiffest_smooth_contact(const sim::Model& model) {
  double omega2 = 0.0;
  if (model.body_contact.contact == sim::BodyContactModel::Smooth && sim::searches_body_contact(model.bodies)) {
    omega2 = sim::resolve_smooth_response(model.body_contact.smooth, model.body_contact.material).omega2;
  }
  if (model.floor && model.floor->contact == sim::FloorContact::Smooth) {
    omega2 = sim::resolve_smooth_floor(*model.floor).omega2;
  }
  for (const sim::Collider& collider : model.colliders) {
    if (collider.contact == sim::FloorContact::Smooth) {
      omega2 = std::max(omega2, sim::resolve_smooth_collider(collider).omega2);
    }
  }
  return std::sqrt(omega2);
}

// vbd's coarse level per body (solver.coarse_space, or "auto" by the body's size) and what it cost on the bounce
// with 128 cells: 1.05x the run without at icosphere:5, 1.02x at :6, 1.27x at :4
// (docs/notes/2026-12-05-vbd-coarse-linear.md).
void print_vbd_coarse_level(const sim::Model& model) {
  const sim::Solver& solver = model.solver;
  std::string cells;
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const int count =
        solver.coarse_space_auto ? sim::auto_coarse_cells(model.bodies[b].vertex_count) : solver.coarse_space;
    if (count > 0) {
      cells += (cells.empty() ? "" : ", ") + std::to_string(count) + " cells for body " + std::to_string(b) + " (" +
               std::to_string(model.bodies[b].vertex_count) + " vertices)";
    }
  }
  if (cells.empty()) {
    cells = "none";
  } else {
    cells +=
        "; not in the cost above (on the bounce it took 1.05x at 10,242 vertices, 1.02x at 40,962, 1.27x at 2,562)";
  }
  std::string rule;
  if (solver.coarse_space_auto) {
    rule = " (coarse_space auto: " + std::to_string(sim::kAutoCoarseCells) + " cells for bodies of at least " +
           std::to_string(sim::kAutoCoarseFromVertices) + " vertices)";
  }
  std::printf("  vbd's coarse level: %s%s\n", cells.c_str(), rule.c_str());
}

// The span of impact that vbd's line prices, a round figure: the ball of scenes/bounce_smooth.json is within 1 cm of
// the floor for 0.175 s in its first impact [s].
constexpr double kImpactSpan = 0.1;

// A line per body whose lightly damped breathing mode vbd's steps of h damp at least sim::kDampedTooFast times faster
// than the model does (BDF2's numerical damping, sim::damped_out_by_bdf2), and where that holds for every body, that
// vbd's run starts at its full step (VertexBlockDescent::step).
void print_vbd_breathing(const std::vector<sim::BreathingMode>& breathing, double h) {
  bool every_one = !breathing.empty();  // whether every body's breathing is damped out
  for (std::size_t b = 0; b < breathing.size(); ++b) {
    const sim::BreathingMode& mode = breathing[b];
    if (!sim::damped_out_by_bdf2(mode, h)) {
      every_one = false;
      continue;
    }
    const double numerical = sim::bdf2_damping_ratio(mode.omega * h);
    std::printf(
        "  vbd's steps of %.3g s damp body %zu's breathing at a ratio of %.2g (BDF2 at omega h = %.2g), the "
        "model at %.2g: it fades within about %.2g s",
        h, b, numerical, mode.omega * h, mode.damping_ratio, 1.0 / (numerical * mode.omega));
    if (mode.damping_ratio > 0.0) {
      std::printf(" where the model keeps it for about %.2g s", 1.0 / (mode.damping_ratio * mode.omega));
    } else {
      std::printf(" where the model keeps it undamped");
    }
    std::printf("; to follow it take rk4 or rk45\n");
  }
  if (every_one) {
    std::printf(
        "  so at these steps vbd starts at its full step (small first steps would follow swings it then damps out)\n");
  }
}

// The body with gas whose impact lasts longest (sim::gas_impact_duration) and that duration [s]; 0 where no body has
// gas (the springs alone then decide).
std::pair<std::size_t, double> longest_gas_impact(const sim::Model& model) {
  std::pair<std::size_t, double> longest{0, 0.0};
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const double duration = sim::gas_impact_duration(model.bodies[b]);
    if (duration > longest.second) longest = {b, duration};
  }
  return longest;
}

// vbd's line: the steps per frame `substeps: auto` picks and what they cost in flight; around impacts on a smooth
// contact vbd takes smaller steps of its own, priced per kImpactSpan of impact (how long the impacts last depends on
// the motion) and, for a body with gas, per impact of its estimated duration. Then its coarse level, and the breathing
// modes its steps would damp out.
void print_vbd(const sim::Model& model, const sim::StabilityEstimate& estimate, double frame_interval_s,
               std::size_t vertices, const std::vector<sim::BreathingMode>& breathing) {
  const int steps = sim::auto_substeps(sim::IntegratorKind::Vbd, model, estimate, frame_interval_s);
  const double dt = frame_interval_s / steps;  // its step in flight [s]
  // Its sweeps per step: solver.iterations, or with "converge" or "auto" a range (each step sweeps until it barely
  // moves).
  const bool until_converged = model.solver.sweep_control != sim::SweepControl::Count;
  const bool automatic = model.solver.sweep_control == sim::SweepControl::Auto;
  const int least = until_converged ? sim::VertexBlockDescent::kLeastConvergeSweeps : model.solver.iterations;
  const int most = until_converged ? sim::VertexBlockDescent::kMostConvergeSweeps : model.solver.iterations;
  // CPU s of `steps_per_s` steps per simulated second, each `sweeps` sweeps over the vertices.
  const auto cost_of = [&](double steps_per_s, int sweeps) {
    return steps_per_s * sweeps * static_cast<double>(vertices) * kVbdSweepNsPerVertex * 1e-9;
  };
  // "0.05 s" for a count, "0.05 to 0.8 s" for converge's range.
  const auto costs_of = [&](double steps_per_s) {
    char text[48];
    if (least == most) {
      std::snprintf(text, sizeof text, "%.3g s", cost_of(steps_per_s, least));
    } else {
      std::snprintf(text, sizeof text, "%.3g to %.3g s", cost_of(steps_per_s, least), cost_of(steps_per_s, most));
    }
    return std::string(text);
  };
  char per_frame[32], limit[32] = "no limit", sweeps[48];
  std::snprintf(per_frame, sizeof per_frame, "%d step%s", steps, steps == 1 ? "" : "s");
  if (least == most) {
    std::snprintf(sweeps, sizeof sweeps, "%d sweeps", least);
  } else {
    std::snprintf(sweeps, sizeof sweeps, "%d to %d sweeps (%s)", least, most,
                  sim::to_string(model.solver.sweep_control).c_str());
  }
  // A floor whose contact is a projection after the step needs its travel limit; the smooth one is in the energy.
  if (model.floor && model.floor->contact != sim::FloorContact::Smooth) {
    std::snprintf(limit, sizeof limit, "%.4g", estimate.travel_dt_s);
  }
  std::printf("  %-10s  %-12s %-12.4g %-22s about %s in flight (%.0f steps/s x %s x %zu vertices x %.0f ns)", "vbd",
              limit, dt, per_frame, costs_of(1.0 / dt).c_str(), 1.0 / dt, sweeps, vertices, kVbdSweepNsPerVertex);
  if (const double omega = stiffest_smooth_contact(model); omega > 0.0) {
    const double impact_h = std::ldexp(dt, -sim::vbd_impact_level(dt, omega, sim::vbd_impact_phase(model.solver)));
    std::printf("; impacts take steps of %.2g ms while they last, about %s per %.1f s of impact", 1e3 * impact_h,
                costs_of(kImpactSpan / impact_h).c_str(), kImpactSpan);
    if (const auto [body, duration] = longest_gas_impact(model); duration > 0.0) {
      std::printf("; body %zu's impacts last about %.2g s (its gas: pi sqrt(m / (2 pi R P))), about %s each", body,
                  duration, costs_of(duration / impact_h).c_str());
    }
  }
  std::printf("\n");
  if (automatic) {
    // Its impacts' steps, where solver.impact_phase does not set them: "auto"'s own (sim::vbd_impact_phase).
    char impacts[160] = "";
    if (!model.solver.impact_phase) {
      std::snprintf(
          impacts, sizeof impacts,
          "its impacts' steps keep omega h <= %.3g (solver.impact_phase is not given: %.3g without \"auto\"), "
          "and ",
          sim::vbd_impact_phase(model.solver), sim::kVbdImpactPhase);
    }
    std::printf(
        "  vbd holds its own error (\"iterations\": \"auto\"): %sits steps shorten further wherever BDF2's local "
        "error in the gas's volume would exceed %.3g %% of V per second, so these are its least costs\n",
        impacts, 100.0 * sim::VertexBlockDescent::kVolumeErrorRate);
  }
  print_vbd_coarse_level(model);
  print_vbd_breathing(breathing, dt);
}

struct InfoOptions {
  SceneOptions scene;
  bool plan = false;
};

int run_info(const InfoOptions& options) {
  if (options.plan) {  // for scripts (scripts/slurm-render): no world is built
    const scene::Scene scene = scene::load_scene(options.scene.scene_file, options.scene.overrides);
    std::printf("last_frame %d\nfps %d\nname %s\n",
                frames::plan_frames(scene.duration_s, scene.fps, scene.solver.dt_s, scene.source.string()).frame_count,
                scene.fps, scene.name.c_str());
    return 0;
  }
  PreparedRun run = prepare_run(options.scene);
  const sim::StabilityEstimate estimate = sim::estimate_stability(run.world.model, run.world.state);
  const auto& bodies = run.world.model.bodies;
  std::vector<sim::BreathingMode> breathing;  // per body
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const auto x = run.world.model.of(bodies[b], run.world.state.x);
    breathing.push_back(sim::breathing_mode(bodies[b], x));
    print_body(b, bodies[b], sim::body_stats(bodies[b], x), estimate.bodies[b], breathing.back());
    if (const sim::Skin* skin = run.world.model.skin_of(static_cast<int>(b))) {
      std::printf("  simulated on a proxy; render and export show its detailed mesh: %zu vertices, %zu faces\n",
                  skin->vertex_count(), skin->triangles.size());
    }
  }
  std::printf("estimated stable dt (limiting body %d; auto uses %.2f x it; frame interval 1/%d s):\n",
              estimate.limiting_body, sim::kAutoDtSafety, run.scene.fps);
  if (estimate.travel_dt_s != sim::StabilityEstimate::kUnlimited) {
    std::printf("  (includes the floor-contact travel limit: dt <= %.4g s, a tenth of the shortest edge per step)\n",
                estimate.travel_dt_s);
  }
  std::printf("  %-10s  %-12s %-12s %-22s %s\n", "integrator", "stable dt/s", "auto dt/s", "steps/frame at auto dt",
              "expected wall time per simulated second (one thread)");
  for (const sim::IntegratorInfo& integrator : sim::kIntegrators) {
    if (integrator.kind == sim::IntegratorKind::Xpbd) {
      print_xpbd(run.world.model, estimate, run.clock.frame_interval_s, run.world.state.x.size());
    } else if (integrator.kind == sim::IntegratorKind::Vbd) {
      print_vbd(run.world.model, estimate, run.clock.frame_interval_s, run.world.state.x.size(), breathing);
    } else {
      print_integrator(integrator.kind, estimate.stable_dt(integrator.kind), run.clock.frame_interval_s,
                       run.world.state.x.size());
    }
  }
  std::printf("this scene: %s, dt = %.4g s (%d %s per frame)\n",
              sim::to_string(run.world.model.solver.integrator).c_str(), run.clock.dt_s, run.clock.steps_per_frame,
              run.clock.steps_per_frame == 1 ? "step" : "steps");
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
