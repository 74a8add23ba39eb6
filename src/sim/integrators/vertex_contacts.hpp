// The smooth contact between bodies (and a body's smooth self-contact) as terms of vbd's per-vertex step energy
// (sim/integrators/vertex_block_descent.hpp).
#pragma once

#include <span>
#include <vector>

#include "sim/contact/body_collision.hpp"
#include "sim/contact/smooth_contact.hpp"
#include "sim/integrators/vertex_energy.hpp"
#include "sim/model/model.hpp"

namespace sim {

// Design note. The smooth body contact's force (sim/contact/body_collision.hpp) as energy terms, per vertex (as the
// removed newton integrator took it, docs/notes/2026-12-01-newton.md). A contact is a vertex p near
// the nearest triangle (corners k, closest point Σ w_k x_k) of another body, or of its own body outside p's rest
// neighbourhood (self-collision); its relative position r = x_p − Σ w_k x_k. With its frame (triangle, w, unit
// direction n) and its dashpot weight w_d and friction normal force N lagged, its energy is
//   E_c(r) = m ω² δ² R(d/δ) + m b w_d (n·Δr)² / (2ĥ) + N ĥ √(|v'_t|² + ε²),
//   d = δ − n·r, Δr = r − r̃, v'_t = (I − n nᵀ) Δr / ĥ                                                       [J]
// (r̃ = r at x̃, so Δr/ĥ is BDF2's relative velocity; at x = the lag point −∇E_c is add_smooth_forces' force at
// that velocity). Each of its vertices j enters r with a coefficient c_j (+1 for p, −w_k for corner k); moving x_j
// alone by Δ moves r by c_j Δ, so vertex j's block takes
//   ∇_j E_c = c_j ∇_r E_c,   H_j += c_j² K,   K = (m ω² s(d/δ) + m b w_d/ĥ) n nᵀ + friction's block    (PSD)
// and its line search E_c(r + c_j Δ) − E_c(r). Σ_j of the forces −c_j ∇_r E_c is zero (Σ c_j = 0): momentum is kept.
// The frames, w_d and N are lagged at the iterate once per sweep (lag()), so the sweeps' fixed point is BDF2 of the
// smooth contact force exactly (IPC lags its friction so: Li et al. 2020, §5).
// The vertex colouring does not separate the vertices of a contact: the sweeps visit the vertices one after another
// (Gauss–Seidel), so each sees the others' latest positions; a loop that moves a colour's vertices at once must take
// the vertices in contacts one by one (or colour the contacts too).
class VertexContacts {
 public:
  // Active when the model's bodies touch by the smooth contact and there is a pair to search (two bodies, or one
  // self-colliding body).
  void build(const Model& model);
  bool active() const { return active_; }
  // Finds the contacts at x (every vertex of the model) and lags their frames, dashpot weights and friction normal
  // forces there; `base` is x̃ and `h_hat` ĥ of the step. Reads x and base (kept as views) until the next lag.
  // With `found_at`, the contacts (nearest triangles, sides, frames) are those of the vertices at found_at instead.
  void lag(const Model& model, std::span<const Vec3> x, std::span<const Vec3> base, double h_hat,
           std::span<const Vec3> found_at = {});
  // ∇_v E and H_v of the contacts of world vertex v at the positions lag() was given (as they are now).
  void add_terms(int vertex, Vec3& gradient, Block3& hessian) const;
  // The contacts' change of E when world vertex v alone moves by step [J].
  double energy_change(int vertex, const Vec3& step) const;
  // The contacts' change of E when the vertices first_vertex .. first_vertex + motion.size() move by α motion [J].
  double motion_energy_change(int first_vertex, std::span<const Vec3> motion, double alpha) const;
  std::size_t contacts() const { return contacts_.size(); }
  // Contact c's frame, and ∇_r E_c and K at the current positions (for the joint coarse correction).
  const BodyCollider::SmoothFrame& frame(std::size_t c) const { return contacts_[c].frame; }
  void relative_derivatives(std::size_t c, Vec3& gradient, Block3& hessian) const {
    derivatives(contacts_[c], relative(contacts_[c]), gradient, hessian);
  }
  // ω = 1/τ of the contact [1/s] where a step of h from (x, v) is an impact between bodies, else 0: the vertices in or
  // reaching a skin within h (at their speed towards it) carry more normal momentum Σ m |v_rel·n| than their body would
  // at `impact_speed` [m/s] (vertex_block_descent.cpp, kBodyImpactSpeed; the floor and colliders scale theirs by τ).
  double impact_omega(const Model& model, std::span<const Vec3> x, std::span<const Vec3> v, double h,
                      double impact_speed) const;

 private:
  struct Contact {
    BodyCollider::SmoothFrame frame;
    double mass_kg = 0.0;      // m, the vertex p's
    double dashpot = 0.0;      // m b w_d [kg/s]
    double friction = 0.0;     // N [N]
    Vec3 base = Vec3::Zero();  // r̃ [m]
  };
  // r = x_p − Σ w_k x_k at the current positions [m].
  Vec3 relative(const Contact& c) const;
  // E_c at r [J].
  double energy(const Contact& c, const Vec3& r) const;
  // ∇_r E_c and K at r.
  void derivatives(const Contact& c, const Vec3& r, Vec3& gradient, Block3& hessian) const;

  bool active_ = false;
  SmoothResponse response_;
  BodyCollider collider_;
  std::vector<BodyCollider::SmoothFrame> frames_;  // scratch of lag()
  std::vector<Contact> contacts_;
  // World vertex v's part in contacts: entries [start_[v], start_[v + 1]) of contact_of_ and coefficient_.
  std::vector<int> start_, contact_of_;
  std::vector<double> coefficient_;
  std::span<const Vec3> x_, base_;
  double h_hat_ = 0.0;
  // impact_omega()'s search and its frames (scratch, kept between calls).
  mutable BodyCollider impact_collider_;
  mutable std::vector<BodyCollider::SmoothFrame> impact_frames_;
  mutable std::vector<double> approach_;  // per body [kg m/s]
};

}  // namespace sim
