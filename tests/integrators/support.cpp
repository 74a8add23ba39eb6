// Integrator test helpers.
#include "support.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include <nlohmann/json.hpp>

#include "analysis/observed_order.hpp"
#include "scene/scene_json.hpp"
#include "setup/build_world.hpp"
#include "sim/step/diagnostics.hpp"

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
  return make_world(json_text, solver);
}

sim::World make_world(const std::string& json_text, const sim::Solver& solver) {
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

softbody::Vec3 wiggle(std::size_t i, double phase) {
  const double s = static_cast<double>(i);
  return softbody::Vec3(std::sin(7.1 * s + phase), std::cos(3.3 * s + 2.0 * phase), std::sin(5.7 * s + 1.0 + phase));
}

double total_energy(const sim::World& world) {
  double energy = 0.0;
  for (std::size_t b = 0; b < world.model.bodies.size(); ++b)
    energy += sim::diagnose(world.model, world.state, b).total_J();
  return energy;
}

double fitted_slope(const std::vector<double>& x, const std::vector<double>& y) {
  return analysis::least_squares_line(x, y).slope;
}

HalvingSweep::HalvingSweep(std::string json_text, double span_s, double reference_dt_s)
    : json_text_(std::move(json_text)), span_s_(span_s), reference_dt_s_(reference_dt_s) {}

sim::State HalvingSweep::state_after(sim::IntegratorKind integrator, double dt) const {
  sim::World world = make_world(json_text_, integrator);
  run_for(world, span_s_, dt);
  return world.state;
}

const sim::State& HalvingSweep::reference() {
  if (!reference_) reference_ = state_after(sim::IntegratorKind::Rk45, reference_dt_s_);
  return *reference_;
}

double HalvingSweep::reference_uncertainty() {
  if (!uncertainty_)
    uncertainty_ = rms_position_difference(state_after(sim::IntegratorKind::Rk45, 2 * reference_dt_s_), reference());
  return *uncertainty_;
}

std::vector<double> HalvingSweep::errors(sim::IntegratorKind integrator, double coarsest_dt, int halvings) {
  std::vector<double> errors;
  double dt = coarsest_dt;
  for (int k = 0; k <= halvings; ++k, dt /= 2.0)
    errors.push_back(rms_position_difference(state_after(integrator, dt), reference()));
  return errors;
}

double observed_order(const std::vector<double>& errors) {
  std::vector<double> k, log_error;
  for (std::size_t i = 0; i < errors.size(); ++i) {
    k.push_back(static_cast<double>(i));
    log_error.push_back(std::log2(errors[i]));
  }
  return -fitted_slope(k, log_error);
}

double report_observed_order(sim::IntegratorKind integrator, const std::vector<double>& errors,
                             double reference_uncertainty) {
  const double order = observed_order(errors);
  std::printf("%-10s", sim::to_string(integrator).c_str());
  for (std::size_t k = 0; k < errors.size(); ++k) std::printf(" e(dt/%d)=%.3e", 1 << k, errors[k]);
  std::printf("  pairwise:");
  for (std::size_t k = 1; k < errors.size(); ++k) std::printf(" %.3f", std::log2(errors[k - 1] / errors[k]));
  std::printf("  fitted order %.3f (reference uncertainty %.1e)\n", order, reference_uncertainty);
  return order;
}

ToleranceSweep rk45_tolerance_sweep(const std::string& json_text, double span_s, const sim::State& reference,
                                    int loosest_exponent, int tightest_exponent) {
  ToleranceSweep sweep;
  std::vector<double> log_tolerance, log_error;
  for (int e = loosest_exponent; e <= tightest_exponent; ++e) {
    const double tolerance = std::pow(10.0, -e);
    sim::World world = make_world(json_text, sim::IntegratorKind::Rk45, tolerance);
    world.advance_to(span_s);
    const double error = rms_position_difference(world.state, reference);
    std::printf("rk45 tolerance %.0e: error %.3e, %lld accepted + %lld rejected steps\n", tolerance, error,
                world.state.steps, world.state.rejected_steps);
    sweep.tolerances.push_back(tolerance);
    sweep.errors.push_back(error);
    log_tolerance.push_back(std::log10(tolerance));
    log_error.push_back(std::log10(error));
  }
  sweep.slope = fitted_slope(log_tolerance, log_error);
  std::printf("rk45: d log(error) / d log(tolerance) = %.3f\n", sweep.slope);
  return sweep;
}

}  // namespace integrator_tests
