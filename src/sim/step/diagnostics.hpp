// Per-body measurements of a state: centre of mass, volume, and every energy term.
#pragma once

#include "sim/model/model.hpp"
#include "sim/model/state.hpp"

namespace sim {

struct BodyDiagnostics {
  Vec3 com_m = Vec3::Zero();  // centre of mass
  Vec3 com_velocity_m_per_s = Vec3::Zero();
  Vec3 momentum_kg_m_per_s = Vec3::Zero();
  double volume_m3 = 0.0;        // signed enclosed volume
  double kinetic_J = 0.0;        // Σ ½ m v²
  double gravitational_J = 0.0;  // −Σ m g·x (zero at y = 0 for g along −y)
  double spring_J = 0.0;         // Σ ½ k (|d| − L0)², the bending links' ½ k_b (|d| − ℓ0)² with it
  double gas_J = 0.0;            // −nRT ln(V / V0)
  double contact_J = 0.0;        // the smooth contacts' springs: the floor's, and this body's vertices'
                                 // in other bodies (0 with the other contacts)
  double min_y_m = 0.0;          // lowest vertex
  double total_J() const { return kinetic_J + gravitational_J + spring_J + gas_J + contact_J; }
};

BodyDiagnostics diagnose(const Body& body, std::span<const Vec3> x, std::span<const Vec3> v, const Vec3& gravity);

// Diagnostics of body `index` of the model in `state` (with the smooth floor contact's energy).
BodyDiagnostics diagnose(const Model& model, const State& state, std::size_t index);

}  // namespace sim
