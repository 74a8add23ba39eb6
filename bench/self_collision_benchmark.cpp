// Google Benchmark: the step with and without self-collision, on scenes/bounce.json's ball at icosphere:5 (in
// flight: the cost of the search alone) and on scenes/fold.json's tube folded over its bar (contacts in every step).
#include <benchmark/benchmark.h>

#include <array>
#include <optional>
#include <string>

#include "bench_world.hpp"
#include "scene/scene_json.hpp"
#include "setup/build_world.hpp"

namespace {

// Args: {self_collision 0 or 1}. Symplectic Euler at bench_dt_s(5), the ball falling (no contact yet).
void BM_SelfCollisionBall(benchmark::State& st) {
  bench::BenchCase c;
  c.level = 5;
  scene::Scene s = bench::bench_scene(c);
  s.bodies.at(0).self_collision = st.range(0) == 1;
  std::vector<std::string> notes;
  sim::World world = setup::build_world(s, notes);
  const double dt = bench::bench_dt_s(c.level);
  for (auto _ : st) world.step(dt);
  st.SetLabel(st.range(0) == 1 ? "icosphere:5, self-collision" : "icosphere:5");
  st.counters["vertices"] = static_cast<double>(world.state.x.size());
}

// scenes/fold.json (symplectic, impulse contact), first run for kFoldSettleSteps (0.23 s at its auto step of
// 4.6e-5 s: the halves pressed together under the bar, frame 7 of its render) with self-collision; the folded state is
// made once and copied. Args: {self_collision 0 or 1}.
constexpr int kFoldSettleSteps = 5000;
constexpr double kFoldDt_s = 4.6e-5;

scene::Scene fold_scene(bool self_collision) {
  scene::Scene s = scene::load_scene(std::string(SOFTBODY_SOURCE_DIR) + "/scenes/fold.json");
  s.bodies.at(0).self_collision = self_collision;
  return s;
}

void BM_SelfCollisionFold(benchmark::State& st) {
  static std::optional<sim::State> folded;
  std::vector<std::string> notes;
  if (!folded) {
    sim::World settling = setup::build_world(fold_scene(true), notes);
    for (int i = 0; i < kFoldSettleSteps; ++i) settling.step(kFoldDt_s);
    folded = settling.state;
  }
  sim::World world = setup::build_world(fold_scene(st.range(0) == 1), notes);
  world.state = *folded;
  for (auto _ : st) world.step(kFoldDt_s);
  st.SetLabel(st.range(0) == 1 ? "folded tube, self-collision" : "folded tube");
  st.counters["vertices"] = static_cast<double>(world.state.x.size());
}

}  // namespace

BENCHMARK(BM_SelfCollisionBall)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SelfCollisionFold)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
