// Stable time-step estimate: the fastest modes of each body and each integrator's amplification matrix.
#include "sim/step/stability.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include <Eigen/Eigenvalues>

#include "core/errors.hpp"
#include "sim/contact/body_collision.hpp"
#include "sim/contact/smooth_contact.hpp"
#include "sim/forces/forces.hpp"

namespace sim {
namespace {

using Mat3 = Eigen::Matrix3d;

// Power iterations give λ_max from below; this margin makes the estimate conservative (the iterates
// converge to within about 1 % on icospheres, and the pressure-stretched state moves λ by a few %).
constexpr double kPowerMargin = 1.05;

// Geometric stiffness share of a stretched spring, k (1 − L0/|d|) across the spring; compressed: 0.
double geometric_share(double length, double rest_length) {
  return length > rest_length ? 1.0 - rest_length / length : 0.0;
}

// Constraint e's stiffness per unit of the edges' k: 1 on the edges, k_b / k on the bending links (then c_b / c is
// the same ratio, so the damping stays proportional, C = (c/k) K). Without springs (k ≤ 0): 1 on the edges, 0 on
// the links.
double relative_stiffness(const Body& body, std::size_t e) {
  const double k = body.params.stiffness_N_per_m;
  if (k > 0.0) return body.constraints.stiffness_N_per_m[e] / k;
  return e < body.constraints.edge_count ? 1.0 : 0.0;
}

// y = K u with k = 1 over the body's constraints: K_e = w_e [d̂d̂ᵀ + g (I − d̂d̂ᵀ)] on each (the spring's Hessian
// per unit stiffness, compressions clamped; w_e its relative_stiffness).
void spring_matvec(const Body& body, std::span<const Vec3> x, const std::vector<Vec3>& u, std::vector<Vec3>& y) {
  y.assign(u.size(), Vec3::Zero());
  const DistanceConstraints& constraints = body.constraints;
  for (std::size_t e = 0; e < constraints.size(); ++e) {
    const double weight = relative_stiffness(body, e);
    if (weight <= 0.0) continue;
    const auto [i, j] = constraints.ends[e];
    const Vec3 d = x[i] - x[j];
    const double length = d.norm();
    if (length == 0.0) continue;
    const Vec3 n = d / length;
    const Vec3 du = u[i] - u[j];
    const double g = geometric_share(length, constraints.rest_length_m[e]);
    Vec3 f = n * n.dot(du) + g * (du - n * n.dot(du));
    if (weight != 1.0) f *= weight;
    y[i] += f;
    y[j] -= f;
  }
}

// λ_max of M⁻¹K (k = 1) by power iterations with the M-weighted Rayleigh quotient uᵀKu / uᵀMu [1/kg].
double power_lambda(const Body& body, std::span<const Vec3> x) {
  const std::vector<double>& m = body.masses.kg;
  std::vector<Vec3> u(x.size()), y;
  for (std::size_t i = 0; i < u.size(); ++i) {
    const double s = static_cast<double>(i);  // deterministic start with every mode present
    u[i] = Vec3(std::sin(1.3 * s + 0.1), std::cos(2.1 * s), std::sin(0.7 * s + 1.0));
  }
  double lambda = 0.0;
  for (int it = 0; it < kPowerIterations; ++it) {
    spring_matvec(body, x, u, y);
    double uKu = 0.0, uMu = 0.0;
    for (std::size_t i = 0; i < u.size(); ++i) {
      uKu += u[i].dot(y[i]);
      uMu += m[i] * u[i].squaredNorm();
    }
    if (uMu == 0.0) break;
    lambda = std::max(lambda, uKu / uMu);
    double norm = 0.0;
    for (std::size_t i = 0; i < u.size(); ++i) {
      u[i] = y[i] / m[i];
      norm += m[i] * u[i].squaredNorm();
    }
    if (norm == 0.0) break;
    for (Vec3& ui : u) ui /= std::sqrt(norm);
  }
  return lambda;
}

// Gershgorin: every eigenvalue of M⁻¹K lies below max_i Σ_{e∋i} 2 max(1, g_e) / m_i (diagonal block
// plus off-diagonal blocks, each of norm max(1, g)) [1/kg].
double gershgorin_lambda(const Body& body, std::span<const Vec3> x) {
  const DistanceConstraints& constraints = body.constraints;
  std::vector<double> row(x.size(), 0.0);
  for (std::size_t e = 0; e < constraints.size(); ++e) {
    const double r = relative_stiffness(body, e);
    if (r <= 0.0) continue;
    const auto [i, j] = constraints.ends[e];
    const double w = 2.0 * r * std::max(1.0, geometric_share((x[i] - x[j]).norm(), constraints.rest_length_m[e]));
    row[i] += w;
    row[j] += w;
  }
  double lambda = 0.0;
  for (std::size_t i = 0; i < row.size(); ++i) lambda = std::max(lambda, row[i] / body.masses.kg[i]);
  return lambda;
}

// The gas's stiffness over the mass [1/s²]: its local (per-face) Hessian (nRT/V) ∂²V/∂x², bounded per
// vertex by (nRT/V) Σ_{f∋i} perimeter_f / 6 / m_i, plus the breathing term (nRT/V²) Σ_i |∂V/∂x_i|² / m_i.
double gas_omega2(const Body& body, std::span<const Vec3> x) {
  const Topology& t = body.topology;
  const double nRT = body.params.pressure_J;
  if (nRT == 0.0) return 0.0;
  std::vector<double> local(x.size(), 0.0);
  for (const Triangle& f : t.faces) {
    const Vec3 &a = x[f[0]], &b = x[f[1]], &c = x[f[2]];
    const double perimeter = (b - a).norm() + (c - b).norm() + (a - c).norm();
    for (int i : f) local[i] += perimeter / 6.0;
  }
  std::vector<Vec3> dV;
  volume_gradient(t.faces, x, dV);
  const double volume = guarded_volume(enclosed_volume(t.faces, x), body.rest.volume_m3);
  double local_max = 0.0, breathing = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    local_max = std::max(local_max, local[i] / body.masses.kg[i]);
    breathing += dV[i].squaredNorm() / body.masses.kg[i];
  }
  return nRT / volume * local_max + nRT / (volume * volume) * breathing;
}

// The amplification matrix of one step of size h for the mode ẍ = −μ x − γ ẋ, state (x, v, cached a).
Mat3 amplification(IntegratorKind integrator, double h, double mu, double gamma) {
  Mat3 A = Mat3::Zero();  // first-order form y' = A y on (x, v)
  A(0, 1) = 1.0;
  A(1, 0) = -mu;
  A(1, 1) = -gamma;
  const Mat3 hA = h * A;
  Mat3 G = Mat3::Zero();
  switch (integrator) {
    case IntegratorKind::Euler:
      G = Mat3::Identity() + hA;
      G(2, 2) = 0.0;
      break;
    case IntegratorKind::Symplectic:
      G(1, 0) = -h * mu, G(1, 1) = 1.0 - h * gamma;                 // v' = v + h a(x, v)
      G(0, 0) = 1.0 - h * h * mu, G(0, 1) = h * (1.0 - h * gamma);  // x' = x + h v'
      break;
    case IntegratorKind::Verlet:
      for (int col = 0; col < 3; ++col) {  // velocity_verlet.cpp applied to each basis state
        const Eigen::Vector3d y = Mat3::Identity().col(col);
        const double v_half = y[1] + 0.5 * h * y[2];
        const double x_new = y[0] + h * v_half;
        const double v_pred = v_half + 0.5 * h * y[2];
        const double a_new = -mu * x_new - gamma * v_pred;
        G.col(col) = Eigen::Vector3d(x_new, v_half + 0.5 * h * a_new, a_new);
      }
      break;
    case IntegratorKind::Rk4:
    case IntegratorKind::Rk45: {
      // Taylor polynomial of exp(hA) to 4th order; DOPRI5's is to 5th plus (hA)⁶/600 (Hairer et al. IV.2).
      const int order = integrator == IntegratorKind::Rk4 ? 4 : 5;
      Mat3 term = Mat3::Identity();
      G = Mat3::Identity();
      for (int j = 1; j <= order; ++j) {
        term = term * hA / j;
        G += term;
      }
      if (order == 5) G += term * hA / 5.0;  // term = (hA)⁵/120, so this adds (hA)⁶/600
      G(2, 2) = 0.0;
      break;
    }
    default: break;  // xpbd, vbd: stable_dt() answers without an amplification matrix
  }
  return G;
}

double spectral_radius(const Mat3& G) { return Eigen::EigenSolver<Mat3>(G, false).eigenvalues().cwiseAbs().maxCoeff(); }

// G in the dimensionless state (x, h v, h² a): the same eigenvalues, but entries of order hω instead of
// ω², which a stiff mode at a tiny h would otherwise spread over 20 orders of magnitude.
Mat3 balanced(const Mat3& G, double h) {
  const Eigen::Vector3d d(1.0, h, h * h);
  return d.asDiagonal() * G * d.cwiseInverse().asDiagonal();
}

bool stable_at(IntegratorKind integrator, double h, double mu, double gamma) {
  // ρ = 1 exactly for undamped modes of symplectic methods, and eigenvalues of the near-defective maps at
  // small h carry errors of about √ε: a mode that grows by less than 1 % in 10⁵ steps counts as stable.
  constexpr double kTolerance = 1e-7;
  return spectral_radius(balanced(amplification(integrator, h, mu, gamma), h)) <= 1.0 + kTolerance;
}

// Largest h for one mode: scan upwards geometrically from far below any limit, then bisect.
double mode_limit(IntegratorKind integrator, double mu, double gamma) {
  const double omega = std::sqrt(mu);
  // An ω of 0, infinity or NaN has no step limit that this scan can find (1e3/ω would overflow or never end it).
  if (!(omega > 0.0 && std::isfinite(1e3 / omega) && std::isfinite(1e-6 / omega))) return StabilityEstimate::kUnlimited;
  double stable = 0.0, h = 1e-6 / omega;  // below this the eigenvalues of G lose their accuracy
  // From 1e-6/ω to 1e3/ω in steps of 1.25: 93 steps; the count bounds the scan whatever the arithmetic does.
  constexpr int kScanSteps = 94;
  int scanned = 0;
  while (stable_at(integrator, h, mu, gamma)) {
    stable = h;
    h *= 1.25;
    if (h > 1e3 / omega || ++scanned > kScanSteps) return StabilityEstimate::kUnlimited;
  }
  if (stable == 0.0) return 0.0;
  double unstable = h;
  for (int it = 0; it < 40; ++it) {
    const double mid = 0.5 * (stable + unstable);
    (stable_at(integrator, mid, mu, gamma) ? stable : unstable) = mid;
  }
  return stable;
}

}  // namespace

