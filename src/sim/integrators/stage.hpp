// Explicit Runge–Kutta building blocks: the slope of y = (x, v) at a stage, and stage states.
#pragma once

#include <array>
#include <vector>

#include "sim/integrators/integrators.hpp"

namespace sim {

// dy/dt at one stage: ẋ = v, v̇ = a(x, v).
struct Slope {
  std::vector<Vec3> dx;  // m/s
  std::vector<Vec3> dv;  // m/s²
};

// k = f(y): copies the velocities and evaluates the accelerations (no allocation once sized).
inline void evaluate_slope(Dynamics& dynamics, const State& y, Slope& k) {
  k.dx.assign(y.v.begin(), y.v.end());
  dynamics.accelerations(y, k.dv);
}

// out = y0 + h Σ_j w[j] k[j]: a stage state, or the step's result when w are the weights b. Its time is
// t0 + h Σ_j w[j] (the stage's c_i = Σ_j a_ij; 1 for the result): a keyframed collider's pose at the stage.
template <std::size_t N>
void combine(const State& y0, double h, const std::array<double, N>& w, const std::array<const Slope*, N>& k,
             State& out) {
  const std::size_t n = y0.x.size();
  out.x.resize(n);
  out.v.resize(n);
  double c = 0.0;
  for (const double weight : w) c += weight;
  out.time_s = y0.time_s + h * c;
  for (std::size_t i = 0; i < n; ++i) {
    Vec3 dx = Vec3::Zero(), dv = Vec3::Zero();
    for (std::size_t j = 0; j < N; ++j) {
      if (w[j] == 0.0) continue;
      dx += w[j] * k[j]->dx[i];
      dv += w[j] * k[j]->dv[i];
    }
    out.x[i] = y0.x[i] + h * dx;
    out.v[i] = y0.v[i] + h * dv;
  }
}

}  // namespace sim
