// The accuracy sweep: reference, runs, errors, timing.
#include "analysis/accuracy.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/errors.hpp"
#include "frames/frame_clock.hpp"
#include "frames/frame_loop.hpp"
#include "setup/build_world.hpp"
#include "sim/step/stability.hpp"

namespace analysis {

std::vector<sim::IntegratorKind> every_integrator() {
  std::vector<sim::IntegratorKind> all;
  for (const sim::IntegratorInfo& integrator : sim::kIntegrators) all.push_back(integrator.kind);
  return all;
}
namespace {

using softbody::Vec3;

// Keeps every frame's positions (frame 0 included) in one flat array, allocated once.
class PositionRecorder final : public frames::FrameSink {
 public:
  PositionRecorder(int frames, std::size_t vertices) : vertices_(vertices) {
    positions_.reserve(static_cast<std::size_t>(frames) * vertices);
  }
  void on_frame(int, double, const sim::World& world) override {
    const std::vector<Vec3>& x = world.state.x;
    positions_.insert(positions_.end(), x.begin(), x.end());
  }
  void finish(bool) override {}
  const std::vector<Vec3>& positions() const { return positions_; }
  std::size_t frames() const { return positions_.size() / vertices_; }

 private:
  std::size_t vertices_;
  std::vector<Vec3> positions_;
};

struct Trajectory {
  std::vector<Vec3> positions;  // frame-major
  long long steps = 0;
  long long rejected_steps = 0;
  double step_wall_s = 0.0;
  double dt_s = 0.0;
  bool diverged = false;
};

scene::Scene with_solver(scene::Scene scene, sim::IntegratorKind integrator, double dt_s, double tolerance) {
  scene.solver.integrator = integrator;
  scene.solver.dt_s = dt_s;
  scene.solver.tolerance = tolerance;
  return scene;
}

// One simulation of `scene` over `duration_s`, positions recorded at every frame.
Trajectory simulate(const scene::Scene& scene, double duration_s) {
  const frames::FrameClock clock = frames::plan_frames(duration_s, scene.fps, scene.solver.dt_s);
  std::vector<std::string> notes;
  sim::World world = setup::build_world(scene, notes);
  PositionRecorder recorder(clock.frame_count + 1, world.state.x.size());
  frames::FrameSink* sinks[] = {&recorder};
  Trajectory trajectory;
  trajectory.dt_s = clock.dt_s;
  try {
    const frames::RunStats stats = frames::run_frames(world, clock, sinks);
    trajectory.steps = stats.steps;
    trajectory.rejected_steps = stats.rejected_steps;
    trajectory.step_wall_s = stats.step_wall_s;
    if (world.adaptive()) trajectory.dt_s = duration_s / static_cast<double>(std::max(1LL, stats.steps));
  } catch (const softbody::DivergedError&) {
    trajectory.diverged = true;
  }
  trajectory.positions = recorder.positions();
  return trajectory;
}

// RMS of |a − b| over frames [first_frame, last] and every vertex.
// `integrator` at fixed steps (sim::step, also for rk45: its fifth-order formula without error control,
// not the adaptive advance_to), frames recorded like simulate() does.
Trajectory fixed_step_run(const scene::Scene& scene, sim::IntegratorKind integrator, double dt_s, double duration_s) {
  const frames::FrameClock clock = frames::plan_frames(duration_s, scene.fps, dt_s);
  std::vector<std::string> notes;
  sim::World world = setup::build_world(with_solver(scene, integrator, dt_s, 1.0), notes);
  PositionRecorder recorder(clock.frame_count + 1, world.state.x.size());
  Trajectory trajectory;
  trajectory.dt_s = clock.dt_s;
  recorder.on_frame(0, 0.0, world);
  const auto start = std::chrono::steady_clock::now();
  try {
    for (int frame = 1; frame <= clock.frame_count; ++frame) {
      for (int s = 0; s < clock.steps_per_frame; ++s) world.step(clock.dt_s);
      recorder.on_frame(frame, frame * clock.frame_interval_s, world);
    }
  } catch (const softbody::DivergedError&) {
    trajectory.diverged = true;
  }
  trajectory.step_wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  trajectory.steps = world.state.steps;
  trajectory.positions = recorder.positions();
  return trajectory;
}

double rms_distance(const std::vector<Vec3>& a, const std::vector<Vec3>& b, std::size_t vertices,
                    std::size_t first_frame) {
  const std::size_t begin = first_frame * vertices, end = std::min(a.size(), b.size());
  if (end <= begin) return 0.0;
  double sum = 0.0;
  for (std::size_t i = begin; i < end; ++i) sum += (a[i] - b[i]).squaredNorm();
  return std::sqrt(sum / static_cast<double>(end - begin));
}

// 1e-09, not std::to_string's 0.000000.
std::string format_tolerance(double tolerance) {
  char text[32];
  std::snprintf(text, sizeof text, "%.0e", tolerance);
  return text;
}

std::string format_seconds(double s) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g s", s);
  return text;
}

double body_size(const std::vector<Vec3>& x0) {
  Vec3 centroid = Vec3::Zero();
  for (const Vec3& x : x0) centroid += x / static_cast<double>(x0.size());
  double sum = 0.0;
  for (const Vec3& x : x0) sum += (x - centroid).squaredNorm();
  return std::sqrt(sum / static_cast<double>(x0.size()));
}

// Short runs are timed three times and the median kept: the machine is shared, and one slow run from
// another process's burst should not bend the curve.
Trajectory timed_run(const scene::Scene& scene, double duration_s) {
  Trajectory first = simulate(scene, duration_s);
  constexpr double kRepeatBelow_s = 0.5;
  if (first.diverged || first.step_wall_s >= kRepeatBelow_s) return first;
  std::array<double, 3> wall{first.step_wall_s, simulate(scene, duration_s).step_wall_s,
                             simulate(scene, duration_s).step_wall_s};
  std::sort(wall.begin(), wall.end());
  first.step_wall_s = wall[1];
  return first;
}

class Benchmark {
 public:
  Benchmark(const scene::Scene& scene, const AccuracyOptions& options, const Log& log)
      : scene_(scene), options_(options), log_(log) {
    result_.scene_name = scene.name;
    result_.duration_s = options.duration_s > 0.0 ? options.duration_s : scene.duration_s;
    result_.fps = scene.fps;
    result_.floor_factor = options.floor_factor;
  }