double ModeBounds::omega_max() const { return std::sqrt(omega2_springs + omega2_gas + omega2_contact); }

BodyStats body_stats(const Body& body, std::span<const Vec3> x) {
  const Topology& t = body.topology;
  BodyStats s;
  s.vertices = body.vertex_count;
  s.edges = static_cast<int>(t.edges.size());
  s.faces = static_cast<int>(t.faces.size());
  std::vector<int> valence(x.size(), 0);
  s.edge_min_m = std::numeric_limits<double>::infinity();
  for (const auto& [i, j] : t.edges) {
    ++valence[i], ++valence[j];
    const double length = (x[i] - x[j]).norm();
    s.edge_min_m = std::min(s.edge_min_m, length);
    s.edge_max_m = std::max(s.edge_max_m, length);
  }
  s.valence_min = *std::min_element(valence.begin(), valence.end());
  s.valence_max = *std::max_element(valence.begin(), valence.end());
  s.mass_min_kg = *std::min_element(body.masses.kg.begin(), body.masses.kg.end());
  s.mass_max_kg = *std::max_element(body.masses.kg.begin(), body.masses.kg.end());
  s.rest_volume_m3 = body.rest.volume_m3;
  return s;
}

ModeBounds mode_bounds(const Body& body, std::span<const Vec3> x) {
  ModeBounds b;
  b.lambda_max_per_kg = power_lambda(body, x);
  b.lambda_gershgorin_per_kg = gershgorin_lambda(body, x);
  const double lambda = std::min(kPowerMargin * b.lambda_max_per_kg, b.lambda_gershgorin_per_kg);
  b.omega2_springs = body.params.stiffness_N_per_m * lambda;
  b.omega2_gas = gas_omega2(body, x);
  b.damping_rate = body.params.damping_N_s_per_m * lambda;
  return b;
}

