// Builds the benchmark worlds from scenes/bounce.json, so that benchmarks and the CLI run the same physics.
#include "bench_world.hpp"

#include <cmath>
#include <vector>

#include "scene/scene_json.hpp"

namespace bench {

double bench_dt_s(int level) { return level <= 4 ? 1e-4 : 1e-4 * std::pow(0.25, level - 4); }

scene::Scene bench_scene(const BenchCase& c) {
  scene::Scene s = scene::load_scene(std::string(SOFTBODY_SOURCE_DIR) + "/scenes/bounce.json");
  scene::Body& body = s.bodies.at(0);
  body.mesh = "icosphere:" + std::to_string(c.level);
  if (!c.pressure) body.pressure_J = 0.0;
  if (!c.damping) body.damping_N_s_per_m = 0.0;
  if (!c.floor) s.floor.reset();
  // The unit ball's lowest vertex at y = 0: contact from the first step (the paper floor bounces it).
  if (c.on_floor) body.position_m.y() = 1.0;
  s.solver.integrator = c.integrator;
  s.solver.dt_s = bench_dt_s(c.level);
  s.solver.threads = c.threads;
  return s;
}

sim::World bench_world(const BenchCase& c) {
  std::vector<std::string> notes;
  return sim::build_world(bench_scene(c), notes);
}

}  // namespace bench
