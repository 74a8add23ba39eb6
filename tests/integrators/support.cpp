// Integrator test helpers.
#include "support.hpp"

#include <cmath>
#include <cstdio>

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

double hessian_mismatch(sim::IncrementalPotential& potential, const sim::Model& model, const sim::BlockSystem& hessian,
                        std::span<const softbody::Vec3> x, const Eigen::VectorXd& r, double step) {
  using softbody::Vec3;
  // H r first: assemble() below replaces the rank-one terms.
  Eigen::VectorXd product;
  hessian.multiply(r, product);
  const auto add_rank_one = [&](std::span<const Vec3> u, auto vertex_of) {
    double u_r = 0.0;
    for (std::size_t i = 0; i < u.size(); ++i) u_r += u[i].dot(r.segment<3>(hessian.dof(vertex_of(i))));
    for (std::size_t i = 0; i < u.size(); ++i) product.segment<3>(hessian.dof(vertex_of(i))) += u_r * u[i];
  };
  for (const sim::IncrementalPotential::GasTerm& term : potential.gas_terms()) {
    const int first = model.bodies[static_cast<std::size_t>(term.body)].first_vertex;
    add_rank_one(term.direction, [first](std::size_t i) { return first + static_cast<int>(i); });
  }
  for (const sim::BodyContactPotential::Term& term : potential.contact_terms()) {
    add_rank_one(term.u, [&term](std::size_t i) { return term.vertex[i]; });
  }
  std::vector<Vec3> plus(x.begin(), x.end()), minus(x.begin(), x.end());
  for (std::size_t i = 0; i < x.size(); ++i) {
    plus[i] += step * r.segment<3>(hessian.dof(static_cast<int>(i)));
    minus[i] -= step * r.segment<3>(hessian.dof(static_cast<int>(i)));
  }
  sim::BlockSystem scratch;
  scratch.build(model.vertex_count(), potential.pairs());
  Eigen::VectorXd gradient_plus = Eigen::VectorXd::Zero(hessian.size()), gradient_minus = gradient_plus;
  const auto exact = sim::IncrementalPotential::Hessian::Exact;
  potential.assemble(model, plus, exact, scratch, gradient_plus);
  potential.assemble(model, minus, exact, scratch, gradient_minus);
  const Eigen::VectorXd derivative = (gradient_plus - gradient_minus) / (2.0 * step);
  return (derivative - product).norm() / product.norm();
}

}  // namespace integrator_tests
