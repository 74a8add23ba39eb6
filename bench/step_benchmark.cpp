// Google Benchmark: our step per integrator and mesh size, the skipped passes, and Bullet side by side.
#include <benchmark/benchmark.h>

#include <array>
#include <optional>
#include <string>

#include "bench_world.hpp"
#include "bullet_pressure_body.hpp"
#include "core/errors.hpp"

namespace {

using bench::BenchCase;

constexpr std::array kIntegrators = {sim::IntegratorKind::Euler,  sim::IntegratorKind::Symplectic,
                                     sim::IntegratorKind::Verlet, sim::IntegratorKind::Rk4,
                                     sim::IntegratorKind::Rk45,   sim::IntegratorKind::Xpbd};

// Steps the world of `c` once per iteration; a diverged world (not expected at bench_dt_s) is rebuilt
// and counted in the "rebuilds" counter, so a number is never silently taken from a blown-up state.
void run_steps(benchmark::State& st, const BenchCase& c) {
  sim::World world = bench::bench_world(c);
  const double dt = bench::bench_dt_s(c.level);
  const auto vertices = static_cast<double>(world.state.x.size());
  double rebuilds = 0;
  for (auto _ : st) {
    try {
      world.step(dt);
    } catch (const softbody::DivergedError&) {
      st.PauseTiming();
      world = bench::bench_world(c);
      rebuilds += 1;
      st.ResumeTiming();
    }
  }
  st.counters["vertices"] = vertices;
  st.counters["vertex_steps_per_s"] =
      benchmark::Counter(vertices * static_cast<double>(st.iterations()), benchmark::Counter::kIsRate);
  st.counters["rebuilds"] = rebuilds;
}

// Args: {integrator index, level}.
void BM_Step(benchmark::State& st) {
  BenchCase c;
  c.integrator = kIntegrators.at(static_cast<std::size_t>(st.range(0)));
  c.level = static_cast<int>(st.range(1));
  st.SetLabel(sim::to_string(c.integrator));
  run_steps(st, c);
}

// Args: {level, what is switched off: 0 nothing, 1 pressure, 2 damping, 3 floor, 4 all three}.
void BM_Skip(benchmark::State& st) {
  BenchCase c;
  c.level = static_cast<int>(st.range(0));
  const auto off = st.range(1);
  c.pressure = !(off == 1 || off == 4);
  c.damping = !(off == 2 || off == 4);
  c.floor = !(off == 3 || off == 4);
  static constexpr std::array kLabels = {"full", "no_pressure", "no_damping", "no_floor", "springs_gravity_only"};
  st.SetLabel(kLabels.at(static_cast<std::size_t>(off)));
  run_steps(st, c);
}

// Ours in the Bullet comparison: symplectic Euler, springs, dampers, pressure, gravity, floor; the body starts
// on the floor so that contact is part of every measured step, as it is for Bullet. Args: {level}.
void BM_Ours(benchmark::State& st) {
  BenchCase c;
  c.level = static_cast<int>(st.range(0));
  c.on_floor = true;
  st.SetLabel("symplectic");
  run_steps(st, c);
}

// Ours as in BM_Ours on `threads` threads (the same states bit for bit; only bodies of at least
// sim::kParallelMinVertices vertices use them). Args: {level, threads}.
void BM_OursThreads(benchmark::State& st) {
  BenchCase c;
  c.level = static_cast<int>(st.range(0));
  c.threads = static_cast<int>(st.range(1));
  c.on_floor = true;
  st.SetLabel("symplectic, " + std::to_string(c.threads) + " thread" + (c.threads > 1 ? "s" : ""));
  run_steps(st, c);
}

// Bullet's btSoftBody on the same triangles, dt, mass, gravity and floor, starting on the floor. Args: {level}.
void BM_Bullet(benchmark::State& st) {
  BenchCase c;
  c.level = static_cast<int>(st.range(0));
  c.on_floor = true;
  const scene::Scene s = bench::bench_scene(c);
  const sim::World ours = bench::bench_world(c);
  bench::BulletBodySpec spec;
  spec.vertices_m = ours.state.x;
  spec.triangles = ours.model.bodies.at(0).topology.faces;
  spec.mass_kg = s.bodies.at(0).mass_kg;
  spec.pressure = s.bodies.at(0).pressure_J;
  spec.gravity_m_per_s2 = s.gravity_m_per_s2.y();
  spec.floor_height_m = s.floor->height_m;
  spec.velocity_m_per_s = s.bodies.at(0).velocity_m_per_s;
  bench::BulletPressureBody bullet(spec);
  const double dt = bench::bench_dt_s(c.level);
  for (auto _ : st) bullet.step(dt);
  const auto vertices = static_cast<double>(bullet.vertex_count());
  st.SetLabel("bullet float, height " + std::to_string(bullet.first_node_height_m()));
  st.counters["vertices"] = vertices;
  st.counters["vertex_steps_per_s"] =
      benchmark::Counter(vertices * static_cast<double>(st.iterations()), benchmark::Counter::kIsRate);
}

// Body–body contact: scenes/pile.json's four bodies (1800 vertices) stacked, each resting on the one below,
// against the same bodies apart on the floor; the difference is the contact search and response. The
// stack is first settled for kContactSettleSteps steps (0.04 s) so that every measured step has contact;
// the settled state is made once and copied. Args: {1 stacked, 0 apart}.
constexpr int kContactSettleSteps = 2000;

void BM_Contact(benchmark::State& st) {
  const bool touching = st.range(0) == 1;
  static std::array<std::optional<sim::State>, 2> settled;
  auto& cached = settled.at(touching ? 1 : 0);
  if (!cached) cached = bench::contact_world(touching, kContactSettleSteps).state;
  sim::World world = bench::contact_world(touching, 0);
  world.state = *cached;
  const double dt = bench::contact_scene(touching).solver.dt_s;
  for (auto _ : st) world.step(dt);
  const auto vertices = static_cast<double>(world.state.x.size());
  st.SetLabel(touching ? "stacked" : "apart");
  st.counters["vertices"] = vertices;
  st.counters["vertex_steps_per_s"] =
      benchmark::Counter(vertices * static_cast<double>(st.iterations()), benchmark::Counter::kIsRate);
}

void step_args(benchmark::internal::Benchmark* b) {
  for (int i = 0; i < static_cast<int>(kIntegrators.size()); ++i) {
    for (int level = 1; level <= 6; ++level) b->Args({i, level});
  }
}

void skip_args(benchmark::internal::Benchmark* b) {
  for (int off = 0; off <= 4; ++off) b->Args({5, off});
}

// Bullet and ours alternate, level by level, so that both see the same machine load.
void register_comparison() {
  for (int level : {3, 5}) {
    benchmark::RegisterBenchmark("BM_Ours", BM_Ours)->Arg(level)->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark("BM_Bullet", BM_Bullet)->Arg(level)->Unit(benchmark::kMicrosecond);
  }
}

}  // namespace

BENCHMARK(BM_Step)->Apply(step_args)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Skip)->Apply(skip_args)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Contact)->Arg(1)->Arg(0)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_OursThreads)->ArgsProduct({{5, 6}, {1, 2}})->Unit(benchmark::kMicrosecond)->UseRealTime();

int main(int argc, char** argv) {
  register_comparison();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
