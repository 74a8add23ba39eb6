// `softbody bench accuracy SCENE [--out DIR] ...`: the integrators' run time against their error.
#include <cstdio>
#include <iostream>
#include <memory>

#include "analysis/accuracy.hpp"
#include "analysis/work_precision.hpp"
#include "app/commands.hpp"
#include "core/errors.hpp"
#include "scene/scene_json.hpp"

namespace app {
namespace {

struct AccuracyCommand {
  SceneOptions scene;
  std::string out_dir = "out/bench";
  std::vector<std::string> integrators;
  std::string reference_integrator = "rk45";
  analysis::AccuracyOptions options;
};

std::vector<sim::IntegratorKind> parse_integrators(const std::string& option, const std::vector<std::string>& names) {
  std::vector<sim::IntegratorKind> chosen;
  for (const std::string& name : names) {
    const std::optional<sim::IntegratorKind> integrator = sim::integrator_named(name);
    if (!integrator) {
      std::string expected;
      for (const sim::IntegratorInfo& known : sim::kIntegrators)
        expected += (expected.empty() ? "" : ", ") + std::string(known.name);
      throw softbody::InputError(option + ": unknown integrator '" + name + "' (expected one of " + expected + ")");
    }
    chosen.push_back(*integrator);
  }
  return chosen;
}

int run_accuracy(AccuracyCommand& command) {
  const scene::Scene scene = scene::load_scene(command.scene.scene_file, command.scene.overrides);
  if (!command.integrators.empty())
    command.options.integrators = parse_integrators("--integrators", command.integrators);
  command.options.reference_integrator =
      parse_integrators("--reference-integrator", {command.reference_integrator}).front();
  const analysis::AccuracyResult result = analysis::run_accuracy_benchmark(
      scene, command.options, [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); });
  const auto written = analysis::write_work_precision(result, command.out_dir);
  std::cout << analysis::accuracy_summary(result);
  for (const auto& path : written) std::cout << "wrote " << path.string() << "\n";
  return 0;
}

}  // namespace

Action add_accuracy_options(CLI::App& command) {
  auto state = std::make_shared<AccuracyCommand>();
  add_scene_options(command, state->scene);
  analysis::AccuracyOptions& o = state->options;
  command.add_option("--out", state->out_dir, "Folder for work_precision_<scene>.{csv,txt,gp,png}")
      ->type_name("DIR")
      ->capture_default_str();
  command.add_option("--duration", o.duration_s, "Simulated seconds (default: the scene's duration)")
      ->type_name("S")
      ->check(CLI::PositiveNumber);
  command
      .add_option("--reference-dt", o.reference_dt_s,
                  "Step of the fixed-step 5th-order reference (default: solver.dt / 10)")
      ->type_name("S")
      ->check(CLI::PositiveNumber);
  command
      .add_option("--reference-integrator", state->reference_integrator,
                  "Method of the fixed-step reference (rk45: its 5th-order formula without error control)")
      ->type_name("NAME")
      ->capture_default_str();
  command
      .add_option("--floor-factor", o.floor_factor,
                  "Runs with an error below this times the reference's uncertainty are not plotted")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  command.add_option("--budget", o.run_budget_s, "Stop refining an integrator once one run takes longer than this")
      ->type_name("S")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command.add_option("--coarsest", o.coarsest_factor, "Fixed-step sweeps start at this times solver.dt")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command.add_option("--refinement", o.refinement, "Each fixed-step run's dt is the previous one's divided by this")
      ->check(CLI::Range(1.0001, 1000.0))
      ->capture_default_str();
  command.add_option("--max-runs", o.max_runs, "Most runs per integrator")
      ->check(CLI::Range(1, 40))
      ->capture_default_str();
  command.add_option("--integrators", state->integrators, "Only these (default: all of them)")
      ->delimiter(',')
      ->type_name("NAME,...");
  command.footer(
      "For each integrator: a sweep of steps from --coarsest x solver.dt, divided by --refinement each run (rk45:\n"
      "tolerances 1e-2, 1e-3, ...), until a run takes longer than --budget, reaches the reference's own uncertainty,\n"
      "or --max-runs. Error = RMS vertex position error against the reference over every frame after frame 0\n"
      "(final_error: the last frame only). The reference is Dormand-Prince's 5th-order formula at a fixed\n"
      "step (--reference-integrator); its distance to the same at twice the step is its uncertainty.\n"
      "CSV columns: " +
      std::string(analysis::kAccuracyCsvHeader) +
      "\n"
      "  dt: the step used (rk45: the mean accepted step); wall_s: stepping time, median of 3 for runs\n"
      "  under 0.5 s; status: ok | diverged (non-finite state) | blown_up (RMS error above the body's size)\n"
      "  | at_reference (error below --floor-factor x the reference's uncertainty: not plotted).");
  return [state] { return run_accuracy(*state); };
}

Action register_bench(CLI::App& parent) {
  CLI::App* bench = parent.add_subcommand("bench", "Benchmarks (accuracy: integrators' run time against error)");
  bench->require_subcommand(1);
  CLI::App* accuracy = bench->add_subcommand(
      "accuracy", "Run time against error of every integrator on a scene; CSV and work-precision plot");
  return add_accuracy_options(*accuracy);
}

}  // namespace app
