// The divergence guard: cheap checks after every step that the state is still a physical one.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "sim/body.hpp"

namespace sim {

// What the guard found wrong, and where.
struct Divergence {
  int body = 0;
  int vertex = -1;   // -1 when the finding is about the whole body (its volume)
  std::string what;  // e.g. "has a non-finite velocity", "volume inverted (V = -0.1 m³, V0 = 4.1 m³)"
};

// Checks, per body, in two passes (vertices, then faces):
//   1. every position and velocity finite;
//   2. internal kinetic energy (relative to the centre of mass) ≤ kRunawayFactor × the energy budget the
//      body started with: its kinetic energy, its spring energy, the gas's work down to the collapse
//      limit nRT ln(V / (kCollapseFraction V0)), and its fall to the floor M |g| (y_com − y_floor).
//      Gravity alone does not change internal motion, so only numerical energy gain can exceed it;
//   3. for a body with gas: enclosed volume > 0 (not inverted) and > kCollapseFraction V0 (collapsed).
// The budget is taken from the state at the first check after rebase() (a new state, e.g. set by a test).
class DivergenceGuard {
 public:
  static constexpr double kRunawayFactor = 10.0;
  static constexpr double kCollapseFraction = 0.01;

  // `floor_height_m`: the floor's y, or nothing without a floor; g: gravity [m/s²].
  void configure(std::optional<double> floor_height_m, double gravity_m_per_s2) {
    floor_height_m_ = floor_height_m;
    gravity_ = gravity_m_per_s2;
    rebase();
  }
  // Forget the energy budget: the next check takes it from the state it sees.
  void rebase() { budget_J_.clear(); }

  // The first problem found, or nothing.
  std::optional<Divergence> check(std::span<const Body> bodies, std::span<const Vec3> x, std::span<const Vec3> v);

  // Check 1 alone (one vectorised pass in the common case): what World runs on the steps between full checks.
  std::optional<Divergence> check_finite(std::span<const Body> bodies, std::span<const Vec3> x,
                                         std::span<const Vec3> v) const;

 private:
  double budget(const Body& body, std::span<const Vec3> x, std::span<const Vec3> v) const;

  std::optional<double> floor_height_m_;
  double gravity_ = 9.81;
  std::vector<double> budget_J_;  // per body
};

}  // namespace sim