  AccuracyResult run() {
    const auto start = std::chrono::steady_clock::now();
    estimate_stable_steps();
    compute_reference();
    for (sim::IntegratorKind integrator : options_.integrators) {
      if (integrator == sim::IntegratorKind::Rk45) {
        sweep_tolerances();
      } else {
        sweep_steps(integrator);
      }
    }
    result_.total_wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result_;
  }

 private:
  void say(const std::string& line) const {
    if (log_) log_(line);
  }

  // Every integrator's estimated stable dt at the scene's initial state (what `softbody info` prints).
  void estimate_stable_steps() {
    std::vector<std::string> notes;
    const sim::World world = setup::build_world(scene_, notes);
    const sim::StabilityEstimate estimate = sim::estimate_stability(world.model, world.state);
    result_.stable_dt_s.assign(estimate.stable_dt_s.begin(), estimate.stable_dt_s.end());
  }

  // The reference method at a fixed step, and again at twice the step to check it.
  void compute_reference() {
    const double dt = options_.reference_dt_s > 0.0 ? options_.reference_dt_s : scene_.solver.dt_s / 10.0;
    const double duration = result_.duration_s;
    const sim::IntegratorKind method = options_.reference_integrator;
    const Trajectory fine = fixed_step_run(scene_, method, dt, duration);
    const Trajectory check = fixed_step_run(scene_, method, 2.0 * dt, duration);
    if (fine.diverged || check.diverged) {
      throw softbody::DivergedError("the reference solution diverged at dt = " + std::to_string(dt) +
                                    " s; choose a smaller --reference-dt");
    }
    reference_ = fine.positions;
    vertices_ = fine.positions.size() / static_cast<std::size_t>(frame_count() + 1);
    result_.vertices = vertices_;
    result_.body_size_m = body_size({fine.positions.begin(), fine.positions.begin() + static_cast<long>(vertices_)});
    result_.reference.method =
        method == sim::IntegratorKind::Rk45 ? "rk45 fixed step (5th order)" : sim::to_string(method) + " fixed step";
    result_.reference.dt_s = fine.dt_s;
    result_.reference.uncertainty_m = rms_distance(fine.positions, check.positions, vertices_, 1);
    result_.reference.wall_s = fine.step_wall_s + check.step_wall_s;
    char line[200];
    std::snprintf(line, sizeof line, "reference: %s, dt = %.3g s; distance to dt = %.3g s: %.2e m (%.1f s)",
                  result_.reference.method.c_str(), fine.dt_s, check.dt_s, result_.reference.uncertainty_m,
                  result_.reference.wall_s);
    say(line);
  }