double stable_dt(IntegratorKind integrator, const ModeBounds& bounds) {
  const double mu_max = bounds.omega2_springs + bounds.omega2_gas + bounds.omega2_contact;
  if (integrator == IntegratorKind::Xpbd) {
    // Springs and dampers as compliant constraints, which for one mode is backward Euler on them. The gas (and a
    // smooth contact) explicit as symplectic Euler takes them (xpbd's prediction is a symplectic-Euler kick and drift).
    const double explicit_omega2 = bounds.omega2_gas + bounds.omega2_contact;
    return explicit_omega2 > 0.0 ? 2.0 / std::sqrt(explicit_omega2) : StabilityEstimate::kUnlimited;
  }
  if (integrator == IntegratorKind::Vbd) {
    // Every force implicit: BDF2 (and backward Euler, its first step) is A-stable, |amplification| < 1 for every
    // mode with Re λ ≤ 0 at every h, and each vertex move lowers the step's energy. No
    // mode limits h; what does is accuracy (numerical damping ∝ h ω² of each mode) and, with a floor, the
    // post-step contact's travel per step (travel_dt_s, applied to every integrator).
    return StabilityEstimate::kUnlimited;
  }
  if (mu_max == 0.0 && bounds.damping_rate == 0.0) return StabilityEstimate::kUnlimited;  // free particles
  // Forward Euler without dampers: ρ² = 1 + h²ω² > 1 at every h (the tolerance above would hide it).
  if (integrator == IntegratorKind::Euler && bounds.damping_rate == 0.0) return 0.0;
  const double margin = integrator == IntegratorKind::Euler ? kSharpLimitMargin : 1.0;
  // Modes from λ_max down to 1e-6 λ_max, with μ and γ both proportional to λ.
  double limit = StabilityEstimate::kUnlimited;
  constexpr int kSamples = 25;
  for (int s = 0; s < kSamples; ++s) {
    const double share = std::pow(1e-6, static_cast<double>(s) / (kSamples - 1));
    const double mu = std::max(share * mu_max, 1e-300);
    limit = std::min(limit, mode_limit(integrator, mu, share * bounds.damping_rate));
    if (limit == 0.0) break;
  }
  return margin * limit;
}

