// bench_stress: the stability stress sweep (every integrator, ≥ 1000 runs; --quick for ctest's `stress`
// label). Writes stress.csv and stability maps; exits 1 if any run failed silently, crashed or tunnelled, or
// was stopped by the guard at a dt at or below the estimated stable dt (the estimate must be conservative).
#include <chrono>
#include <cstdio>
#include <filesystem>

#include <CLI/CLI.hpp>

#include "analysis/limits.hpp"
#include "analysis/stress.hpp"

int main(int argc, char** argv) {
  CLI::App cli("bench_stress: stability stress sweep; each run must end stable or be stopped by the guard");
  bool quick = false, maps = true, limits = false;
  int limit_steps = 20000;
  std::string out_dir = "out/stress";
  cli.add_flag("--quick", quick, "A short subset (about 200 runs, for ctest -L stress)");
  cli.add_option("--out", out_dir, "Output folder for stress.csv and the stability maps")->type_name("DIR");
  cli.add_flag("!--no-maps", maps, "Skip the gnuplot stability maps");
  cli.add_flag("--limits", limits, "Instead: measure each integrator's stable dt and compare it with the estimate");
  cli.add_option("--limit-steps", limit_steps, "Steps per trial of --limits (default 20000)");
  CLI11_PARSE(cli, argc, argv);

  std::filesystem::create_directories(out_dir);
  if (limits) {
    const auto rows = analysis::measure_limits(analysis::limit_bodies(), limit_steps);
    for (const auto& r : rows) {
      std::printf("%-15s %-11s %-5s %-10s estimate %.4g s, measured stable %.4g s (unstable %.4g s): ratio %.3f\n",
                  r.body.name.c_str(), r.body.mesh.c_str(), r.floor ? "floor" : "free",
                  sim::to_string(r.integrator).c_str(), r.estimate_dt_s, r.measured_dt_s, r.unstable_dt_s,
                  r.measured_dt_s > 0 ? r.estimate_dt_s / r.measured_dt_s : 0.0);
    }
    analysis::write_limits_csv(rows, std::filesystem::path(out_dir) / "stability_limits.csv");
    return 0;
  }
  const auto start = std::chrono::steady_clock::now();
  std::vector<analysis::StressResult> results;
  int counts[3] = {0, 0, 0}, below_estimate_guarded = 0;
  const std::vector<analysis::StressCase> cases = analysis::stress_cases(quick);
  for (const analysis::StressCase& c : cases) {
    results.push_back(analysis::run_stress_case(c));
    const analysis::StressResult& r = results.back();
    ++counts[static_cast<int>(r.outcome)];
    if (r.guarded_within_estimate()) {
      ++below_estimate_guarded;
      std::fprintf(stderr, "GUARDED AT OR BELOW THE ESTIMATE %s %s %s dt=%.3g (estimate %.3g): %s\n", c.group.c_str(),
                   c.shape.c_str(), sim::to_string(c.integrator).c_str(), r.dt_s, r.estimate_dt_s, r.message.c_str());
    }
    if (r.outcome == analysis::Outcome::Failed) {
      std::fprintf(stderr, "FAILED %s %s %s dt=%.3g: %s\n", c.group.c_str(), c.shape.c_str(),
                   sim::to_string(c.integrator).c_str(), r.dt_s, r.message.c_str());
    }
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::filesystem::path csv = std::filesystem::path(out_dir) / "stress.csv";
  analysis::write_stress_csv(results, csv);
  std::printf(
      "%zu runs in %.1f s: %d stable, %d stopped by the guard, %d failed; stopped by the guard at dt <= "
      "estimate: %d\n",
      results.size(), wall, counts[0], counts[1], counts[2], below_estimate_guarded);
  std::printf("wrote %s\n", csv.c_str());
  if (maps) {
    for (const auto& png : analysis::write_stability_maps(results, out_dir)) std::printf("wrote %s\n", png.c_str());
  }
  return counts[2] == 0 && below_estimate_guarded == 0 ? 0 : 1;
}