  int frame_count() const {
    return frames::plan_frames(result_.duration_s, scene_.fps, scene_.solver.dt_s).frame_count;
  }

  AccuracyRun measure(sim::IntegratorKind integrator, double dt, double tolerance) {
    const Trajectory t = timed_run(with_solver(scene_, integrator, dt, tolerance), result_.duration_s);
    AccuracyRun run;
    run.integrator = integrator;
    run.dt_s = t.dt_s;
    run.tolerance = tolerance;
    run.steps = t.steps;
    run.rejected_steps = t.rejected_steps;
    run.wall_s = t.step_wall_s;
    if (t.diverged) {
      run.status = RunStatus::Diverged;
      run.rms_error_m = run.final_error_m = std::numeric_limits<double>::quiet_NaN();
    } else {
      run.rms_error_m = rms_distance(t.positions, reference_, vertices_, 1);
      run.final_error_m = rms_distance(t.positions, reference_, vertices_, t.positions.size() / vertices_ - 1);
      if (!(run.rms_error_m <= result_.body_size_m)) run.status = RunStatus::BlownUp;
      if (run.rms_error_m < options_.floor_factor * result_.reference.uncertainty_m)
        run.status = RunStatus::AtReference;
    }
    const double stable_dt = result_.stable_dt_s[static_cast<std::size_t>(integrator)];
    run.above_stable_dt = integrator != sim::IntegratorKind::Rk45 && run.dt_s > stable_dt;
    char line[260];
    std::snprintf(
        line, sizeof line, "%-10s dt %.3e s%s: %s, rms error %.3e m, final %.3e m, %lld steps, %.3f s%s",
        sim::to_string(integrator).c_str(), run.dt_s,
        tolerance > 0.0 ? (" (tol " + format_tolerance(tolerance) + ")").c_str() : "", to_string(run.status).c_str(),
        run.rms_error_m, run.final_error_m, run.steps, run.wall_s,
        run.above_stable_dt ? (" (above the estimated stable dt " + format_seconds(stable_dt) + ")").c_str() : "");
    say(line);
    result_.runs.push_back(run);
    return run;
  }

  // Below floor_factor × the reference's uncertainty a run measures the reference: stop refining.
  static bool at_reference_floor(const AccuracyRun& run) { return run.status == RunStatus::AtReference; }

  void sweep_steps(sim::IntegratorKind integrator) {
    double dt = options_.coarsest_factor * scene_.solver.dt_s;
    for (int k = 0; k < options_.max_runs; ++k, dt /= options_.refinement) {
      const AccuracyRun run = measure(integrator, dt, 0.0);
      if (run.wall_s > options_.run_budget_s || at_reference_floor(run)) break;
    }
  }

  void sweep_tolerances() {
    double tolerance = options_.rk45_loosest_tolerance;
    for (int k = 0; k < options_.max_runs; ++k, tolerance /= 10.0) {
      const AccuracyRun run = measure(sim::IntegratorKind::Rk45, scene_.solver.dt_s, tolerance);
      if (run.wall_s > options_.run_budget_s || at_reference_floor(run)) break;
    }
  }

  const scene::Scene& scene_;
  const AccuracyOptions& options_;
  const Log& log_;
  AccuracyResult result_;
  std::vector<Vec3> reference_;
  std::size_t vertices_ = 0;
};

}  // namespace

std::string to_string(RunStatus status) {
  switch (status) {
    case RunStatus::Ok: return "ok";
    case RunStatus::Diverged: return "diverged";
    case RunStatus::BlownUp: return "blown_up";
    case RunStatus::AtReference: return "at_reference";
  }
  return "?";
}

AccuracyResult run_accuracy_benchmark(const scene::Scene& scene, const AccuracyOptions& options, const Log& log) {
  Benchmark benchmark(scene, options, log);
  return benchmark.run();
}

}  // namespace analysis
