// The incremental potential's terms: one pass over vertices (inertia, gravity), edges (springs, dampers, the
// gas's face curvature) and faces (the gas's volume and gradient).
#include "sim/integrators/incremental_potential.hpp"

#include <cmath>
#include <map>
#include <utility>

#include "sim/forces/energy.hpp"
#include "sim/forces/forces.hpp"
#include "sim/forces/spring_jacobian.hpp"

namespace sim {
namespace {

using Mat3 = Eigen::Matrix3d;

// [w]×, the matrix of w × ·.
Mat3 cross_matrix(const Vec3& w) {
  Mat3 m;
  m << 0.0, -w.z(), w.y(), w.z(), 0.0, -w.x(), -w.y(), w.x(), 0.0;
  return m;
}

}  // namespace

void IncrementalPotential::build(const Model& model) {
  pairs_.clear();
  rest_length_m_.clear();
  edges_.clear();
  gas_.clear();
  area_sums_.clear();
  gas_curvature_.assign(model.bodies.size(), 0.0);
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const Body& body = model.bodies[b];
    const int first = body.first_vertex;
    std::map<std::pair<int, int>, int> across;  // directed edge (a, b) of a face → the face's third vertex
    for (const auto& [a, bb, c] : body.topology.faces) {
      across[{a, bb}] = c;
      across[{bb, c}] = a;
      across[{c, a}] = bb;
    }
    const DistanceConstraints& constraints = body.constraints;  // the edges, then the bending links
    for (std::size_t e = 0; e < constraints.size(); ++e) {
      const auto [i, j] = constraints.ends[e];
      pairs_.push_back({first + i, first + j});
      rest_length_m_.push_back(constraints.rest_length_m[e]);
      Edge edge;
      edge.body = static_cast<int>(b);
      edge.across_ij = edge.across_ji = -1;
      if (e < constraints.edge_count) {  // a mesh edge has faces across it; a bending link none
        const auto ij = across.find({i, j}), ji = across.find({j, i});
        // A closed, consistently wound mesh has both; without one side the edge gets no curvature term.
        edge.across_ij = ij == across.end() ? -1 : first + ij->second;
        edge.across_ji = ji == across.end() ? -1 : first + ji->second;
      }
      edge.stiffness_N_per_m = constraints.stiffness_N_per_m[e];
      edge.damping_N_s_per_m = constraints.damping_N_s_per_m[e];
      edges_.push_back(edge);
    }
    if (body.params.pressure_J != 0.0) {
      gas_.push_back({static_cast<int>(b), std::vector<Vec3>(static_cast<std::size_t>(body.vertex_count))});
      area_sums_.emplace_back(static_cast<std::size_t>(body.vertex_count));
    }
  }
  damper_axis_.resize(edges_.size());
  floor_.build(model);
  colliders_.build(model);
  contact_.build(model);
}

void IncrementalPotential::begin_step(const Model& model, const State& start, double h) {
  h_ = h;
  start_x_ = start.x;  // sized on the first step, then copied in place
  predicted_x_.resize(start.x.size());
  for (std::size_t i = 0; i < start.x.size(); ++i) predicted_x_[i] = start.x[i] + h * start.v[i];
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    const Vec3 d = start.x[pairs_[e][0]] - start.x[pairs_[e][1]];
    const double length = d.norm();
    damper_axis_[e] = length > 0.0 ? Vec3(d / length) : Vec3::Zero();
  }
  floor_.begin_step(h);
  floor_.lag(model, predicted_x_);
  colliders_.begin_step(model, start.time_s + h, h);
  colliders_.lag(model, predicted_x_);
  contact_.begin_step(h);
  contact_.lag(model, predicted_x_);
}

double IncrementalPotential::energy(const Model& model, std::span<const Vec3> x, double& scale) {
  const std::vector<double>& m = model.mass_kg;
  const Vec3& g = model.gravity_m_per_s2;
  double inertial = 0.0, gravity = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    inertial += m[i] * (x[i] - predicted_x_[i]).squaredNorm();  // Σ m |x − x̂|²
    gravity -= m[i] * g.dot(x[i] - start_x_[i]);                // −Σ m g·(x − x_n)
  }
  double springs = 0.0, dampers = 0.0;
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    const auto [i, j] = pairs_[e];
    const Edge& edge = edges_[e];
    const double stretch = (x[i] - x[j]).norm() - rest_length_m_[e];
    springs += edge.stiffness_N_per_m * stretch * stretch;  // Σ k (|d| − L0)², halved below
    const double along = ((x[i] - start_x_[i]) - (x[j] - start_x_[j])).dot(damper_axis_[e]);
    dampers += edge.damping_N_s_per_m * along * along;  // Σ c (Δx_ij·d̂)², over 2h below
  }
  double gas = 0.0, gas_size = 0.0;
  for (const GasTerm& term : gas_) {
    const Body& body = model.bodies[term.body];
    const double energy = gas_energy(body, enclosed_volume(body.topology.faces, model.of(body, x)));
    gas += energy;
    gas_size += std::abs(energy);
  }
  const double inertial_J = inertial / (2.0 * h_ * h_), springs_J = 0.5 * springs, dampers_J = dampers / (2.0 * h_);
  double floor_size = 0.0;
  double floor = floor_.energy(model, x, start_x_, floor_size);
  if (colliders_.active()) floor += colliders_.energy(model, x, start_x_, floor_size);
  double contact_size = 0.0;
  const double contact = contact_.energy(model, x, start_x_, contact_size);
  scale = inertial_J + std::abs(gravity) + springs_J + dampers_J + gas_size + floor_size + contact_size;
  return inertial_J + gravity + springs_J + dampers_J + gas + floor + contact;
}

