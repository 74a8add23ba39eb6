// Integrator test helpers.
#include "support.hpp"

#include <cmath>

#include <nlohmann/json.hpp>

#include "scene/scene_json.hpp"
#include "setup/build_world.hpp"
#include "sim/diagnostics.hpp"

namespace integrator_tests {

scene::Scene scene_with_solver(const std::string& json_text, const sim::Solver& solver) {
  const std::filesystem::path file = std::filesystem::path(SOFTBODY_SOURCE_DIR) / "tests" / "inline.json";
  scene::Scene s = scene::scene_from_json(scene::parse_scene_text(json_text, file), file);
  s.solver = solver;
  return s;
}

sim::World make_world(const std::string& json_text, sim::IntegratorKind integrator, double tolerance) {
  sim::Solver solver;
  solver.integrator = integrator;
  solver.tolerance = tolerance;
  std::vector<std::string> notes;
  return setup::build_world(scene_with_solver(json_text, solver), notes);
}

void run_for(sim::World& world, double duration_s, double dt) {
  const auto steps = static_cast<long long>(std::llround(duration_s / dt));
  for (long long i = 0; i < steps; ++i) world.step(dt);
}

double rms_position_difference(const sim::State& a, const sim::State& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.x.size(); ++i) sum += (a.x[i] - b.x[i]).squaredNorm();
  return std::sqrt(sum / static_cast<double>(a.x.size()));
}

double total_energy(const sim::World& world) {
  double energy = 0.0;
  for (std::size_t b = 0; b < world.model.bodies.size(); ++b) energy += sim::diagnose(world.model, world.state, b).total_J();
  return energy;
}

double fitted_slope(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double sum_x = 0, sum_y = 0, sum_xx = 0, sum_xy = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    sum_x += x[k];
    sum_y += y[k];
    sum_xx += x[k] * x[k];
    sum_xy += x[k] * y[k];
  }
  return (n * sum_xy - sum_x * sum_y) / (n * sum_xx - sum_x * sum_x);
}

double observed_order(const std::vector<double>& errors) {
  std::vector<double> k, log_error;
  for (std::size_t i = 0; i < errors.size(); ++i) {
    k.push_back(static_cast<double>(i));
    log_error.push_back(std::log2(errors[i]));
  }
  return -fitted_slope(k, log_error);
}

}  // namespace integrator_tests
