// The run-time-versus-error benchmark: every integrator over a sweep of steps (rk45: tolerances), each
// run's wall time and its position error against a converged fine-step reference.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "sim/model/body.hpp"

namespace analysis {

// Every integrator of sim::kIntegrators, in its order.
std::vector<sim::IntegratorKind> every_integrator();

struct AccuracyOptions {
  double duration_s = 0.0;      // simulated span; 0: the scene's duration
  double reference_dt_s = 0.0;  // reference step; 0: solver.dt / 10
  // The reference's method, at fixed steps: rk45 means Dormand–Prince's 5th-order formula without error
  // control. With contact events every method is first order at best, so a cheaper method at a finer
  // step can make the better reference there (docs/physics/integrators.md).
  sim::IntegratorKind reference_integrator = sim::IntegratorKind::Rk45;
  double coarsest_factor = 32.0;  // fixed-step sweeps start at this × solver.dt, then refine
  // Each fixed-step run's dt is the previous one's over this (2: halving). A finer ratio (√2) puts more runs
  // between the stability limit and the reference's floor, where an order can be fitted.
  double refinement = 2.0;
  int max_runs = 12;                     // per integrator
  double run_budget_s = 3.0;             // stop refining an integrator once one run takes longer than this
  double rk45_loosest_tolerance = 1e-2;  // then ÷10 per run
  // Runs whose error is below this × the reference's uncertainty measure the reference, not themselves:
  // status at_reference, not plotted, and the sweep stops. 100 on smooth scenes; lower it where no
  // converged reference can be had (contact), to see the curves at all (the summary then says so).
  double floor_factor = 100.0;
  std::vector<sim::IntegratorKind> integrators = every_integrator();  // the methods compared, in this order
};

// Status of one run: ok; diverged (a non-finite state, or rk45's step underflowed); blown_up (finite, but
// the RMS error exceeds the body's size, so the numbers mean nothing); at_reference (the error is below
// floor_factor × the reference's own uncertainty, so it measures the reference, not the run: not plotted).
enum class RunStatus { Ok, Diverged, BlownUp, AtReference };
std::string to_string(RunStatus status);

struct AccuracyRun {
  sim::IntegratorKind integrator = sim::IntegratorKind::Euler;
  double dt_s = 0.0;       // the step used (frame-aligned); rk45: the mean accepted step
  double tolerance = 0.0;  // rk45 only, else 0
  long long steps = 0;     // accepted steps
  long long rejected_steps = 0;
  double wall_s = 0.0;         // stepping time of the run (median of 3 for runs under 0.5 s)
  double rms_error_m = 0.0;    // RMS over every frame after frame 0 and every vertex of |x − x_ref|
  double final_error_m = 0.0;  // RMS over vertices at the last frame
  RunStatus status = RunStatus::Ok;
  // A fixed step above the integrator's estimated stable dt (sim/step/stability.hpp). With a smooth contact's
  // regularised friction such a run need not blow up (the friction force is bounded by μN), so its error is
  // finite, but it is not in the asymptotic range: fit orders without these runs.
  bool above_stable_dt = false;
};

struct Reference {
  std::string method;          // e.g. "rk45 fixed step (5th order)"
  double dt_s = 0.0;           // the step of the reference used
  double uncertainty_m = 0.0;  // RMS error-norm distance to the same method at twice the step
  double wall_s = 0.0;         // both reference runs
};

struct AccuracyResult {
  std::string scene_name;
  double duration_s = 0.0;
  int fps = 0;
  std::size_t vertices = 0;
  double body_size_m = 0.0;         // RMS distance of the vertices from their centroid at t = 0
  std::vector<double> stable_dt_s;  // the estimated stable dt of each integrator of `runs`, by IntegratorKind
  Reference reference;
  double floor_factor = 0.0;  // AccuracyOptions::floor_factor: runs below it times the uncertainty are at_reference
  std::vector<AccuracyRun> runs;
  double total_wall_s = 0.0;
};

using Log = std::function<void(const std::string&)>;

// Runs the reference, then each integrator's sweep. `log` receives one line per run (may be empty).
AccuracyResult run_accuracy_benchmark(const scene::Scene& scene, const AccuracyOptions& options, const Log& log = {});

}  // namespace analysis
