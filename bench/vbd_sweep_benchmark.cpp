// Google Benchmark: the cost of one vbd sweep per vertex (ns per vertex per sweep), with and without the affine
// correction, on scenes/bounce_smooth.json's ball in flight.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "scene/scene_json.hpp"
#include "setup/build_world.hpp"
#include "sim/forces/dynamics.hpp"
#include "sim/integrators/vertex_block_descent.hpp"
#include "sim/integrators/vertex_move_lanes.hpp"

namespace {

constexpr int kSweeps = 4;  // sweeps per measured step (the bench's default setting)

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
// Args: {level, affine correction 1/0, threads, lanes 1/0 (sim/integrators/vertex_move_lanes.hpp)}; CPU time is
// summed over the threads, so compare wall time (real_time).
void BM_VbdSweep(benchmark::State& st) {
  const int level = static_cast<int>(st.range(0));
  const bool affine = st.range(1) == 1;
  const int threads = static_cast<int>(st.range(2));
  const bool lanes = st.range(3) == 1;
  sim::enable_lanes(lanes);
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
  sim::enable_lanes(true);
  st.SetLabel(std::string(affine ? "with" : "without") + " affine correction, " + std::to_string(threads) +
              " thread(s), " + (lanes ? "lanes" : "one vertex at a time") + ", h " + std::to_string(h) + " s");
  st.counters["vertices"] = vertices;
  st.counters["steps_per_call"] = static_cast<double>(vbd.statistics().steps) / static_cast<double>(st.iterations());
  st.counters["ns_per_vertex_sweep"] =
      benchmark::Counter(vertex_sweeps * 1e-9, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  st.counters["sure_fraction"] =
      static_cast<double>(vbd.statistics().sure_steps) / static_cast<double>(vbd.statistics().vertex_solves);
  st.counters["halvings_per_solve"] =
      static_cast<double>(vbd.statistics().halvings) / static_cast<double>(vbd.statistics().vertex_solves);
}

}  // namespace

BENCHMARK(BM_VbdSweep)->ArgsProduct({{3, 5, 6}, {1, 0}, {1, 2}, {1, 0}})->UseRealTime()->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