namespace {

// The height a falling vertex may reach a contact surface at [m]: the floor's; without a floor the lowest of the
// colliders (a plane's point, a bounded shape's lowest extent); none without either.
std::optional<double> lowest_contact_height(const Model& model) {
  if (model.floor) return model.floor->height_m;
  std::optional<double> lowest;
  for (const Collider& collider : model.colliders) {
    Vec3 lo, hi;
    const ColliderGeometry geometry = collider_at(collider, 0.0);  // a keyframed one: where it starts
    const double height = world_bounds(geometry, lo, hi) ? lo.y() : geometry.position_m.y();
    lowest = lowest ? std::min(*lowest, height) : height;
  }
  return lowest;
}

}  // namespace

StabilityEstimate estimate_stability(const Model& model, const State& state, bool modes) {
  StabilityEstimate estimate;
  if (modes) {
    estimate = estimate_stability(model.bodies, state.x);
  } else {
    estimate.stable_dt_s.fill(StabilityEstimate::kUnlimited);
  }
  for (const Vec3& v : state.v) estimate.impact_speed_m_per_s = std::max(estimate.impact_speed_m_per_s, v.norm());
  const std::optional<double> ground = lowest_contact_height(model);
  if (!ground) {
    scale_for_contacts(estimate, model);
    return estimate;
  }
  const double g = model.gravity_m_per_s2.norm();
  // A keyframed collider's fastest point meets a vertex at up to its speed more.
  double collider_speed = 0.0;
  for (const Collider& collider : model.colliders) {
    collider_speed = std::max(collider_speed, fastest_point_speed(collider.motion, collider.geometry.world_reach_m));
  }
  for (const Body& body : model.bodies) {
    const auto x = model.of(body, state.x);
    const auto v = model.of(body, state.v);
    double speed = collider_speed, height = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      speed = std::max(speed, v[i].norm());
      height = std::max(height, x[i].y() - *ground);
    }
    speed += std::sqrt(2.0 * g * std::max(0.0, height));  // m/s, v² = 2 g h
    estimate.impact_speed_m_per_s = std::max(estimate.impact_speed_m_per_s, speed);
    if (speed > 0.0) {
      const double travel = kTravelFraction * body_stats(body, x).edge_min_m / speed;
      estimate.travel_dt_s = std::min(estimate.travel_dt_s, travel);
    }
  }
  scale_for_contacts(estimate, model);
  for (double& dt : estimate.stable_dt_s) dt = std::min(dt, estimate.travel_dt_s);
  return estimate;
}

