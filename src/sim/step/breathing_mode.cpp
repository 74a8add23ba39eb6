// A body's breathing mode and BDF2's numerical damping of it.
#include "sim/step/breathing_mode.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

#include "sim/forces/energy.hpp"

namespace sim {

BreathingMode breathing_mode(const Body& body, std::span<const Vec3> x) {
  const Vec3 centre = centre_of_mass(body, x);
  double inertia = 0.0;  // I [kg m²]
  for (std::size_t i = 0; i < x.size(); ++i) inertia += body.masses.kg[i] * (x[i] - centre).squaredNorm();
  const DistanceConstraints& constraints = body.constraints;
  double stiffness = 3.0 * body.params.pressure_J;  // K [J]: the gas's −nRT ln(s³ V)'' at s = 1
  double damping = 0.0;                             // C [J s]
  for (std::size_t e = 0; e < constraints.size(); ++e) {
    const auto [a, b] = constraints.ends[e];
    const double length2 = (x[static_cast<std::size_t>(a)] - x[static_cast<std::size_t>(b)]).squaredNorm();
    stiffness += constraints.stiffness_N_per_m[e] * length2;
    damping += constraints.damping_N_s_per_m[e] * length2;
  }
  BreathingMode mode;
  if (inertia <= 0.0 || stiffness <= 0.0) return mode;
  mode.omega = std::sqrt(stiffness / inertia);
  mode.damping_ratio = damping / (2.0 * inertia * mode.omega);
  return mode;
}

double bdf2_damping_ratio(double omega_h) {
  if (omega_h <= 0.0) return 0.0;
  using Complex = std::complex<double>;
  const Complex a(1.5, -omega_h);  // (3/2 − i ω h) ξ² − 2 ξ + ½ = 0
  const Complex root = std::sqrt(Complex(4.0, 0.0) - 2.0 * a);
  const double larger = std::max(std::abs((2.0 + root) / (2.0 * a)), std::abs((2.0 - root) / (2.0 * a)));
  return -std::log(larger) / omega_h;
}

bool damped_out_by_bdf2(const BreathingMode& mode, double h) {
  return mode.omega > 0.0 && mode.damping_ratio < kLightlyDamped &&
         bdf2_damping_ratio(mode.omega * h) >= kDampedTooFast * mode.damping_ratio;
}

}  // namespace sim
