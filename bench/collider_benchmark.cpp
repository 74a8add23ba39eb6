// Google Benchmark: the step of scenes/bounce.json's ball at icosphere:5 resting on the ground, the ground being the
// floor alone (no collider), a box collider on the floor, the floor with a box far away, or a mesh collider (a cube
// mesh) on the floor; for symplectic Euler, xpbd and vbd at their automatic steps. The floor and the colliders use
// the friction contact without restitution, so that the ball settles and stays in contact.
#include <benchmark/benchmark.h>

#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "scene/scene_json.hpp"
#include "setup/build_world.hpp"
#include "sim/step/step_plan.hpp"

namespace {

enum class Ground { Floor, Box, FarBox, Mesh };

constexpr std::array<sim::IntegratorKind, 3> kIntegrators = {sim::IntegratorKind::Symplectic, sim::IntegratorKind::Xpbd,
                                                             sim::IntegratorKind::Vbd};

// The colliders key and the ball's centre height [m] for `ground`: the ball (unit radius) starts touching the floor
// (y = 0) or the top of the 20 cm box (y = 0.2).
// ("": none)
std::pair<std::string, double> ground_overrides(Ground ground) {
  switch (ground) {
    case Ground::Floor: return {"", 1.0};
    case Ground::Box: return {R"(colliders=[{"shape": "box", "position": [0, 0.1, 0], "size": [4, 0.2, 4]}])", 1.2};
    case Ground::FarBox: return {R"(colliders=[{"shape": "box", "position": [20, 0.1, 0], "size": [4, 0.2, 4]}])", 1.0};
    case Ground::Mesh:  // a unit cube of 8 × 8 quads a side, scaled to 4 m, its top at y = 0.2
      return {R"(colliders=[{"shape": "mesh", "mesh": "cube:8", "scale": 4, "position": [0, -1.8, 0]}])", 1.2};
  }
  return {};
}

scene::Scene ground_scene(sim::IntegratorKind integrator, Ground ground) {
  const auto [colliders, height_m] = ground_overrides(ground);
  std::vector<std::string> overrides = {
      "solver.integrator=\"" + sim::to_string(integrator) + "\"",
      "solver.dt=\"auto\"",
      R"(floor={"height": 0, "contact": "friction", "restitution": 0, "friction": 0.5})",
      "bodies.0.mesh=\"icosphere:5\"",
      "bodies.0.position=[0, " + std::to_string(height_m) + ", 0]",
      "bodies.0.velocity=[0, 0, 0]",
      "solver.threads=1",
  };
  if (!colliders.empty()) overrides.push_back(colliders);
  return scene::load_scene(std::string(SOFTBODY_SOURCE_DIR) + "/scenes/bounce.json", overrides);
}

// The world for (integrator, ground) after kSettle_s of simulated time (the ball resting on its ground, its contact
// patch near its final size: about 500 vertices), made once per case and copied into each repetition.
constexpr double kSettle_s = 0.3;

sim::World settled_world(sim::IntegratorKind integrator, Ground ground) {
  static std::map<std::pair<int, int>, sim::State> settled;
  std::vector<std::string> notes;
  const scene::Scene s = ground_scene(integrator, ground);
  sim::World world = setup::build_world(s, notes);
  sim::resolve_step(world.model, world.state, 1.0 / s.fps, s.source.string());
  const auto key = std::make_pair(static_cast<int>(integrator), static_cast<int>(ground));
  if (const auto found = settled.find(key); found != settled.end()) {
    world.state = found->second;
    return world;
  }
  const double dt = world.model.solver.dt_s;
  while (world.state.time_s < kSettle_s) world.step(dt);
  settled.emplace(key, world.state);
  return world;
}

const char* ground_name(Ground ground) {
  switch (ground) {
    case Ground::Floor: return "on the floor, no collider";
    case Ground::Box: return "on a box collider";
    case Ground::FarBox: return "on the floor, a box collider 20 m away";
    case Ground::Mesh: return "on a mesh collider (cube:8)";
  }
  return "";
}

// Args: {integrator (index into kIntegrators), ground}.
void BM_ColliderStep(benchmark::State& st) {
  const sim::IntegratorKind integrator = kIntegrators.at(static_cast<std::size_t>(st.range(0)));
  const auto ground = static_cast<Ground>(st.range(1));
  sim::World world = settled_world(integrator, ground);
  const double dt = world.model.solver.dt_s;
  for (auto _ : st) world.step(dt);
  st.SetLabel(sim::to_string(integrator) + ", icosphere:5 " + ground_name(ground));
  st.counters["dt_us"] = dt * 1e6;
}

void ground_cases(benchmark::internal::Benchmark* b) {
  for (int integrator = 0; integrator < static_cast<int>(kIntegrators.size()); ++integrator) {
    for (const Ground ground : {Ground::Floor, Ground::Box, Ground::FarBox, Ground::Mesh}) {
      b->Args({integrator, static_cast<int>(ground)});
    }
  }
}

}  // namespace

BENCHMARK(BM_ColliderStep)->Apply(ground_cases)->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
