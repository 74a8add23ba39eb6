// The smooth floor contact: a penalty spring-damper on each vertex's penetration with regularised Coulomb
// friction, evaluated as a force inside a(x, v), so that the equations of motion stay an ODE that every
// integrator converges on (the paper's and the friction contact are projections after the step instead).
//
// Design note. For a vertex of mass m at penetration d = floor − y > 0 and velocity v = (v_t, v_n):
//   normal      f_n = m ω² δ P(d/δ) − m 2ζω v_n s(d/δ)          ω = 1/τ  [N]
//   friction    f_t = −μ m ω² δ P(d/δ) v_t / √(|v_t|² + ε²)     (Coulomb on the elastic normal force)  [N]
//   energy      E   = m ω² δ² R(d/δ)                            (f_n's elastic part is −∂E/∂y)  [J]
// with the smootherstep s(t) = 6t⁵ − 15t⁴ + 10t³ on [0, 1] (0 below, 1 above) and its integrals
// P(t) = ∫₀ᵗ s = t⁶ − 3t⁵ + 5t⁴/2 (t − ½ beyond 1) and R(t) = ∫₀ᵗ P. Past the smoothing depth δ the contact is
// the linear spring m ω² (d − δ/2) and the dashpot 2ζωm; over the first δ both fade to zero with two
// continuous derivatives, so the force is C² in x and v (the spring alone, ∝ P, is C³). Where a vertex crosses
// d = 0 or d = δ the dashpot's third time derivative jumps (by 120 m ζω v_n⁴/δ³), so the step that straddles
// the crossing has a local error O(h⁴) instead of the O(h²) of a switch: a method of order ≤ 3 keeps its
// order through an impact, and rk4 keeps order 4 in its envelope, but that part of its error depends on
// where in its step each vertex crosses, so it is not a smooth function of dt. It falls like 1/δ³, which is why
// scenes/bounce_smooth.json smooths over 1 cm (docs/physics/contact.md, "The smooth floor").
// Friction scales with the elastic part alone, which is never negative, so the friction bound has no kink
// where the dashpot pulls; it is regularised over the slip speed ε, so it is smooth in v_t too.
// Restitution of a single vertex on the linear part: e = exp(−πζ/√(1 − ζ²)) (a damped half oscillation),
// so the intent e gives ζ = −ln e / √(π² + ln² e) (e = 0: critical damping).
#pragma once

#include <span>

#include "core/vec.hpp"
#include "sim/model/settings.hpp"

namespace sim {

using softbody::Vec3;

// A smooth contact's constants per unit mass, resolved from the intent (the floor's and the bodies' alike).
struct SmoothResponse {
  double omega2 = 0.0;        // ω² = 1/τ² [1/s²]: the contact spring per unit mass
  double damping_rate = 0.0;  // 2ζω [1/s]: the contact dashpot per unit mass
  double friction = 0.0;      // μ
  double slip_speed_m_per_s = 0.0;
  double smoothing_m = 0.0;  // δ [m]
};

struct SmoothFloor : SmoothResponse {
  double height_m = 0.0;
};

// The damping ratio ζ whose damped half oscillation keeps `restitution` of the impact speed.
double damping_ratio_for_restitution(double restitution);

SmoothResponse resolve_smooth_response(const SmoothContact& contact, const ContactMaterial& material);
SmoothFloor resolve_smooth_floor(const Floor& floor);

// The contact's spring force per unit mass at penetration `depth` > 0, ω² δ P(depth/δ) [m/s²], and the weight
// of its dashpot there, s(depth/δ) (see the design note).
double smooth_elastic_per_mass(const SmoothResponse& contact, double depth_m);
double smooth_dashpot_weight(const SmoothResponse& contact, double depth_m);
// The contact spring's potential energy per unit mass at penetration `depth` > 0, ω² δ² R(depth/δ) [J/kg]
// (its derivative in depth is smooth_elastic_per_mass).
double smooth_energy_per_mass(const SmoothResponse& contact, double depth_m);

// f_i += the contact force on every vertex below the floor (see the design note) [N].
void add_smooth_floor_forces(const SmoothFloor& floor, std::span<const double> mass_kg, std::span<const Vec3> x,
                             std::span<const Vec3> v, std::span<Vec3> force);

// Σ_i m_i ω² δ² R(d_i/δ): the contact springs' potential energy [J].
double smooth_floor_energy(const SmoothFloor& floor, std::span<const double> mass_kg, std::span<const Vec3> x);

}  // namespace sim
