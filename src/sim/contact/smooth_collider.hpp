// The smooth contact (sim/contact/smooth_contact.hpp) against a static collider: the floor's spring, dashpot and
// regularised friction with the depth d = −(signed distance) and the outward normal n of the collider's surface
// at the vertex (sim/contact/collider_shape.hpp) in place of the floor's floor − y and +y:
//   f = [m ω² δ P(d/δ) − m 2ζω (v·n) s(d/δ)] n − μ m ω² δ P(d/δ) v_t / √(|v_t|² + ε²),   v_t = v − (v·n) n   [N]
//   E = m ω² δ² R(d/δ)                                                                                   [J]
// As a force inside a(x, v) it serves every explicit integrator. For vbd the same
// terms are written as parts of the step's energy, with the dashpot's weight, friction's normal force and the
// normal n lagged (taken at an earlier iterate, as IPC lags its friction: Li et al. 2020, §5):
//   spring    U = m ω² δ² R(d(x)/δ)                    ∇ = −m ω² δ P n(x)       ∇² ≈ m ω² s(d/δ) n nᵀ
//   dashpot   D_n = m b w (Δx·n̄)² / (2h)               ∇ = m b w (Δx·n̄)/h n̄    ∇² = m b w/h n̄ n̄ᵀ
//   friction  D_t = N h √(|v_t|² + ε²), v_t = P̄ Δx/h     ∇ = N v_t / r           ∇² = (N/(h r)) (P̄ − v_t v_tᵀ/r²)
// with P̄ = I − n̄ n̄ᵀ and r = √(|v_t|² + ε²). The spring's Hessian drops the surface's curvature term −m ω² δ P ∇n
// (negative semi-definite on a convex shape): what remains is positive semi-definite, and its energy is exact, so
// the line searches still see the true E. On a plane (∇n = 0) every term equals the floor's.
#pragma once

#include <span>

#include "sim/contact/smooth_contact.hpp"
#include "sim/model/settings.hpp"

namespace sim {

struct SmoothCollider : SmoothResponse {
  ColliderGeometry geometry;
};

// The collider's constants and its shape at time t (a keyframed collider's pose, with its points' velocity u).
SmoothCollider resolve_smooth_collider(const Collider& collider, double time_s = 0.0);

// f_i += the contact force on every vertex inside the collider [N].
void add_smooth_collider_forces(const SmoothCollider& collider, std::span<const double> mass_kg,
                                std::span<const Vec3> x, std::span<const Vec3> v, std::span<Vec3> force);

// Σ_i m_i ω² δ² R(d_i/δ): the contact springs' potential energy [J].
double smooth_collider_energy(const SmoothCollider& collider, std::span<const double> mass_kg, std::span<const Vec3> x);

// One vertex's lagged quantities (see the header note); all zero where the vertex was outside.
struct ColliderLag {
  Vec3 normal = Vec3::Zero();  // n̄
  double dashpot_kg_s = 0.0;   // m b w
  double friction_N = 0.0;     // N = μ m ω² δ P(d/δ)
};

ColliderLag lag_smooth_collider(const SmoothCollider& collider, double m, const Vec3& x);

// The vertex's terms U + D_n + D_t at x for a step of h from `start` (x_n; vbd: x̃ and ĥ) [J].
double smooth_collider_terms(const SmoothCollider& collider, const ColliderLag& lag, double m, const Vec3& x,
                             const Vec3& start, double h);

// gradient += ∇, hessian += ∇² of the vertex's terms at x.
void add_smooth_collider_derivatives(const SmoothCollider& collider, const ColliderLag& lag, double m, const Vec3& x,
                                     const Vec3& start, double h, Vec3& gradient, Mat3& hessian);

}  // namespace sim
