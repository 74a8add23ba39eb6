// build/bench_large_steps: issue 13's "what the user waits for": the bounce at icosphere levels, every
// integrator at its automatic step, and Bullet's
// btSoftBody, each run's wall time per simulated second and its error against a converged run of our model.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bounce_run.hpp"
#include "reference_cache.hpp"
#include "setup/build_world.hpp"
#include "trajectory_error.hpp"

namespace {

using bench::BounceRecord;
using bench::BounceSetup;

struct Options {
  std::vector<int> levels{3};
  std::vector<std::string> integrators{"euler", "symplectic", "verlet", "rk4", "rk45", "xpbd", "vbd"};
  std::vector<std::string> friction_too{"symplectic"};   // also run at their automatic step on the friction floor
  std::vector<int> bullet_rates{60, 240};                // Bullet: dt = 1/rate
  std::vector<double> reference_tolerances{1e-8, 1e-7};  // rk45: the first is the reference
  double duration_s = 3.0;
  int repeats = 3;  // runs whose CPU time is below repeat_below_s are repeated: medians
  double repeat_below_s = 5.0;
  bool header = true;
  bool reference = true;        // false: no rk45 reference (level 6: over 15 CPU min), the error columns empty
  std::string reference_cache;  // a file holding the reference run (read if it holds one, else written)
};

// One CSV row's description of a run.
struct RowLabel {
  std::string program, model, contact, step;
};

std::string csv_safe(std::string text) {
  std::replace(text.begin(), text.end(), ',', ';');
  std::replace(text.begin(), text.end(), '\n', ' ');
  return text.empty() ? "ok" : text;
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// Runs `record` once, and again up to `repeats` times in all while a run takes under repeat_below_s: the
// trajectories are deterministic, so only the wall time (the median) changes. Returns the first record.
template <class Record>
BounceRecord timed(const Options& o, Record record, int& runs) {
  BounceRecord first = record();
  std::vector<double> walls{first.wall_s}, cpus{first.cpu_s};
  while (static_cast<int>(walls.size()) < o.repeats && first.cpu_s < o.repeat_below_s) {
    const BounceRecord again = record();
    walls.push_back(again.wall_s);
    cpus.push_back(again.cpu_s);
  }
  first.wall_s = median(walls);
  first.cpu_s = median(cpus);
  runs = static_cast<int>(walls.size());
  return first;
}

void print_row(int level, const Options& o, const RowLabel& label, const BounceRecord& r, int runs,
               const BounceRecord* reference) {
  bench::TrajectoryError e;
  if (reference != nullptr) e = bench::trajectory_error(r, *reference);
  const double simulated =
      bench::kBounceSampleInterval_s * static_cast<double>(std::max<std::size_t>(r.volume_m3.size(), 2) - 1);
  std::printf("%d,%.4g,%s,%s,%s,%s,%.6g,%lld,%.5g,%.5g,%d,", level, o.duration_s, label.program.c_str(),
              label.model.c_str(), label.contact.c_str(), label.step.c_str(), r.dt_s, r.steps, r.cpu_s / simulated,
              r.wall_s / simulated, runs);
  if (reference != nullptr) {
    std::printf("%.4g,%.4g,%.4g,%.4g,", e.com_max_m, e.volume_worst_pct, e.rms_end_m, e.rms_samples_m);
  } else {
    std::printf(",,,,");
  }
  std::printf(",%s\n", csv_safe(r.failure).c_str());  // newton_iterations_per_step: empty (newton was removed)
  std::fflush(stdout);
  std::fprintf(stderr, "level %d %s %s %s: %.4g CPU s, %.4g wall s per simulated s\n", level, label.program.c_str(),
               label.contact.c_str(), label.step.c_str(), r.cpu_s / simulated, r.wall_s / simulated);
}

std::string tolerance_label(double tolerance) {
  char text[32];
  std::snprintf(text, sizeof text, "tolerance %.0e", tolerance);
  return text;
}

// The reference cache of `level`: the option's path with "%d" replaced by the level (several levels, one option).
std::string cache_path(const std::string& pattern, int level) {
  const std::size_t at = pattern.find("%d");
  return at == std::string::npos ? pattern : pattern.substr(0, at) + std::to_string(level) + pattern.substr(at + 2);
}

void run_level(int level, const Options& o) {
  BounceSetup reference_setup;
  reference_setup.level = level;
  reference_setup.integrator = sim::IntegratorKind::Rk45;
  reference_setup.tolerance = o.reference_tolerances.at(0);
  const BounceRecord reference =
      o.reference ? bench::load_or_record(reference_setup, o.duration_s, cache_path(o.reference_cache, level))
                  : BounceRecord{};
  const BounceRecord* compared = o.reference ? &reference : nullptr;
  if (o.reference) {
    print_row(level, o, {"reference rk45", "ours", "smooth", tolerance_label(reference_setup.tolerance)}, reference, 1,
              nullptr);
  }
  for (std::size_t t = 1; o.reference && t < o.reference_tolerances.size(); ++t) {
    BounceSetup check = reference_setup;
    check.tolerance = o.reference_tolerances[t];
    print_row(level, o, {"reference check rk45", "ours", "smooth", tolerance_label(check.tolerance)},
              bench::record_bounce(check, o.duration_s), 1, &reference);
  }
  for (const std::string& name : o.integrators) {
    const sim::IntegratorKind integrator = *sim::integrator_named(name);
    std::vector<std::pair<double, sim::FloorContact>> steps{{0.0, sim::FloorContact::Smooth}};  // 0: auto
    if (std::find(o.friction_too.begin(), o.friction_too.end(), name) != o.friction_too.end()) {
      steps.emplace_back(0.0, sim::FloorContact::Friction);
    }
    for (const auto& [dt, contact] : steps) {
      BounceSetup setup;
      setup.level = level;
      setup.integrator = integrator;
      setup.dt_s = dt;
      setup.contact = contact;
      int runs = 0;
      const BounceRecord r = timed(
          o, [&] { return bench::record_bounce(setup, o.duration_s); }, runs);
      std::string step = dt > 0.0                                  ? "1/" + std::to_string(std::lround(1.0 / dt)) + " s"
                         : integrator == sim::IntegratorKind::Xpbd ? "substeps auto"
                                                                   : "dt auto";
      if (integrator == sim::IntegratorKind::Rk45) step += " (" + tolerance_label(setup.tolerance) + ")";
      print_row(level, o, {"softbody " + name, "ours", sim::to_string(setup.contact), step}, r, runs, compared);
    }
  }
  for (const int rate : o.bullet_rates) {
    if (rate <= 0) continue;  // --bullet-rates 0 (or ''): no Bullet run
    int runs = 0;
    const BounceRecord r = timed(
        o, [&] { return bench::record_bullet_bounce(level, 1.0 / rate, o.duration_s); }, runs);
    print_row(level, o,
              {"bullet btSoftBody", "bullet (own model)", "bullet SDF_RS", "1/" + std::to_string(rate) + " s"}, r, runs,
              compared);
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App cli(
      "bench_large_steps: the bounce of issue 13, every integrator and Bullet, wall time per simulated "
      "second against the error from a converged rk45 run (smooth floor); CSV on stdout");
  Options o;
  cli.add_option("--levels", o.levels, "icosphere levels")->delimiter(',');
  cli.add_option("--integrators", o.integrators, "integrators, each at its automatic step")->delimiter(',');
  cli.add_option("--friction-too", o.friction_too, "integrators also run on the friction floor at their automatic step")
      ->delimiter(',');
  cli.add_option("--bullet-rates", o.bullet_rates, "Bullet: steps per second (0: no Bullet run)")->delimiter(',');
  cli.add_option("--reference-tolerances", o.reference_tolerances,
                 "rk45 tolerances of the reference (the first) and of its checks")
      ->delimiter(',');
  cli.add_option("--duration", o.duration_s, "simulated seconds");
  cli.add_option("--repeats", o.repeats, "runs (median wall time) of each setting that takes under --repeat-below");
  cli.add_option("--repeat-below", o.repeat_below_s, "wall seconds");
  cli.add_flag("!--no-header", o.header, "no CSV header line (to append)");
  cli.add_flag("!--no-reference", o.reference, "no rk45 reference run: timings only, the error columns empty");
  cli.add_option("--reference-cache", o.reference_cache,
                 "file with the reference run (%d: the level), read if it holds one, else written after computing it "
                 "(its row then repeats the times of the run that wrote it; same duration and tolerance are the "
                 "caller's business); bench_xpbd_convergence writes the same records");
  CLI11_PARSE(cli, argc, argv);
  for (const std::string& name : o.integrators) {
    if (!sim::integrator_named(name)) {
      std::fprintf(stderr, "error: --integrators: expected integrator names, got %s\n", name.c_str());
      return 2;
    }
  }
  if (o.header) {
    std::printf(
        "level,duration_s,program,model,contact,step,dt_s,steps,cpu_s_per_sim_s,wall_s_per_sim_s,runs,com_max_error_m,"
        "volume_worst_error_pct,rms_end_m,rms_samples_m,newton_iterations_per_step,status\n");
  }
  for (const int level : o.levels) run_level(level, o);
  return 0;
}
