// Dormand–Prince 5(4) stages, error estimate and step-size control.
#include "sim/integrators/dormand_prince.hpp"

#include <algorithm>
#include <cmath>

namespace sim {
namespace {

// Butcher tableau (Hairer, Nørsett & Wanner, Table II.5.2): a_ij by rows; c_i = Σ_j a_ij is implicit
// because the forces do not depend on time.
constexpr std::array<double, 1> kA2 = {1.0 / 5.0};
constexpr std::array<double, 2> kA3 = {3.0 / 40.0, 9.0 / 40.0};
constexpr std::array<double, 3> kA4 = {44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0};
constexpr std::array<double, 4> kA5 = {19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, -212.0 / 729.0};
constexpr std::array<double, 5> kA6 = {9017.0 / 3168.0, -355.0 / 33.0, 46732.0 / 5247.0, 49.0 / 176.0,
                                       -5103.0 / 18656.0};
// Fifth-order weights b (= the 7th stage's row, hence FSAL).
constexpr std::array<double, 6> kB = {35.0 / 384.0, 0.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0};
// b − b̂ with b̂ the embedded fourth-order weights: the error estimate's weights (7 stages).
constexpr std::array<double, 7> kE = {35.0 / 384.0 - 5179.0 / 57600.0,
                                      0.0,
                                      500.0 / 1113.0 - 7571.0 / 16695.0,
                                      125.0 / 192.0 - 393.0 / 640.0,
                                      -2187.0 / 6784.0 + 92097.0 / 339200.0,
                                      11.0 / 84.0 - 187.0 / 2100.0,
                                      -1.0 / 40.0};

double scaled_square(const Vec3& error, const Vec3& y0, const Vec3& y1, double tolerance) {
  double sum = 0.0;
  for (int c = 0; c < 3; ++c) {
    const double scale = tolerance + tolerance * std::max(std::abs(y0[c]), std::abs(y1[c]));
    sum += (error[c] / scale) * (error[c] / scale);
  }
  return sum;
}

}  // namespace

void DormandPrince::prepare(Dynamics& dynamics, State& state) {
  if (state.carry.acceleration.empty()) dynamics.accelerations(state, state.carry.acceleration);
}

void DormandPrince::stages(Dynamics& dynamics, const State& state, double dt) {
  k_[0].dx.assign(state.v.begin(), state.v.end());  // the first stage f(y) = (v, a(x, v)), carried over
  k_[0].dv.assign(state.carry.acceleration.begin(), state.carry.acceleration.end());
  combine(state, dt, kA2, {&k_[0]}, stage_);
  evaluate_slope(dynamics, stage_, k_[1]);
  combine(state, dt, kA3, {&k_[0], &k_[1]}, stage_);
  evaluate_slope(dynamics, stage_, k_[2]);
  combine(state, dt, kA4, {&k_[0], &k_[1], &k_[2]}, stage_);
  evaluate_slope(dynamics, stage_, k_[3]);
  combine(state, dt, kA5, {&k_[0], &k_[1], &k_[2], &k_[3]}, stage_);
  evaluate_slope(dynamics, stage_, k_[4]);
  combine(state, dt, kA6, {&k_[0], &k_[1], &k_[2], &k_[3], &k_[4]}, stage_);
  evaluate_slope(dynamics, stage_, k_[5]);
  combine(state, dt, kB, {&k_[0], &k_[1], &k_[2], &k_[3], &k_[4], &k_[5]}, result_);
  evaluate_slope(dynamics, result_, k_[6]);
}

double DormandPrince::error_norm(const State& state, double dt) const {
  const std::size_t n = state.x.size();
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    Vec3 ex = Vec3::Zero(), ev = Vec3::Zero();
    for (std::size_t j = 0; j < kE.size(); ++j) {
      if (kE[j] == 0.0) continue;
      ex += kE[j] * k_[j].dx[i];
      ev += kE[j] * k_[j].dv[i];
    }
    sum += scaled_square(dt * ex, state.x[i], result_.x[i], tolerance_);
    sum += scaled_square(dt * ev, state.v[i], result_.v[i], tolerance_);
  }
  return std::sqrt(sum / static_cast<double>(6 * std::max<std::size_t>(n, 1)));
}

void DormandPrince::advance(State& state) {
  std::swap(state.x, result_.x);  // buffers change hands: no copy, no allocation
  std::swap(state.v, result_.v);
  std::swap(state.carry.acceleration, k_[6].dv);  // FSAL: a(new state) is the next step's first stage
}

void DormandPrince::step(Dynamics& dynamics, State& state, double dt) {
  stages(dynamics, state, dt);
  advance(state);
}

double DormandPrince::attempt(Dynamics& dynamics, State& state, double dt) {
  stages(dynamics, state, dt);
  const double error = error_norm(state, dt);
  advance(state);
  return error;
}

}  // namespace sim
