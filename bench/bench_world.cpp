// Builds the benchmark worlds from scenes/bounce.json, so that benchmarks and the CLI run the same physics.
#include "bench_world.hpp"

#include <array>
#include <cmath>
#include <vector>

#include "scene/scene_json.hpp"
#include "setup/build_world.hpp"

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
  return setup::build_world(bench_scene(c), notes);
}

scene::Scene contact_scene(bool touching) {
  using softbody::Vec3;
  scene::Scene s = scene::load_scene(std::string(SOFTBODY_SOURCE_DIR) + "/scenes/pile.json");
  s.solver.integrator = sim::IntegratorKind::Symplectic;
  // Pillows are 1 m tall (y in [-0.5, 0.5]) and 1.6 m wide; the ball has radius 0.45 m. Stacked, each
  // body's lowest point sits on the highest point of the one below; apart, all rest on the floor 2 m apart.
  const std::array<Vec3, 4> stacked = {Vec3(0, 0.5, 0), Vec3(0.15, 1.5, 0.05), Vec3(-0.1, 2.5, -0.05),
                                       Vec3(0.1, 3.45, 0)};
  const std::array<Vec3, 4> apart = {Vec3(-3, 0.5, 0), Vec3(-1, 0.5, 0), Vec3(1, 0.5, 0), Vec3(3, 0.45, 0)};
  for (std::size_t b = 0; b < s.bodies.size(); ++b) s.bodies.at(b).position_m = (touching ? stacked : apart).at(b);
  return s;
}

sim::World contact_world(bool touching, int settle_steps) {
  std::vector<std::string> notes;
  const scene::Scene s = contact_scene(touching);
  sim::World world = setup::build_world(s, notes);
  for (int i = 0; i < settle_steps; ++i) world.step(s.solver.dt_s);
  return world;
}

}  // namespace bench
