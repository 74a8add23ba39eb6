// Divergence guard checks: finite values, runaway internal energy, volume inversion and collapse.
#include "sim/guard.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "sim/finite_scan.hpp"
#include "sim/forces.hpp"

namespace sim {
namespace {

struct Motion {
  Vec3 com_velocity = Vec3::Zero();
  double internal_kinetic_J = 0.0;  // Σ ½ m |v − v_com|² = Σ ½ m v² − ½ M v_com²
};

Motion motion_of(const Topology& t, std::span<const Vec3> v) {
  Vec3 momentum = Vec3::Zero();
  double kinetic = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    momentum += t.mass_kg[i] * v[i];
    kinetic += 0.5 * t.mass_kg[i] * v[i].squaredNorm();
  }
  Motion m;
  m.com_velocity = momentum / t.total_mass_kg;
  m.internal_kinetic_J = std::max(0.0, kinetic - 0.5 * t.total_mass_kg * m.com_velocity.squaredNorm());
  return m;
}

std::optional<Divergence> non_finite(int b, std::span<const Vec3> x, std::span<const Vec3> v) {
  if (all_finite(x) && all_finite(v)) return std::nullopt;  // the common case, in one vectorised pass
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (x[i].allFinite() && v[i].allFinite()) continue;
    return Divergence{b, static_cast<int>(i), x[i].allFinite() ? "has a non-finite velocity" : "has a non-finite position"};
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
                (v[fastest] - m.com_velocity).norm(), m.internal_kinetic_J, DivergenceGuard::kRunawayFactor, budget_J);
  return Divergence{b, static_cast<int>(fastest), text};
}

std::optional<Divergence> bad_volume(int b, const Body& body, std::span<const Vec3> x) {
  // Only a gas gives the volume meaning: a shell of springs alone, or free particles, may fold flat.
  if (body.params.pressure_J == 0.0 || !(body.topology.rest_volume_m3 > 0.0)) return std::nullopt;
  const double volume = enclosed_volume(body.topology.faces, x);
  const double rest = body.topology.rest_volume_m3;
  char text[160];
  if (!(volume > 0.0)) {
    std::snprintf(text, sizeof text, "volume inverted (V = %.3g m^3, rest volume V0 = %.3g m^3)", volume, rest);
    return Divergence{b, -1, text};
  }
  if (body.params.pressure_J > 0.0 && volume < DivergenceGuard::kCollapseFraction * rest) {
    std::snprintf(text, sizeof text, "volume collapsed to %.2g %% of its rest volume (V = %.3g m^3)",
                  100.0 * volume / rest, volume);
    return Divergence{b, -1, text};
  }
  return std::nullopt;
}

}  // namespace

double DivergenceGuard::budget(const Body& body, std::span<const Vec3> x, std::span<const Vec3> v) const {
  const Topology& t = body.topology;
  double kinetic = 0.0, spring = 0.0, lowest_com_y = 0.0;
  Vec3 com = Vec3::Zero();
  for (std::size_t i = 0; i < x.size(); ++i) {
    kinetic += 0.5 * t.mass_kg[i] * v[i].squaredNorm();
    com += t.mass_kg[i] * x[i];
  }
  com /= t.total_mass_kg;
  for (std::size_t e = 0; e < t.edges.size(); ++e) {
    const double stretch = (x[t.edges[e][0]] - x[t.edges[e][1]]).norm() - t.rest_length_m[e];
    spring += 0.5 * body.params.stiffness_N_per_m * stretch * stretch;  // ½ k (|d| − L0)²
  }
  double gas = 0.0;
  if (body.params.pressure_J > 0.0 && t.rest_volume_m3 > 0.0) {
    // The gas's work W = nRT ln(V_end / V_start): compressed to the collapse limit, or expanded tenfold.
    const double volume = std::max(enclosed_volume(t.faces, x), kCollapseFraction * t.rest_volume_m3);
    gas = body.params.pressure_J * (std::log(volume / (kCollapseFraction * t.rest_volume_m3)) + std::log(10.0));
  }
  if (floor_height_m_) lowest_com_y = std::max(0.0, com.y() - *floor_height_m_);
  const double fall = t.total_mass_kg * std::abs(gravity_) * lowest_com_y;  // M |g| h
  // A body at rest with no stored energy still gets a small allowance: 1 cm/s for every kilogram.
  const double floor_J = 0.5 * t.total_mass_kg * 1e-4;
  return kinetic + spring + gas + fall + floor_J;
}

std::optional<Divergence> DivergenceGuard::check_finite(std::span<const Body> bodies, std::span<const Vec3> x,
                                                        std::span<const Vec3> v) const {
  if (all_finite(x) && all_finite(v)) return std::nullopt;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const Body& body = bodies[b];
    if (auto found = non_finite(static_cast<int>(b), x.subspan(body.first_vertex, body.vertex_count),
                                v.subspan(body.first_vertex, body.vertex_count))) {
      return found;
    }
  }
  return std::nullopt;
}

std::optional<Divergence> DivergenceGuard::check(std::span<const Body> bodies, std::span<const Vec3> x,
                                                 std::span<const Vec3> v) {
  const bool take_budget = budget_J_.size() != bodies.size();
  if (take_budget) budget_J_.assign(bodies.size(), 0.0);
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const Body& body = bodies[b];
    const auto xb = x.subspan(body.first_vertex, body.vertex_count);
    const auto vb = v.subspan(body.first_vertex, body.vertex_count);
    const int index = static_cast<int>(b);
    if (auto found = non_finite(index, xb, vb)) return found;
    if (take_budget) budget_J_[b] = budget(body, xb, vb);
    const Motion m = motion_of(body.topology, vb);
    if (!(m.internal_kinetic_J <= kRunawayFactor * budget_J_[b])) return runaway(index, m, budget_J_[b], vb);
    if (auto found = bad_volume(index, body, xb)) return found;
  }
  return std::nullopt;
}

}  // namespace sim
