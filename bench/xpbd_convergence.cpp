// build/bench_xpbd_convergence: xpbd's error on the issue-13 bounce against the converged rk45 reference as the
// substeps double, split by phase (flight, impact, after) and by direction, to see what limits its order.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "bounce_run.hpp"
#include "reference_cache.hpp"

namespace {

using bench::BounceRecord;
using bench::BounceSetup;
using softbody::Vec3;

// The largest |error| of one quantity over the samples of each phase.
struct PhaseErrors {
  double flight = 0.0, impact = 0.0, after = 0.0;
  void add(std::size_t sample, std::size_t touch, std::size_t leave, double error) {
    double& phase = sample < touch ? flight : sample < leave ? impact : after;
    phase = std::max(phase, error);
  }
};

// The first sample at which any vertex of the reference is below the floor (y = 0), or the sample count.
std::size_t first_touch(const BounceRecord& reference) {
  for (std::size_t s = 0; s < reference.x_m.size(); ++s) {
    for (const Vec3& x : reference.x_m[s]) {
      if (x.y() < 0.0) return s;
    }
  }
  return reference.x_m.size();
}

// After the first touch: the first sample at which the reference's centre of mass rises again past its
// lowest point by half the way back to its height at the touch (the end of the squash), or the sample count.
std::size_t end_of_squash(const BounceRecord& reference, std::size_t touch) {
  if (touch >= reference.com_m.size()) return touch;
  std::size_t lowest = touch;
  for (std::size_t s = touch; s < reference.com_m.size(); ++s) {
    if (reference.com_m[s].y() < reference.com_m[lowest].y()) lowest = s;
    const double back = reference.com_m[s].y() - reference.com_m[lowest].y();
    if (s > lowest && back > 0.5 * (reference.com_m[touch].y() - reference.com_m[lowest].y())) return s;
  }
  return reference.com_m.size();
}

void report(int substeps, const BounceRecord& run, const BounceRecord& reference, std::size_t touch,
            std::size_t leave) {
  PhaseErrors com, com_vertical, com_horizontal, volume;
  const std::size_t samples = std::min(run.com_m.size(), reference.com_m.size());
  for (std::size_t s = 0; s < samples; ++s) {
    const Vec3 d = run.com_m[s] - reference.com_m[s];
    com.add(s, touch, leave, d.norm());
    com_vertical.add(s, touch, leave, std::abs(d.y()));
    com_horizontal.add(s, touch, leave, std::hypot(d.x(), d.z()));
    volume.add(s, touch, leave, 100.0 * std::abs(run.volume_m3[s] / reference.volume_m3[s] - 1.0));
  }
  std::printf("%d,%.6g,%.5g,%.4g,%.4g,%.4g,%.4g,%.4g,%.4g,%.4g,%.4g,%.4g,%.4g,%.4g,%.4g,%s\n", substeps, run.dt_s,
              run.cpu_s / (bench::kBounceSampleInterval_s * static_cast<double>(samples - 1)), com.flight, com.impact,
              com.after, com_vertical.flight, com_vertical.impact, com_vertical.after, com_horizontal.flight,
              com_horizontal.impact, com_horizontal.after, volume.flight, volume.impact, volume.after,
              run.failure.empty() ? "ok" : "failed");
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App cli(
      "bench_xpbd_convergence: xpbd's error on the bounce (smooth floor) against a converged rk45 run as "
      "the substeps per 1/60 s grow, by phase; CSV on stdout");
  int level = 3;
  double duration_s = 1.2, tolerance = 1e-8;
  std::vector<int> substeps{10, 20, 40, 80, 160, 320};
  std::string integrator = "xpbd";
  std::string reference_cache;
  int against_substeps = 0;
  cli.add_option("--level", level, "icosphere level");
  cli.add_option("--duration", duration_s, "simulated seconds");
  cli.add_option("--reference-tolerance", tolerance, "rk45 tolerance of the reference");
  cli.add_option("--substeps", substeps, "xpbd substeps (another integrator: steps) per 1/60 s")->delimiter(',');
  cli.add_option("--integrator", integrator, "the integrator to compare (fixed steps)")
      ->check([](const std::string& name) { return sim::integrator_named(name) ? "" : "expected an integrator name"; });
  cli.add_option("--reference-cache", reference_cache,
                 "file with the reference run: read if it holds one, else written after computing it (same level, "
                 "duration and tolerance are the caller's business)");
  cli.add_option("--against-substeps", against_substeps,
                 "compare with --integrator at this many steps per 1/60 s instead of the rk45 reference (where the "
                 "reference is too costly: its differences, not errors)");
  CLI11_PARSE(cli, argc, argv);
  BounceSetup reference_setup;
  reference_setup.level = level;
  reference_setup.integrator = sim::IntegratorKind::Rk45;
  reference_setup.tolerance = tolerance;
  if (against_substeps > 0) {
    reference_setup.integrator = *sim::integrator_named(integrator);
    reference_setup.dt_s = bench::kBounceSampleInterval_s / against_substeps;
  }
  const BounceRecord reference = bench::load_or_record(reference_setup, duration_s, reference_cache);
  const std::size_t touch = first_touch(reference), leave = end_of_squash(reference, touch);
  if (against_substeps > 0)
    std::printf("# against %s at %d steps per 1/60 s, not rk45\n", integrator.c_str(), against_substeps);
  std::printf(
      "# %s, level %d, %.4g s; reference rk45 %.0e; phases: flight to %.4g s, impact (squash) to %.4g s, after\n",
      integrator.c_str(), level, duration_s, tolerance, bench::kBounceSampleInterval_s * static_cast<double>(touch),
      bench::kBounceSampleInterval_s * static_cast<double>(leave));
  std::printf(
      "substeps,dt_s,cpu_s_per_sim_s,com_flight_m,com_impact_m,com_after_m,com_y_flight_m,com_y_impact_m,"
      "com_y_after_m,com_xz_flight_m,com_xz_impact_m,com_xz_after_m,volume_flight_pct,volume_impact_pct,"
      "volume_after_pct,status\n");
  for (const int n : substeps) {
    BounceSetup setup;
    setup.level = level;
    setup.integrator = *sim::integrator_named(integrator);
    setup.dt_s = bench::kBounceSampleInterval_s / n;
    report(n, bench::record_bounce(setup, duration_s), reference, touch, leave);
  }
  return 0;
}