void IncrementalPotential::update_lags(const Model& model, std::span<const Vec3> x) {
  floor_.lag(model, x);
  colliders_.lag(model, x);
  contact_.lag(model, x);
}

double IncrementalPotential::gas_face_pass(const Model& model, std::size_t gas, std::span<const Vec3> x) {
  const Body& body = model.bodies[gas_[gas].body];
  const double volume = volume_and_area_sums(body.topology.faces, model.of(body, x), area_sums_[gas]);
  return guarded_volume(volume, body.rest.volume_m3);
}

void IncrementalPotential::assemble(const Model& model, std::span<const Vec3> x, Hessian form, BlockSystem& hessian,
                                    Eigen::VectorXd& gradient) {
  const bool definite = form == Hessian::Definite;
  hessian.set_zero();
  // Gas: ∇U = −(nRT/V) ∇V with ∇V_i = g_i / 6 (area sums), u = √nRT ∇V / V.
  for (std::size_t k = 0; k < gas_.size(); ++k) {
    const Body& body = model.bodies[gas_[k].body];
    const double volume = gas_face_pass(model, k, x);
    gas_curvature_[gas_[k].body] = body.params.pressure_J / volume;
    const double u_per_area_sum = std::sqrt(body.params.pressure_J) / (6.0 * volume);
    for (std::size_t i = 0; i < area_sums_[k].size(); ++i) gas_[k].direction[i] = u_per_area_sum * area_sums_[k][i];
  }
  // Inertia and gravity: ∇ = m (x − x̂)/h² − m g, ∇² = m/h² I.
  const std::vector<double>& m = model.mass_kg;
  const double inverse_h2 = 1.0 / (h_ * h_);
  for (std::size_t i = 0; i < x.size(); ++i) {
    gradient.segment<3>(hessian.dof(static_cast<int>(i))) =
        m[i] * (inverse_h2 * (x[i] - predicted_x_[i]) - model.gravity_m_per_s2);
    hessian.add_diagonal(static_cast<int>(i), m[i] * inverse_h2 * Mat3::Identity());
  }
  floor_.add_derivatives(model, x, start_x_, hessian, gradient);
  colliders_.add_derivatives(model, x, start_x_, hessian, gradient);
  contact_.add_derivatives(model, x, start_x_, gradient);
  for (std::size_t k = 0; k < gas_.size(); ++k) {
    const Body& body = model.bodies[gas_[k].body];
    const double per_area_sum = gas_curvature_[gas_[k].body] / 6.0;  // nRT / V / 6 [N/m²]
    for (std::size_t i = 0; i < area_sums_[k].size(); ++i) {
      gradient.segment<3>(hessian.dof(body.first_vertex + static_cast<int>(i))) -= per_area_sum * area_sums_[k][i];
    }
  }
  // Edges: springs, dampers, the gas's face curvature.
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    const auto [i, j] = pairs_[e];
    const Edge& edge = edges_[e];
    const double k = edge.stiffness_N_per_m, c_over_h = edge.damping_N_s_per_m / h_;
    const Vec3 d = x[i] - x[j];
    const double length = d.norm();
    const Vec3& axis = damper_axis_[e];
    // ∂/∂x_i: k (|d| − L0) d̂ + (c/h) (Δx_ij·d̂_n) d̂_n; the opposite on j.
    Vec3 edge_gradient = c_over_h * ((x[i] - start_x_[i]) - (x[j] - start_x_[j])).dot(axis) * axis;
    if (length > 0.0) edge_gradient += (k * (length - rest_length_m_[e]) / length) * d;
    gradient.segment<3>(hessian.dof(i)) += edge_gradient;
    gradient.segment<3>(hessian.dof(j)) -= edge_gradient;
    const Mat3 springs =
        definite ? spring_stiffness_block(d, rest_length_m_[e], k) : spring_hessian_block(d, rest_length_m_[e], k);
    const Mat3 block = springs + c_over_h * (axis * axis.transpose());
    Mat3 diagonal = block, coupling = -block;
    const double curvature = gas_curvature_[edge.body];
    if (curvature != 0.0 && edge.across_ij >= 0 && edge.across_ji >= 0) {
      const Vec3 w = (-curvature / 6.0) * (x[edge.across_ji] - x[edge.across_ij]);  // −(nRT/V) ∂²V/∂x_i∂x_j = [w]×
      const double size = w.norm();
      if (!definite) {
        coupling += cross_matrix(w);
      } else if (size > 0.0) {
        const Vec3 unit = w / size;
        diagonal += 0.5 * size * (Mat3::Identity() - unit * unit.transpose());
        coupling += 0.5 * cross_matrix(w);
      }
    }
    hessian.add_diagonal(i, diagonal);
    hessian.add_diagonal(j, diagonal);
    hessian.add_coupling(e, coupling);
  }
}

}  // namespace sim