namespace {

// A smooth contact in every body's bounds, and each integrator's limit taken again from them. Its dashpot
// adds 2ζω to the damping rate, and so does its regularised friction while a vertex nearly sticks:
// ∂f_t/∂v_t = μ N / ε per unit mass, with N the contact spring's force per unit mass at the depth an impact at
// the estimate's speed reaches, about v τ (at least the smoothing depth δ).
void add_smooth_contact(StabilityEstimate& estimate, const SmoothResponse& contact) {
  const double tau = 1.0 / std::sqrt(contact.omega2);
  const double depth = std::max(contact.smoothing_m, estimate.impact_speed_m_per_s * tau);
  const double friction_rate = contact.friction * smooth_elastic_per_mass(contact, depth) / contact.slip_speed_m_per_s;
  for (ModeBounds& b : estimate.bodies) {
    b.omega2_contact += contact.omega2;
    b.damping_rate += contact.damping_rate + friction_rate;
    for (const IntegratorInfo& integrator : kIntegrators) {
      double& limit = estimate.stable_dt_s[static_cast<int>(integrator.kind)];
      limit = std::min(limit, stable_dt(integrator.kind, b));
    }
  }
}

}  // namespace

namespace {

// The margins a post-step projection asks of the explicit integrators (the floor's friction or paper contact).
void scale_for_projection(StabilityEstimate& estimate) {
  for (const IntegratorInfo& integrator : kIntegrators) {
    if (integrator.explicit_springs) estimate.stable_dt_s[static_cast<int>(integrator.kind)] *= kContactMargin;
  }
}

// What the paper's reflection asks besides (symplectic Euler's and forward Euler's limits).
void scale_for_paper_projection(StabilityEstimate& estimate) {
  estimate.stable_dt_s[static_cast<int>(IntegratorKind::Symplectic)] *= kSymplecticProjectionFactor;
  double& euler = estimate.stable_dt_s[static_cast<int>(IntegratorKind::Euler)];
  for (const ModeBounds& b : estimate.bodies) {
    if (b.damping_rate == 0.0 || b.omega2_springs == 0.0) continue;            // no dampers: already 0 (unstable)
    const double c_over_k = b.damping_rate / b.omega2_springs;                 // γ/ω² = cλ/(kλ) [s]
    const double zeta = b.damping_rate / (2.0 * std::sqrt(b.omega2_springs));  // of the fastest mode
    euler = std::min(
        euler, c_over_k * (zeta < kPaperEulerZeta ? kPaperEulerFractionLightDamping : kPaperEulerFractionHeavyDamping));
  }
}

}  // namespace

void scale_for_floor_contact(StabilityEstimate& estimate, const Floor& floor) {
  if (floor.contact == FloorContact::Smooth) {
    add_smooth_contact(estimate,
                       resolve_smooth_floor(floor));  // a force like the others: no projection, no projection margins
    return;
  }
  scale_for_projection(estimate);
  if (floor.contact == FloorContact::Paper) scale_for_paper_projection(estimate);
}

void scale_for_collider_contacts(StabilityEstimate& estimate, const Model& model) {
  bool margins = model.floor && model.floor->contact != FloorContact::Smooth;  // the floor's already taken
  bool paper_margins = model.floor && model.floor->contact == FloorContact::Paper;
  for (const Collider& collider : model.colliders) {
    if (collider.contact == FloorContact::Smooth) {
      add_smooth_contact(estimate, resolve_smooth_response(collider.smooth, collider.material));
      continue;
    }
    // A projection's margins once per kind, as the floor's: another projecting surface does not shrink them again.
    if (!margins) scale_for_projection(estimate);
    if (collider.contact == FloorContact::Paper && !paper_margins) scale_for_paper_projection(estimate);
    margins = true;
    paper_margins = paper_margins || collider.contact == FloorContact::Paper;
  }
}

void scale_for_contacts(StabilityEstimate& estimate, const Model& model) {
  if (model.floor) scale_for_floor_contact(estimate, *model.floor);
  scale_for_collider_contacts(estimate, model);
  if (searches_body_contact(model.bodies) && model.body_contact.contact == BodyContactModel::Smooth) {
    add_smooth_contact(estimate, resolve_smooth_response(model.body_contact.smooth, model.body_contact.material));
  }
}

