// The smooth body contact in vbd's per-vertex energy: the contacts' lag, each vertex's list of them, and their terms.
#include "sim/integrators/vertex_contacts.hpp"

#include <algorithm>
#include <cmath>

namespace sim {

void VertexContacts::build(const Model& model) {
  active_ = model.body_contact.contact == BodyContactModel::Smooth && searches_body_contact(model.bodies);
  if (active_) response_ = resolve_smooth_response(model.body_contact.smooth, model.body_contact.material);
  contacts_.clear();
  start_.clear();
}

void VertexContacts::lag(const Model& model, std::span<const Vec3> x, std::span<const Vec3> base, double h_hat,
                         std::span<const Vec3> found_at) {
  x_ = x;
  base_ = base;
  h_hat_ = h_hat;
  collider_.find_smooth_frames(model.bodies, found_at.empty() ? x : found_at, frames_);
  contacts_.resize(frames_.size());
  start_.assign(x.size() + 1, 0);
  for (std::size_t c = 0; c < frames_.size(); ++c) {
    Contact& contact = contacts_[c];
    contact.frame = frames_[c];
    const BodyCollider::SmoothFrame& f = contact.frame;
    const double depth = response_.smoothing_m - f.signed_distance_m;  // d = δ − s
    const bool touching = depth > 0.0;
    contact.mass_kg = model.mass_kg[static_cast<std::size_t>(f.vertex)];
    contact.dashpot =
        touching ? contact.mass_kg * response_.damping_rate * smooth_dashpot_weight(response_, depth) : 0.0;
    contact.friction =
        touching ? response_.friction * contact.mass_kg * smooth_elastic_per_mass(response_, depth) : 0.0;
    contact.base = base[static_cast<std::size_t>(f.vertex)];
    for (int k = 0; k < 3; ++k) contact.base -= f.weights[k] * base[static_cast<std::size_t>(f.corners[k])];  // r̃
    ++start_[static_cast<std::size_t>(f.vertex) + 1];
    for (const int corner : f.corners) ++start_[static_cast<std::size_t>(corner) + 1];
  }
  for (std::size_t v = 1; v < start_.size(); ++v) start_[v] += start_[v - 1];
  contact_of_.resize(static_cast<std::size_t>(start_.back()));
  coefficient_.resize(contact_of_.size());
  // Rows filled through their starts (start_[v] ends as row v's end), then shifted back by one.
  for (std::size_t c = 0; c < contacts_.size(); ++c) {
    const BodyCollider::SmoothFrame& f = contacts_[c].frame;
    const auto put = [&](int vertex, double coefficient) {
      const auto slot = static_cast<std::size_t>(start_[static_cast<std::size_t>(vertex)]++);
      contact_of_[slot] = static_cast<int>(c);
      coefficient_[slot] = coefficient;
    };
    put(f.vertex, 1.0);
    for (int k = 0; k < 3; ++k) put(f.corners[static_cast<std::size_t>(k)], -f.weights[k]);
  }
  for (std::size_t v = start_.size() - 1; v > 0; --v) start_[v] = start_[v - 1];
  start_[0] = 0;
}

Vec3 VertexContacts::relative(const Contact& c) const {
  const BodyCollider::SmoothFrame& f = c.frame;
  Vec3 r = x_[static_cast<std::size_t>(f.vertex)];
  for (int k = 0; k < 3; ++k) r -= f.weights[k] * x_[static_cast<std::size_t>(f.corners[k])];  // x_p − Σ w_k x_k
  return r;
}

double VertexContacts::energy(const Contact& c, const Vec3& r) const {
  const Vec3& n = c.frame.direction;
  const double depth = response_.smoothing_m - n.dot(r);
  const double spring = depth > 0.0 ? c.mass_kg * smooth_energy_per_mass(response_, depth) : 0.0;  // m ω² δ² R(d/δ)
  const Vec3 step = r - c.base;                                                                    // Δr [m]
  const double along = n.dot(step);
  const double dashpot = c.dashpot * along * along / (2.0 * h_hat_);  // m b w_d (n·Δr)²/(2ĥ)
  const Vec3 tangential = (step - along * n) / h_hat_;                // v'_t [m/s]
  const double eps2 = response_.slip_speed_m_per_s * response_.slip_speed_m_per_s;
  const double friction = c.friction > 0.0 ? c.friction * h_hat_ * std::sqrt(tangential.squaredNorm() + eps2) : 0.0;
  return spring + dashpot + friction;
}

void VertexContacts::derivatives(const Contact& c, const Vec3& r, Vec3& gradient, Block3& hessian) const {
  const Vec3& n = c.frame.direction;
  const double depth = response_.smoothing_m - n.dot(r);
  const Vec3 step = r - c.base;
  const double along = n.dot(step);
  gradient = (c.dashpot * along / h_hat_) * n;  // m b w_d v'_n n
  double normal = c.dashpot / h_hat_;           // m b w_d / ĥ
  if (depth > 0.0) {
    gradient -= c.mass_kg * smooth_elastic_per_mass(response_, depth) * n;             // −m ω² δ P(d/δ) n
    normal += c.mass_kg * response_.omega2 * smooth_dashpot_weight(response_, depth);  // m ω² s(d/δ)
  }
  hessian = Block3();
  hessian.add_outer(normal, n);
  if (c.friction > 0.0) {
    const Vec3 tangential = (step - along * n) / h_hat_;
    const double eps2 = response_.slip_speed_m_per_s * response_.slip_speed_m_per_s;
    const double slip = std::sqrt(tangential.squaredNorm() + eps2);
    gradient += (c.friction / slip) * tangential;  // N v'_t / r
    // (N/(ĥ r)) (I − n nᵀ − v'_t v'_tᵀ / r²): eigenvalues N ε²/(ĥ r³) along the slip, N/(ĥ r) across it, 0 along n.
    const double a = c.friction / (h_hat_ * slip);
    hessian.add_diagonal(a);
    hessian.add_outer(-a, n);
    hessian.add_outer(-a / (slip * slip), tangential);
  }
}

void VertexContacts::add_terms(int vertex, Vec3& gradient, Block3& hessian) const {
  const auto v = static_cast<std::size_t>(vertex);
  for (int e = start_[v]; e < start_[v + 1]; ++e) {
    const Contact& c = contacts_[static_cast<std::size_t>(contact_of_[static_cast<std::size_t>(e)])];
    const double coefficient = coefficient_[static_cast<std::size_t>(e)];
    Vec3 g;
    Block3 k;
    derivatives(c, relative(c), g, k);
    gradient += coefficient * g;                       // c_j ∇_r E_c
    hessian.add_scaled(coefficient * coefficient, k);  // c_j² K
  }
}

double VertexContacts::energy_change(int vertex, const Vec3& step) const {
  const auto v = static_cast<std::size_t>(vertex);
  double change = 0.0;
  for (int e = start_[v]; e < start_[v + 1]; ++e) {
    const Contact& c = contacts_[static_cast<std::size_t>(contact_of_[static_cast<std::size_t>(e)])];
    const Vec3 r = relative(c);
    change += energy(c, r + coefficient_[static_cast<std::size_t>(e)] * step) - energy(c, r);
  }
  return change;
}

double VertexContacts::motion_energy_change(int first_vertex, std::span<const Vec3> motion, double alpha) const {
  const int last = first_vertex + static_cast<int>(motion.size());
  const auto moved = [&](int vertex) { return vertex >= first_vertex && vertex < last; };
  const auto motion_of = [&](int vertex) { return alpha * motion[static_cast<std::size_t>(vertex - first_vertex)]; };
  double change = 0.0;
  for (const Contact& c : contacts_) {
    const BodyCollider::SmoothFrame& f = c.frame;
    Vec3 shift = Vec3::Zero();  // the motion of r [m]
    bool any = false;
    if (moved(f.vertex)) {
      shift += motion_of(f.vertex);
      any = true;
    }
    for (int k = 0; k < 3; ++k) {
      if (!moved(f.corners[static_cast<std::size_t>(k)])) continue;
      shift -= f.weights[k] * motion_of(f.corners[static_cast<std::size_t>(k)]);
      any = true;
    }
    if (!any) continue;
    const Vec3 r = relative(c);
    change += energy(c, r + shift) - energy(c, r);
  }
  return change;
}

double VertexContacts::impact_omega(const Model& model, std::span<const Vec3> x, std::span<const Vec3> v, double h,
                                    double impact_speed) const {
  if (!active_) return 0.0;
  impact_collider_.find_smooth_frames(model.bodies, x, impact_frames_);
  approach_.assign(model.bodies.size(), 0.0);
  for (const BodyCollider::SmoothFrame& f : impact_frames_) {
    Vec3 relative = v[static_cast<std::size_t>(f.vertex)];
    for (int k = 0; k < 3; ++k) relative -= f.weights[k] * v[static_cast<std::size_t>(f.corners[k])];
    const double towards = std::max(0.0, -relative.dot(f.direction));  // [m/s]
    if (f.signed_distance_m - h * towards >= response_.smoothing_m) continue;
    std::size_t b = 0;  // the vertex's body (the bodies' vertices are contiguous, in order)
    while (b + 1 < model.bodies.size() && model.bodies[b + 1].first_vertex <= f.vertex) ++b;
    approach_[b] += model.mass_kg[static_cast<std::size_t>(f.vertex)] * towards;
  }
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    double mass = 0.0;
    for (const double m : Model::of(model.bodies[b], model.mass_kg)) mass += m;
    if (approach_[b] > impact_speed * mass) return std::sqrt(response_.omega2);
  }
  return 0.0;
}

}  // namespace sim
