// The smooth body contact's spring, dashpot and friction as incremental-potential terms (lagged frames).
#include "sim/contact/body_contact_potential.hpp"

#include <cmath>

namespace sim {

void BodyContactPotential::build(const Model& model) {
  active_ = model.body_contact.contact == BodyContactModel::Smooth && searches_body_contact(model.bodies);
  if (active_) response_ = resolve_smooth_response(model.body_contact.smooth, model.body_contact.material);
  frames_.clear();
  lagged_.clear();
  terms_.clear();
}

void BodyContactPotential::lag(const Model& model, std::span<const Vec3> x) {
  if (!active_) return;
  collider_.find_smooth_frames(model.bodies, x, frames_);
  lagged_.resize(frames_.size());
  for (std::size_t c = 0; c < frames_.size(); ++c) {
    const double depth = response_.smoothing_m - frames_[c].signed_distance_m;  // d = δ − s
    const bool touching = depth > 0.0;
    const double m = model.mass_kg[static_cast<std::size_t>(frames_[c].vertex)];
    lagged_[c].dashpot_weight = touching ? smooth_dashpot_weight(response_, depth) : 0.0;
    lagged_[c].friction_normal = touching ? response_.friction * m * smooth_elastic_per_mass(response_, depth) : 0.0;
  }
}

Vec3 BodyContactPotential::relative(std::size_t c, std::span<const Vec3> x) const {
  const BodyCollider::SmoothFrame& f = frames_[c];
  Vec3 r = x[static_cast<std::size_t>(f.vertex)];
  for (int k = 0; k < 3; ++k) r -= f.weights[k] * x[static_cast<std::size_t>(f.corners[k])];  // x_p − Σ w_k x_k
  return r;
}

double BodyContactPotential::energy(const Model& model, std::span<const Vec3> x, std::span<const Vec3> start,
                                    double& scale) const {
  if (!active_) return 0.0;
  const double eps2 = response_.slip_speed_m_per_s * response_.slip_speed_m_per_s;
  double total = 0.0, size = 0.0;
  for (std::size_t c = 0; c < frames_.size(); ++c) {
    const Vec3& n = frames_[c].direction;
    const double m = model.mass_kg[static_cast<std::size_t>(frames_[c].vertex)];
    const double depth = response_.smoothing_m - n.dot(relative(c, x));
    const double spring = depth > 0.0 ? m * smooth_energy_per_mass(response_, depth) : 0.0;  // m ω² δ² R(d/δ)
    const Vec3 step = relative(c, x) - relative(c, start);                                   // J ΔX [m]
    const double along = n.dot(step);
    const double dashpot = m * response_.damping_rate * lagged_[c].dashpot_weight * along * along / (2.0 * h_);
    const Vec3 tangential = (step - along * n) / h_;  // v'_t [m/s]
    const double friction = lagged_[c].friction_normal * h_ * std::sqrt(tangential.squaredNorm() + eps2);
    total += spring + dashpot + friction;
    size += spring + dashpot + friction;
  }
  scale += size;
  return total;
}

void BodyContactPotential::add_term(std::size_t c, double coefficient, const Vec3& axis) {
  if (!(coefficient > 0.0)) return;
  const BodyCollider::SmoothFrame& f = frames_[c];
  const Vec3 u = std::sqrt(coefficient) * axis;
  terms_.push_back(Term{{f.vertex, f.corners[0], f.corners[1], f.corners[2]},
                        {u, Vec3(-f.weights[0] * u), Vec3(-f.weights[1] * u), Vec3(-f.weights[2] * u)}});  // √κ Jᵀ e
}

void BodyContactPotential::add_derivatives(const Model& model, std::span<const Vec3> x, std::span<const Vec3> start,
                                           Eigen::VectorXd& gradient) {
  terms_.clear();
  if (!active_) return;
  const double eps2 = response_.slip_speed_m_per_s * response_.slip_speed_m_per_s;
  for (std::size_t c = 0; c < frames_.size(); ++c) {
    const BodyCollider::SmoothFrame& f = frames_[c];
    const Vec3& n = f.direction;
    const double m = model.mass_kg[static_cast<std::size_t>(f.vertex)];
    const double depth = response_.smoothing_m - n.dot(relative(c, x));
    const Vec3 step = relative(c, x) - relative(c, start);
    const double along = n.dot(step);
    const double dashpot = m * response_.damping_rate * lagged_[c].dashpot_weight;  // m b w_d [kg/s]
    const Vec3 tangential = (step - along * n) / h_;
    const double r = std::sqrt(tangential.squaredNorm() + eps2);
    const double normal = lagged_[c].friction_normal;
    // ∇ in the relative coordinates: −m ω² δ P(d/δ) n + m b w_d v'_n n + N v'_t / r (= −f), spread by Jᵀ.
    Vec3 g = (dashpot * along / h_) * n + (normal / r) * tangential;
    if (depth > 0.0) g -= m * smooth_elastic_per_mass(response_, depth) * n;
    gradient.segment<3>(3 * f.vertex) += g;
    for (int k = 0; k < 3; ++k) gradient.segment<3>(3 * f.corners[k]) -= f.weights[k] * g;
    // K = (m ω² s(d/δ) + m b w_d / h) n nᵀ + friction's two tangent directions (see the design note).
    const double spring = depth > 0.0 ? m * response_.omega2 * smooth_dashpot_weight(response_, depth) : 0.0;
    add_term(c, spring + dashpot / h_, n);
    if (normal > 0.0) {
      const double slip = tangential.norm();
      Vec3 along_slip = slip > 0.0 ? Vec3(tangential / slip) : n.unitOrthogonal();
      const Vec3 across_slip = n.cross(along_slip);
      add_term(c, normal * eps2 / (h_ * r * r * r), along_slip);  // N ε² / (h r³)
      add_term(c, normal / (h_ * r), across_slip);                // N / (h r)
    }
  }
}

}  // namespace sim
