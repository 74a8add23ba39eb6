// Google Benchmark: the cost of one vbd sweep per vertex (ns per vertex per sweep), with and without the affine
// correction, and of one coarse-level correction (sim/integrators/coarse_space.hpp), on scenes/bounce_smooth.json's
// ball in flight.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "scene/scene_json.hpp"
#include "setup/build_world.hpp"
#include "sim/forces/dynamics.hpp"
#include "sim/forces/forces.hpp"
#include "sim/integrators/coarse_space.hpp"
#include "sim/integrators/vertex_block_descent.hpp"
#include "sim/integrators/vertex_move_lanes.hpp"
#include "sim/step/part_runner.hpp"

namespace {

using softbody::Vec3;

constexpr int kSweeps = 4;  // sweeps per measured step (the bench's default setting)

// The benchmarks' lanes argument: 0 one vertex at a time, 1 four lanes (AVX2), 2 eight (AVX-512F)
// (sim/integrators/vertex_move_lanes.hpp). Switches them for the program; false (the benchmark skipped) where this CPU
// has no eight lanes.
bool use_lanes(benchmark::State& st, int lanes) {
  if (lanes == 2 && !sim::wide_lanes_available()) {
    st.SkipWithError("this CPU has no AVX-512F: no eight lanes");
    return false;
  }
  sim::enable_lanes(lanes > 0);
  sim::enable_wide_lanes(lanes == 2);
  return true;
}

// The lanes back to their default (on, eight where the CPU has them).
void restore_lanes() {
  sim::enable_lanes(true);
  sim::enable_wide_lanes(true);
}

std::string lanes_label(int lanes) {
  return lanes == 0 ? "one vertex at a time" : lanes == 1 ? "four lanes" : "eight lanes";
}

// bounce_smooth.json's ball at icosphere:level, stepped by vbd for 0.1 s from its start 3 m up: in flight, its BDF2
// history made by vbd's own steps.
sim::World flying_ball(int level, int threads) {
  scene::Scene s = scene::load_scene(std::string(SOFTBODY_SOURCE_DIR) + "/scenes/bounce_smooth.json");
  s.bodies.at(0).mesh = "icosphere:" + std::to_string(level);
  s.solver.integrator = sim::IntegratorKind::Vbd;
  s.solver.iterations = kSweeps;
  s.solver.threads = threads;
  std::vector<std::string> notes;
  sim::World world = setup::build_world(s, notes);
  for (int frame = 0; frame < 3; ++frame) world.step(1.0 / 30.0);
  return world;
}

// One BDF2 step (ratio 1: h is the last step's, so vbd takes it whole) per iteration from the same state.
// Args: {level, affine correction 1/0, threads, lanes (use_lanes)}; CPU time is summed over the threads, so compare
// wall time (real_time).
void BM_VbdSweep(benchmark::State& st) {
  const int level = static_cast<int>(st.range(0));
  const bool affine = st.range(1) == 1;
  const int threads = static_cast<int>(st.range(2));
  const int lanes = static_cast<int>(st.range(3));
  if (!use_lanes(st, lanes)) return;
  sim::World world = flying_ball(level, threads);
  const sim::State start = world.state;
  const double h = start.carry.previous_dt_s;
  sim::VertexBlockDescent vbd(kSweeps, affine);
  sim::Dynamics dynamics(world.model, world.workspace.forces);
  sim::State state = start;
  for (auto _ : st) {
    st.PauseTiming();
    state = start;
    st.ResumeTiming();
    vbd.step(dynamics, state, h);
  }
  const auto vertices = static_cast<double>(state.x.size());
  const double vertex_sweeps = vertices * kSweeps * static_cast<double>(vbd.statistics().steps);
  restore_lanes();
  st.SetLabel(std::string(affine ? "with" : "without") + " affine correction, " + std::to_string(threads) +
              " thread(s), " + lanes_label(lanes) + ", h " + std::to_string(h) + " s");
  st.counters["vertices"] = vertices;
  st.counters["steps_per_call"] = static_cast<double>(vbd.statistics().steps) / static_cast<double>(st.iterations());
  st.counters["ns_per_vertex_sweep"] =
      benchmark::Counter(vertex_sweeps * 1e-9, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  st.counters["sure_fraction"] =
      static_cast<double>(vbd.statistics().sure_steps) / static_cast<double>(vbd.statistics().vertex_solves);
  st.counters["halvings_per_solve"] =
      static_cast<double>(vbd.statistics().halvings) / static_cast<double>(vbd.statistics().vertex_solves);
}

// One coarse correction (128 cells and the linear fields, as solver.coarse_space "auto" takes above 5000 vertices) on
// the flying ball's BDF2 step from its start x = y, on `threads` threads, with `lanes` (use_lanes); `refresh`: the
// matrix assembled and factored (vbd assembles it at every kCoarseMatrixSteps-th step and reuses it between).
void coarse_correction_benchmark(benchmark::State& st, int level, bool refresh, int threads, int lanes) {
  if (!use_lanes(st, lanes)) return;
  const sim::World world = flying_ball(level, 1);
  const sim::Body& body = world.model.bodies[0];
  const sim::VertexBlocks blocks = sim::vertex_blocks(body);
  const sim::CoarseSpace space = sim::smooth_coarse_space(blocks, sim::kAutoCoarseCells, body.rest.position_m);
  const double h = world.state.carry.previous_dt_s, h_hat = 2.0 * h / 3.0;
  std::vector<Vec3> target, base;
  for (std::size_t i = 0; i < world.state.x.size(); ++i) {
    base.push_back(world.state.x[i]);
    target.push_back(world.state.x[i] + h_hat * world.state.v[i] + h_hat * h_hat * world.model.gravity_m_per_s2);
  }
  sim::PartRunner runner(threads);
  sim::BodySolve s{blocks, world.model.mass_kg,   target,       base,    h_hat,
                   0.0,    1.0 / (h_hat * h_hat), std::nullopt, nullptr, {}};
  s.gas = sim::GasLaw{body.params.pressure_J, sim::guarded_volume(0.0, body.rest.volume_m3)};
  if (threads > 1) s.runner = &runner;
  sim::CoarseScratch scratch;
  std::vector<Vec3> x = target;
  sim::coarse_correction(body, s, space, x, true, scratch);  // sizes the scratch and factors the matrix once
  for (auto _ : st) {
    st.PauseTiming();
    x = target;
    st.ResumeTiming();
    benchmark::DoNotOptimize(sim::coarse_correction(body, s, space, x, refresh, scratch));
  }
  restore_lanes();
  st.SetLabel(std::string(refresh ? "assembling and factoring" : "reusing") + " the matrix, " + lanes_label(lanes) +
              ", " + std::to_string(threads) + " thread(s), " + std::to_string(space.aggregates) + " aggregates, " +
              std::to_string(space.weight.size()) + " weights");
  st.counters["ns_per_vertex"] =
      benchmark::Counter(static_cast<double>(x.size()) * 1e-9,
                         benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// Args: {level, matrix assembled and factored 1/0, lanes}, one thread.
void BM_CoarseCorrection(benchmark::State& st) {
  coarse_correction_benchmark(st, static_cast<int>(st.range(0)), st.range(1) == 1, 1, static_cast<int>(st.range(2)));
}

// Args: {level, matrix assembled and factored 1/0, threads}, eight lanes; compare the wall time (UseRealTime).
void BM_CoarseCorrectionThreads(benchmark::State& st) {
  coarse_correction_benchmark(st, static_cast<int>(st.range(0)), st.range(1) == 1, static_cast<int>(st.range(2)), 2);
}

}  // namespace

BENCHMARK(BM_CoarseCorrection)->ArgsProduct({{5, 6}, {0, 1}, {2, 1, 0}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CoarseCorrectionThreads)
    ->ArgsProduct({{5, 6}, {0, 1}, {1, 2}})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_VbdSweep)
    ->ArgsProduct({{3, 5, 6}, {1, 0}, {1, 2}, {2, 1, 0}})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
