// A body's breathing mode, the uniform swelling that its gas drives, and how much of it an implicit step damps: for
// `softbody info`, which warns where vbd's steps would damp out a breathing that the model keeps, and for vbd's start,
// which does not follow such a breathing in small steps.
#pragma once

#include <span>

#include "sim/model/body.hpp"

namespace sim {

using softbody::Vec3;

// The breathing mode as one degree of freedom: x = c + s (X − c) about the centre of mass c, at s = 1 (the shape X),
//   stiffness  K = E''(s) = Σ_e k_e l_e² + 3 nRT       [J]    (E = Σ ½ k (s l − L0)² − nRT ln(s³ V))
//   inertia    I = Σ_i m_i |X_i − c|²                  [kg m²]   (the body's lumped masses)
//   damping    C = Σ_e c_e l_e²                        [J s]  (each damper along its edge sees l ṡ)
// so ω = √(K/I) and ζ = C / (2 I ω), over every distance constraint (edges and bending links).
struct BreathingMode {
  double omega = 0.0;          // [rad/s]
  double damping_ratio = 0.0;  // ζ of the model's dampers [1]
};
BreathingMode breathing_mode(const Body& body, std::span<const Vec3> x);

// BDF2's own damping ratio of an undamped oscillator at steps of ω h = `omega_h`: −ln|ξ| / (ω h), ξ the larger root
// of (3/2 − i ω h) ξ² − 2 ξ + ½ = 0 (a BDF2 step of ẋ = i ω x at a constant step): an amplitude ∝ e^(−ζ ω t).
// 0.0019 at ω h = 0.2, 0.069 at 1, 0.16 at 3.3.
double bdf2_damping_ratio(double omega_h);

// Below this damping ratio a body's breathing rings for several periods in the model, so a step that damps it far
// faster changes the answer (scenes/breathing.json, ζ = 0.0015: vbd at one step per frame is 3.8 % off in volume and
// rk4 0.17 %; scenes/bounce_smooth.json, ζ = 0.10: the dampers take it out within about 0.1 s themselves;
// docs/notes/2026-12-06-vbd-breathing.md).
inline constexpr double kLightlyDamped = 0.05;
// How many times faster than the model BDF2 must damp such a breathing to count as damping it out.
inline constexpr double kDampedTooFast = 10.0;
// Whether BDF2's steps of h [s] damp `mode`, a lightly damped breathing (ζ < kLightlyDamped), at least kDampedTooFast
// times faster than the model does, so that they cannot follow it for long.
bool damped_out_by_bdf2(const BreathingMode& mode, double h);

}  // namespace sim
