// Helpers shared by the integrator tests: worlds from scene text, fixed-step runs, state distances.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "scene/scene.hpp"
#include "sim/step/world.hpp"

namespace integrator_tests {

// A deterministic, non-smooth field of unit size over vertex indices (perturbed states for finite differences).
softbody::Vec3 wiggle(std::size_t i, double phase);

// The scene in `json_text` (comments allowed) with its solver replaced by `solver`.
scene::Scene scene_with_solver(const std::string& json_text, const sim::Solver& solver);

// The world of `json_text` integrated with `integrator` (rk45: with `tolerance`).
sim::World make_world(const std::string& json_text, sim::IntegratorKind integrator, double tolerance = 1e-6);
// The same with the whole solver given (e.g. vbd's sweeps).
sim::World make_world(const std::string& json_text, const sim::Solver& solver);

// Gravity only: every vertex is a free particle.
inline constexpr const char* kDust = R"({
  "gravity": [0, -9.81, 0],
  "bodies": [ { "mesh": "icosphere:1", "position": [0, 5, 0], "velocity": [1.5, 4, -0.5],
                "mass": 1.0, "stiffness": 0.0, "damping": 0.0, "pressure": 0.0 } ]
})";

// Runs whole steps of dt until `duration_s` (which dt must divide up to round-off).
void run_for(sim::World& world, double duration_s, double dt);

// RMS over vertices of |x_a − x_b| [m].
double rms_position_difference(const sim::State& a, const sim::State& b);

// A convergence measurement on one scene over one span (the breathing sphere's, the impact's): the reference,
// Dormand–Prince's fifth-order formula at a fixed step, computed once; its uncertainty, its distance to the same
// at twice the step; and a method's errors against it as dt halves.
class HalvingSweep {
 public:
  HalvingSweep(std::string json_text, double span_s, double reference_dt_s);
  const sim::State& reference();
  double reference_uncertainty();
  // `integrator` at fixed steps dt over the span (rk45: its fifth-order formula without error control).
  sim::State state_after(sim::IntegratorKind integrator, double dt) const;
  // RMS position errors against the reference at coarsest_dt / 2^k, k = 0 .. halvings.
  std::vector<double> errors(sim::IntegratorKind integrator, double coarsest_dt, int halvings);
  const std::string& scene() const { return json_text_; }
  double span() const { return span_s_; }

 private:
  std::string json_text_;
  double span_s_, reference_dt_s_;
  std::optional<sim::State> reference_;
  std::optional<double> uncertainty_;
};

// Least-squares slope of y against x (analysis::least_squares_line, as the accuracy benchmark fits).
double fitted_slope(const std::vector<double>& x, const std::vector<double>& y);

// errors[k] measured at dt / 2^k: minus the least-squares slope of log2(error) against k, the observed order.
double observed_order(const std::vector<double>& errors);

// Prints one line of a convergence measurement (the errors, their pairwise orders, the fitted order and the
// reference's uncertainty) and returns the fitted order.
double report_observed_order(sim::IntegratorKind integrator, const std::vector<double>& errors,
                             double reference_uncertainty);

// rk45 on `json_text` over `span_s` at tolerances 10^-loosest_exponent .. 10^-tightest_exponent: each run's error
// against `reference` (printed), and the fitted slope of log(error) against log(tolerance).
struct ToleranceSweep {
  std::vector<double> tolerances, errors;
  double slope = 0.0;
};
ToleranceSweep rk45_tolerance_sweep(const std::string& json_text, double span_s, const sim::State& reference,
                                    int loosest_exponent, int tightest_exponent);

// Total energy of every body: kinetic + gravitational + spring + gas [J].
double total_energy(const sim::World& world);

}  // namespace integrator_tests