StabilityEstimate estimate_stability(std::span<const Body> bodies, std::span<const Vec3> x) {
  StabilityEstimate estimate;
  estimate.stable_dt_s.fill(StabilityEstimate::kUnlimited);
  double fastest = -1.0;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const Body& body = bodies[b];
    const ModeBounds bounds = mode_bounds(body, Model::of(body, x));
    estimate.bodies.push_back(bounds);
    if (bounds.omega_max() > fastest) fastest = bounds.omega_max(), estimate.limiting_body = static_cast<int>(b);
    for (const IntegratorInfo& integrator : kIntegrators) {
      double& limit = estimate.stable_dt_s[static_cast<int>(integrator.kind)];
      limit = std::min(limit, stable_dt(integrator.kind, bounds));
    }
  }
  return estimate;
}

double auto_dt(const StabilityEstimate& estimate, IntegratorKind integrator, double frame_interval_s,
               const std::string& scene_file) {
  const double limit = estimate.stable_dt(integrator);
  if (limit == 0.0) {
    throw softbody::InputError(scene_file + ": solver.dt: \"auto\" found no stable dt for " + to_string(integrator) +
                               " (forward Euler needs dampers: give every body damping > 0, or choose "
                               "solver.integrator symplectic, verlet, rk4, rk45 or vbd)");
  }
  if (limit == StabilityEstimate::kUnlimited) return frame_interval_s / 4.0;
  return std::min(kAutoDtSafety * limit, frame_interval_s);
}

double xpbd_bias_dt(double omega_max, int vertices) {
  if (omega_max <= 0.0) return StabilityEstimate::kUnlimited;
  const double mesh = std::pow(std::max(vertices, 1) / 642.0, kXpbdBiasMeshPower);
  const double phase = std::pow(kXpbdVolumeBias / (kXpbdBiasScale * mesh), 1.0 / kXpbdBiasPower);  // h ω_max
  return phase / omega_max;
}

double xpbd_carried_dt(double omega_max) {
  if (omega_max <= 0.0) return StabilityEstimate::kUnlimited;
  return kXpbdCarriedPhaseLimit / omega_max;
}

bool contact_after_step(const Model& model) {
  bool projected = model.floor && model.floor->contact != FloorContact::Smooth;
  for (const Collider& collider : model.colliders) {  // a keyframed collider's projection: the same travel limit
    projected = projected || (collider.motion.moving() && collider.contact != FloorContact::Smooth);
  }
  // The impulse contact between bodies and a body's impulse self-contact: a fold's halves or two bodies must not pass
  // each other within one step.
  return projected || (searches_body_contact(model.bodies) && model.body_contact.contact == BodyContactModel::Impulse);
}

namespace {

// The fewest substeps per frame interval whose step is at most h, within 1..kXpbdMostAutoSubsteps.
int substeps_of_at_most(double frame_interval_s, double h) {
  return static_cast<int>(
      std::clamp(std::ceil(frame_interval_s / h * (1.0 - 1e-9)), 1.0, double{kXpbdMostAutoSubsteps}));
}

// vbd's smooth contacts are inside its energy and its steps shrink around their impacts: only a projection after the
// step holds it to the travel limit.
bool travel_binds(IntegratorKind integrator, const Model& model) {
  return integrator != IntegratorKind::Vbd || contact_after_step(model);
}

}  // namespace

int travel_substeps(IntegratorKind integrator, const Model& model, const StabilityEstimate& estimate,
                    double frame_interval_s) {
  if (!travel_binds(integrator, model)) return 1;
  return substeps_of_at_most(frame_interval_s, std::min(frame_interval_s, estimate.travel_dt_s));
}

int auto_substeps(IntegratorKind integrator, const Model& model, const StabilityEstimate& estimate,
                  double frame_interval_s) {
  double h = travel_binds(integrator, model) ? std::min(frame_interval_s, estimate.travel_dt_s)
                                             : std::min(frame_interval_s, kVbdLongestAutoStep);
  const bool xpbd = integrator == IntegratorKind::Xpbd;
  for (std::size_t b = 0; xpbd && b < estimate.bodies.size() && b < model.bodies.size(); ++b) {
    h = std::min(h, xpbd_carried_dt(estimate.bodies[b].omega_max()));
  }
  return substeps_of_at_most(frame_interval_s, h);
}

}  // namespace sim
