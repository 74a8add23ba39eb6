// Divergence guard checks: finite values, runaway internal energy, volume inversion and collapse.
#include "sim/step/guard.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "sim/contact/collider_shape.hpp"
#include "sim/forces/energy.hpp"
#include "sim/forces/forces.hpp"
#include "sim/step/finite_scan.hpp"

namespace sim {
namespace {

struct Motion {
  Vec3 com_velocity = Vec3::Zero();
  double internal_kinetic_J = 0.0;  // Σ ½ m |v − v_com|² = Σ ½ m v² − ½ M v_com²
};

Motion motion_of(const Body& body, std::span<const Vec3> v) {
  Motion m;
  m.com_velocity = momentum(body, v) / body.masses.total_kg;
  const double kinetic = kinetic_energy(body, v);
  m.internal_kinetic_J = std::max(0.0, kinetic - 0.5 * body.masses.total_kg * m.com_velocity.squaredNorm());
  return m;
}

std::optional<Divergence> non_finite(int b, std::span<const Vec3> x, std::span<const Vec3> v) {
  if (all_finite(x) && all_finite(v)) return std::nullopt;  // the common case, in one vectorised pass
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (x[i].allFinite() && v[i].allFinite()) continue;
    if (!x[i].allFinite())
      return Divergence{DivergenceKind::NonFinitePosition, b, static_cast<int>(i), "has a non-finite position"};
    return Divergence{DivergenceKind::NonFiniteVelocity, b, static_cast<int>(i), "has a non-finite velocity"};
  }
  return std::nullopt;
}

// The vertex moving fastest relative to the body's centre of mass, for the runaway message.
Divergence runaway(int b, const Motion& m, double budget_J, std::span<const Vec3> v) {
  std::size_t fastest = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if ((v[i] - m.com_velocity).squaredNorm() > (v[fastest] - m.com_velocity).squaredNorm()) fastest = i;
  }
  char text[200];
  std::snprintf(text, sizeof text,
                "runaway speed: %.3g m/s relative to the body (internal kinetic energy %.3g J > %.0f x the %.3g J "
                "the body started with)",
                (v[fastest] - m.com_velocity).norm(), m.internal_kinetic_J, kRunawayFactor, budget_J);
  return Divergence{DivergenceKind::RunawayEnergy, b, static_cast<int>(fastest), text};
}

std::optional<Divergence> bad_volume(int b, const Body& body, std::span<const Vec3> x) {
  // Only a gas gives the volume meaning: a shell of springs alone, or free particles, may fold flat.
  if (body.params.pressure_J == 0.0 || !(body.rest.volume_m3 > 0.0)) return std::nullopt;
  const double volume = enclosed_volume(body.topology.faces, x);
  const double rest = body.rest.volume_m3;
  char text[160];
  if (!(volume > 0.0)) {
    std::snprintf(text, sizeof text, "volume inverted (V = %.3g m^3, rest volume V0 = %.3g m^3)", volume, rest);
    return Divergence{DivergenceKind::VolumeInverted, b, -1, text};
  }
  if (body.params.pressure_J > 0.0 && volume < kCollapseFraction * rest) {
    std::snprintf(text, sizeof text, "volume collapsed to %.2g %% of its rest volume (V = %.3g m^3)",
                  100.0 * volume / rest, volume);
    return Divergence{DivergenceKind::VolumeCollapsed, b, -1, text};
  }
  return std::nullopt;
}

// How far a body's centre may fall before something stops it [m]: to the floor; with colliders, also to each one's
// lowest point along gravity (a bounded shape's world box corner, a plane's position).
double fall_height(const Model& model, const Vec3& com) {
  double height = model.floor ? std::max(0.0, com.y() - model.floor->height_m) : 0.0;
  const double g = model.gravity_m_per_s2.norm();
  if (model.colliders.empty() || g == 0.0) return height;
  const Vec3 down = model.gravity_m_per_s2 / g;
  for (const Collider& collider : model.colliders) {
    const ColliderGeometry geometry = collider_at(collider, 0.0);  // a keyframed one: where it starts
    Vec3 lowest = geometry.position_m, lo, hi;
    if (world_bounds(geometry, lo, hi)) {
      for (int k = 0; k < 3; ++k) lowest[k] = down[k] > 0.0 ? hi[k] : lo[k];
    }
    height = std::max(height, (lowest - com).dot(down));
  }
  return height;
}

// The energy budget of a body in this state [J] (check 2).
double energy_budget(const Model& model, const Body& body, std::span<const Vec3> x, std::span<const Vec3> v,
                     double gravity_m_per_s2) {
  const double kinetic = kinetic_energy(body, v);
  const Vec3 com = centre_of_mass(body, x);
  const double spring = spring_energy(body, x);
  double gas = 0.0;
  if (body.params.pressure_J > 0.0 && body.rest.volume_m3 > 0.0) {
    // The gas's work W = nRT ln(V_end / V_start): compressed to the collapse limit, or expanded tenfold.
    const double collapsed = kCollapseFraction * body.rest.volume_m3;
    const double volume = std::max(enclosed_volume(body.topology.faces, x), collapsed);
    gas = body.params.pressure_J * (std::log(volume / collapsed) + std::log(10.0));
  }
  const double height = fall_height(model, com);
  const double fall = body.masses.total_kg * gravity_m_per_s2 * height;  // M |g| h
  // A body at rest with no stored energy still gets a small allowance: 1 cm/s for every kilogram.
  const double allowance = 0.5 * body.masses.total_kg * 1e-4;
  // A moving collider gives energy: a body hit by its fastest point u may leave at up to 2u, ½ M (2u)².
  double pushed = 0.0;
  for (const Collider& collider : model.colliders) {
    const double u = fastest_point_speed(collider.motion, collider.geometry.world_reach_m);
    pushed += 2.0 * body.masses.total_kg * u * u;
  }
  return kinetic + spring + gas + fall + allowance + pushed;
}

}  // namespace

std::optional<Divergence> check_finite(const Model& model, const State& state) {
  if (all_finite(state.x) && all_finite(state.v)) return std::nullopt;
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const Body& body = model.bodies[b];
    if (auto found = non_finite(static_cast<int>(b), model.of(body, state.x), model.of(body, state.v))) return found;
  }
  return std::nullopt;
}

std::optional<Divergence> check_all(const Model& model, State& state) {
  std::vector<double>& budget = state.guard.budget_J;
  const bool take_budget = budget.size() != model.bodies.size();
  if (take_budget) budget.assign(model.bodies.size(), 0.0);
  const double g = model.gravity_m_per_s2.norm();
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const Body& body = model.bodies[b];
    const auto x = model.of(body, state.x), v = model.of(body, state.v);
    const int index = static_cast<int>(b);
    if (auto found = non_finite(index, x, v)) return found;
    if (take_budget) budget[b] = energy_budget(model, body, x, v, g);
    const Motion m = motion_of(body, v);
    if (!(m.internal_kinetic_J <= kRunawayFactor * budget[b])) return runaway(index, m, budget[b], v);
    if (auto found = bad_volume(index, body, x)) return found;
  }
  return std::nullopt;
}

}  // namespace sim
