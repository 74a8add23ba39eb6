// Vertex block descent: the step's targets, the sweeps, and one vertex's local Newton step with its line search.
#include "sim/integrators/vertex_block_descent.hpp"

#include <cmath>

#include <Eigen/Dense>

#include "core/profile.hpp"
#include "sim/contact/smooth_collider.hpp"
#include "sim/forces/forces.hpp"

namespace sim {
namespace {

constexpr double kArmijo = 1e-4;   // sufficient decrease: ΔE ≤ kArmijo α ∇E·Δ (Nocedal & Wright, Sect. 3.1)
constexpr int kMostHalvings = 10;  // then the vertex stays where it is for this visit
// A Newton step shorter than this fraction of the body's mean edge is taken without a line search: E's change is then
// below its own round-off (about k ε l |l − L0| for a spring), so the test could only refuse a harmless move.
constexpr double kNegligibleStep = 1e-8;

// The gas of one body as a function of its volume: E = −nRT ln V, held to the force model's guard below
// V_g (sim::guarded_volume): there the pressure stays nRT/V_g and E continues linearly, so E stays convex in V.
struct GasLaw {
  double nRT_J = 0.0;
  double guard_m3 = 0.0;  // V_g [m³]

  double pressure(double V) const { return nRT_J / std::max(V, guard_m3); }          // −dE/dV [Pa]
  double stiffness(double V) const { return V > guard_m3 ? nRT_J / (V * V) : 0.0; }  // d²E/dV² [J/m⁶]
  double energy(double V) const {                                                    // E [J]
    return V >= guard_m3 ? -nRT_J * std::log(V) : -nRT_J * (std::log(guard_m3) + (V - guard_m3) / guard_m3);
  }
  // E(V + dV) − E(V) [J], without the cancellation of two logarithms where both are above the guard.
  double energy_change(double V, double dV) const {
    if (V >= guard_m3 && V + dV >= guard_m3) return -nRT_J * std::log1p(dV / V);
    return energy(V + dV) - energy(V);
  }
};

// A symmetric 3×3 block, its upper triangle.
struct Block3 {
  double xx = 0.0, xy = 0.0, xz = 0.0, yy = 0.0, yz = 0.0, zz = 0.0;

  void add_diagonal(double a) {
    xx += a;
    yy += a;
    zz += a;
  }
  void add_outer(double a, const Vec3& u) {  // += a u uᵀ
    xx += a * u.x() * u.x();
    xy += a * u.x() * u.y();
    xz += a * u.x() * u.z();
    yy += a * u.y() * u.y();
    yz += a * u.y() * u.z();
    zz += a * u.z() * u.z();
  }
  // H⁻¹ r by the adjugate (H positive definite here: its determinant is positive).
  Vec3 solve(const Vec3& r) const {
    const double c_xx = yy * zz - yz * yz, c_xy = xz * yz - xy * zz, c_xz = xy * yz - xz * yy;
    const double c_yy = xx * zz - xz * xz, c_yz = xy * xz - xx * yz, c_zz = xx * yy - xy * xy;
    const double inverse_det = 1.0 / (xx * c_xx + xy * c_xy + xz * c_xz);
    return inverse_det * Vec3(c_xx * r.x() + c_xy * r.y() + c_xz * r.z(), c_xy * r.x() + c_yy * r.y() + c_yz * r.z(),
                              c_xz * r.x() + c_yz * r.y() + c_zz * r.z());
  }
};

// What the local solves of one body read during a step.
struct BodySolve {
  const VertexBlocks& blocks;
  std::span<const double> mass_kg;
  std::span<const Vec3> target;    // y
  std::span<const Vec3> base;      // x̃
  double h_hat = 0.0;              // ĥ [s]
  double negligible_step_m = 0.0;  // kNegligibleStep × the mean rest edge [m]
  double inverse_h2 = 0.0;         // 1/ĥ² [1/s²]
  std::optional<GasLaw> gas;
  const SmoothFloor* floor = nullptr;
  std::span<const SmoothCollider> colliders;  // the smooth ones
};

// The smooth floor's terms of one vertex, with the dashpot's weight w and friction's normal force N lagged at the
// visit's start (sim/contact/floor_potential.hpp has the same terms for newton).
struct FloorLag {
  double depth_m = 0.0;       // floor − y at the visit's start
  double dashpot_kg_s = 0.0;  // m b w [kg/s]
  double friction_N = 0.0;    // N = μ m ω² δ P(d/δ)
  double slip_speed2 = 0.0;   // ε² [m²/s²]
};

// The tangential speed's regularised norm r = √(|v_t|² + ε²), v_t = (x_t − x̃_t)/ĥ [m/s].
double regularised_slip(const Vec3& x, const Vec3& base, double h_hat, double slip_speed2) {
  const double vx = (x.x() - base.x()) / h_hat, vz = (x.z() - base.z()) / h_hat;
  return std::sqrt(vx * vx + vz * vz + slip_speed2);
}

// Adds the floor's gradient and Hessian at x (vertex of mass m) and returns its lags.
FloorLag add_floor_terms(const SmoothFloor& floor, double m, const Vec3& x, const Vec3& base, double h_hat,
                         Vec3& gradient, Block3& hessian) {
  FloorLag lag;
  lag.depth_m = floor.height_m - x.y();
  lag.slip_speed2 = floor.slip_speed_m_per_s * floor.slip_speed_m_per_s;
  if (lag.depth_m <= 0.0) return lag;
  const double elastic = m * smooth_elastic_per_mass(floor, lag.depth_m);  // m ω² δ P(d/δ) [N]
  gradient.y() -= elastic;
  hessian.yy += m * floor.omega2 * smooth_dashpot_weight(floor, lag.depth_m);  // m ω² s(d/δ)
  lag.dashpot_kg_s = m * floor.damping_rate * smooth_dashpot_weight(floor, lag.depth_m);
  gradient.y() += lag.dashpot_kg_s * (x.y() - base.y()) / h_hat;  // m b w v'_y
  hessian.yy += lag.dashpot_kg_s / h_hat;
  lag.friction_N = floor.friction * elastic;
  if (lag.friction_N > 0.0) {
    const double vx = (x.x() - base.x()) / h_hat, vz = (x.z() - base.z()) / h_hat;
    const double r = std::sqrt(vx * vx + vz * vz + lag.slip_speed2);
    gradient.x() += lag.friction_N * vx / r;  // N v'_t / r
    gradient.z() += lag.friction_N * vz / r;
    const double a = lag.friction_N / (h_hat * r), b = a / (r * r);  // (N/(ĥ r)) (I − v vᵀ/r²) in x, z
    hessian.xx += a - b * vx * vx;
    hessian.xz -= b * vx * vz;
    hessian.zz += a - b * vz * vz;
  }
  return lag;
}

// The floor terms' change of E when the vertex moves from x by step [J].
double floor_energy_change(const SmoothFloor& floor, const FloorLag& lag, double m, const Vec3& x, const Vec3& step,
                           const Vec3& base, double h_hat) {
  const double depth_after = lag.depth_m - step.y();
  const double spring = m * ((depth_after > 0.0 ? smooth_energy_per_mass(floor, depth_after) : 0.0) -
                             (lag.depth_m > 0.0 ? smooth_energy_per_mass(floor, lag.depth_m) : 0.0));
  const double dashpot = lag.dashpot_kg_s / (2.0 * h_hat) * step.y() * (2.0 * (x.y() - base.y()) + step.y());
  double friction = 0.0;
  if (lag.friction_N > 0.0) {
    friction =
        lag.friction_N * h_hat *
        (regularised_slip(x + step, base, h_hat, lag.slip_speed2) - regularised_slip(x, base, h_hat, lag.slip_speed2));
  }
  return spring + dashpot + friction;
}

// The smooth colliders' terms of one vertex at x (sim/contact/smooth_collider.hpp, newton's too), each collider's
// normal, dashpot weight and friction force lagged at x into `lags`: gradient and Hessian added.
void add_collider_terms(std::span<const SmoothCollider> colliders, double m, const Vec3& x, const Vec3& base,
                        double h_hat, Vec3& gradient, Block3& hessian, std::span<ColliderLag> lags) {
  for (std::size_t c = 0; c < colliders.size(); ++c) {
    lags[c] = lag_smooth_collider(colliders[c], m, x);
    Mat3 block = Mat3::Zero();
    add_smooth_collider_derivatives(colliders[c], lags[c], m, x, base, h_hat, gradient, block);
    hessian.xx += block(0, 0);
    hessian.xy += block(0, 1);
    hessian.xz += block(0, 2);
    hessian.yy += block(1, 1);
    hessian.yz += block(1, 2);
    hessian.zz += block(2, 2);
  }
}

// The colliders' terms' change of E when the vertex moves from x by step, with the lags taken at x [J].
double collider_energy_change(std::span<const SmoothCollider> colliders, std::span<const ColliderLag> lags, double m,
                              const Vec3& x, const Vec3& step, const Vec3& base, double h_hat) {
  double change = 0.0;
  for (std::size_t c = 0; c < colliders.size(); ++c) {
    change += smooth_collider_terms(colliders[c], lags[c], m, x + step, base, h_hat) -
              smooth_collider_terms(colliders[c], lags[c], m, x, base, h_hat);
  }
  return change;
}

}  // namespace

void VertexBlockDescent::prepare_once(const Model& model) {
  if (blocks_.size() == model.bodies.size()) return;
  blocks_.clear();
  int most_constraints = 0;
  for (const Body& body : model.bodies) {
    blocks_.push_back(vertex_blocks(body));
    most_constraints = std::max(most_constraints, blocks_.back().most_constraints);
  }
  lagged_axis_.resize(static_cast<std::size_t>(most_constraints));
  lagged_length_.resize(static_cast<std::size_t>(most_constraints));
  lagged_rate_.resize(static_cast<std::size_t>(most_constraints));
  smooth_floor_.reset();
  if (model.floor && model.floor->contact == FloorContact::Smooth) smooth_floor_ = resolve_smooth_floor(*model.floor);
  smooth_colliders_.clear();
  for (const Collider& collider : model.colliders) {
    if (collider.contact == FloorContact::Smooth) smooth_colliders_.push_back(resolve_smooth_collider(collider));
  }
  collider_lags_.resize(smooth_colliders_.size());
}

double VertexBlockDescent::set_targets(const Model& model, const State& state, double h, bool bdf2) {
  const std::size_t n = state.x.size();
  target_.resize(n);
  base_.resize(n);
  const double h_hat = bdf2 ? 2.0 * h / 3.0 : h;
  const Vec3 fall = (h_hat * h_hat) * model.gravity_m_per_s2;  // ĥ² g [m]
  const std::vector<Vec3>& x_previous = state.carry.previous_x;
  const std::vector<Vec3>& v_previous = state.carry.previous_v;
  for (std::size_t i = 0; i < n; ++i) {
    if (bdf2) {
      base_[i] = (4.0 * state.x[i] - x_previous[i]) / 3.0;                                // x̃
      target_[i] = base_[i] + (h_hat / 3.0) * (4.0 * state.v[i] - v_previous[i]) + fall;  // x̃ + ĥ ṽ + ĥ² g
    } else {
      base_[i] = state.x[i];
      target_[i] = state.x[i] + h * state.v[i] + fall;
    }
  }
  return h_hat;
}

namespace {

// Twice ∂V/∂x_i times 3, Σ_{f ∋ i} (x_b − x_i) × (x_c − x_i) = 6 ∂V/∂x_i [m²].
Vec3 six_volume_gradient(const VertexBlocks& blocks, int i, std::span<const Vec3> x) {
  const Vec3 xi = x[static_cast<std::size_t>(i)];
  Vec3 sum = Vec3::Zero();
  for (int f = blocks.face_start[static_cast<std::size_t>(i)]; f < blocks.face_start[static_cast<std::size_t>(i) + 1];
       ++f) {
    const auto [b, c] = blocks.face_others[static_cast<std::size_t>(f)];
    sum += (x[static_cast<std::size_t>(b)] - xi).cross(x[static_cast<std::size_t>(c)] - xi);
  }
  return sum;
}

// The affine coarse correction (a two-level method: Gauss–Seidel smooths what is local, one Galerkin Newton step on a
// coarse space takes out what crosses the body, which a sweep moves by one ring of vertices only: the momentum a
// floor takes from the whole body, the gas's breathing, a squash). The coarse space is every affine motion of the
// body, δx_i = A (x_i − c) + t (A 3×3, t 3: q, 12 unknowns; c its centroid), δx = B q. The step solves
// (Bᵀ H B) q = −Bᵀ ∇E with the sweeps' clamped, lagged H (Bᵀ H B is positive definite: its inertia part alone is),
// then searches α on E's change along B q as a vertex does.
using Matrix12 = Eigen::Matrix<double, 12, 12>;
using Vector12 = Eigen::Matrix<double, 12, 1>;

// Adds B_iᵀ (w I) B_i and B_iᵀ g to the coarse system for a vertex at r = x_i − c: the inertia's part.
void add_isotropic(double w, const Vec3& r, Matrix12& K) {
  for (int row = 0; row < 3; ++row) {
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < 3; ++b) K(3 * row + a, 3 * row + b) += w * r[a] * r[b];
      K(3 * row + a, 9 + row) += w * r[a];
      K(9 + row, 3 * row + a) += w * r[a];
    }
    K(9 + row, 9 + row) += w;
  }
}

// += B_iᵀ H B_i for a general symmetric 3×3 H at r.
void add_block(const Block3& block, const Vec3& r, Matrix12& K) {
  const Eigen::Matrix3d H =
      (Eigen::Matrix3d() << block.xx, block.xy, block.xz, block.xy, block.yy, block.yz, block.xz, block.yz, block.zz)
          .finished();
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) {
      for (int a = 0; a < 3; ++a) {
        for (int b = 0; b < 3; ++b) K(3 * row + a, 3 * col + b) += H(row, col) * r[a] * r[b];
        K(3 * row + a, 9 + col) += H(row, col) * r[a];
        K(9 + col, 3 * row + a) += H(row, col) * r[a];
      }
      K(9 + row, 9 + col) += H(row, col);
    }
  }
}

// B_iᵀ g at r.
void add_gradient(const Vec3& g, const Vec3& r, Vector12& G) {
  for (int row = 0; row < 3; ++row) {
    for (int a = 0; a < 3; ++a) G(3 * row + a) += g[row] * r[a];
    G(9 + row) += g[row];
  }
}

// B_i q at r: A r + t.
Vec3 affine_motion(const Vector12& q, const Vec3& r) {
  return Vec3(q(0) * r.x() + q(1) * r.y() + q(2) * r.z() + q(9), q(3) * r.x() + q(4) * r.y() + q(5) * r.z() + q(10),
              q(6) * r.x() + q(7) * r.y() + q(8) * r.z() + q(11));
}

// One coarse Newton step with its line search on body `body`'s positions x (see above). Returns whether it moved.
bool affine_correction(const Body& body, const BodySolve& s, std::span<Vec3> x, std::vector<Vec3>& motion,
                       std::vector<Vec3>& area_sums, std::span<ColliderLag> lags) {
  const std::size_t n = x.size();
  Vec3 centre = Vec3::Zero();
  double mass = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    centre += s.mass_kg[i] * x[i];
    mass += s.mass_kg[i];
  }
  centre /= mass;
  Matrix12 K = Matrix12::Zero();
  Vector12 G = Vector12::Zero();
  // Vertices: inertia and floor.
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 r = x[i] - centre;
    const double m = s.mass_kg[i];
    add_isotropic(m * s.inverse_h2, r, K);
    Vec3 gradient = (m * s.inverse_h2) * (x[i] - s.target[i]);
    if (s.floor && x[i].y() < s.floor->height_m) {
      Block3 hessian;
      add_floor_terms(*s.floor, m, x[i], s.base[i], s.h_hat, gradient, hessian);
      add_block(hessian, r, K);
    }
    if (!s.colliders.empty()) {
      Block3 hessian;
      add_collider_terms(s.colliders, m, x[i], s.base[i], s.h_hat, gradient, hessian, lags);
      add_block(hessian, r, K);
    }
    add_gradient(gradient, r, G);
  }
  // Constraints: (B_i − B_j) = [I ⊗ dᵀ | 0], so each adds K_e ⊗ d dᵀ and f_e ⊗ d to the A part.
  const DistanceConstraints& constraints = body.constraints;
  for (std::size_t e = 0; e < constraints.size(); ++e) {
    const auto [i, j] = constraints.ends[e];
    const Vec3 d = x[static_cast<std::size_t>(i)] - x[static_cast<std::size_t>(j)];
    const double length = d.norm();
    if (length == 0.0) continue;
    const Vec3 axis = d / length;
    const double k = constraints.stiffness_N_per_m[e], c_over_h = constraints.damping_N_s_per_m[e] / s.h_hat;
    const double rate = ((x[static_cast<std::size_t>(i)] - s.base[static_cast<std::size_t>(i)]) -
                         (x[static_cast<std::size_t>(j)] - s.base[static_cast<std::size_t>(j)]))
                            .dot(axis);
    const Vec3 f = (k * (length - constraints.rest_length_m[e]) + c_over_h * rate) * axis;
    const double transverse = k * std::max(0.0, 1.0 - constraints.rest_length_m[e] / length);
    const double along = k + c_over_h - transverse;
    for (int row = 0; row < 3; ++row) {
      for (int a = 0; a < 3; ++a) G(3 * row + a) += f[row] * d[a];
      for (int col = 0; col < 3; ++col) {
        const double h_rc = (row == col ? transverse : 0.0) + along * axis[row] * axis[col];
        if (h_rc == 0.0) continue;
        for (int a = 0; a < 3; ++a) {
          for (int b = 0; b < 3; ++b) K(3 * row + a, 3 * col + b) += h_rc * d[a] * d[b];
        }
      }
    }
  }
  // Gas: ∇E = −P ∇V, and the rank-one part of its curvature, nRT/V² (Bᵀ∇V)(Bᵀ∇V)ᵀ.
  double volume = 0.0;
  if (s.gas) {
    volume = volume_and_area_sums(body.topology.faces, x, area_sums);
    Vector12 u = Vector12::Zero();
    for (std::size_t i = 0; i < n; ++i) add_gradient(area_sums[i] / 6.0, x[i] - centre, u);
    G -= s.gas->pressure(volume) * u;
    K += s.gas->stiffness(volume) * u * u.transpose();
  }
  const Vector12 q = K.ldlt().solve(-G);
  const double slope = G.dot(q);
  if (!(slope < 0.0)) return false;
  motion.resize(n);
  for (std::size_t i = 0; i < n; ++i) motion[i] = affine_motion(q, x[i] - centre);
  // Line search on E's change along the motion, with the directions and the floor's weights lagged at x.
  std::vector<Vec3>& trial = area_sums;  // reused: the gas's sums are not needed any more
  for (double alpha = 1.0; alpha > 1e-3; alpha *= 0.5) {
    double change = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3 step = alpha * motion[i];
      const double m = s.mass_kg[i];
      change += 0.5 * m * s.inverse_h2 * step.dot(2.0 * (x[i] - s.target[i]) + step);
      if (s.floor && (x[i].y() < s.floor->height_m || x[i].y() + step.y() < s.floor->height_m)) {
        Vec3 unused_gradient = Vec3::Zero();
        Block3 unused_hessian;
        const FloorLag lag = add_floor_terms(*s.floor, m, x[i], s.base[i], s.h_hat, unused_gradient, unused_hessian);
        change += floor_energy_change(*s.floor, lag, m, x[i], step, s.base[i], s.h_hat);
      }
      if (!s.colliders.empty()) {
        Vec3 unused_gradient = Vec3::Zero();
        Block3 unused_hessian;
        add_collider_terms(s.colliders, m, x[i], s.base[i], s.h_hat, unused_gradient, unused_hessian, lags);
        change += collider_energy_change(s.colliders, lags, m, x[i], step, s.base[i], s.h_hat);
      }
    }
    for (std::size_t e = 0; e < constraints.size(); ++e) {
      const auto [i, j] = constraints.ends[e];
      const auto vi = static_cast<std::size_t>(i), vj = static_cast<std::size_t>(j);
      const Vec3 d = x[vi] - x[vj];
      const double before = d.norm();
      if (before == 0.0) continue;
      const Vec3 axis = d / before;
      const Vec3 relative = alpha * (motion[vi] - motion[vj]);
      const double after = (d + relative).norm();
      const double k = constraints.stiffness_N_per_m[e], rest = constraints.rest_length_m[e];
      change += 0.5 * k * (after - before) * (after + before - 2.0 * rest);
      const double rate = ((x[vi] - s.base[vi]) - (x[vj] - s.base[vj])).dot(axis), along = relative.dot(axis);
      change += 0.5 * constraints.damping_N_s_per_m[e] / s.h_hat * along * (2.0 * rate + along);
    }
    if (s.gas) {
      trial.resize(n);
      for (std::size_t i = 0; i < n; ++i) trial[i] = x[i] + alpha * motion[i];
      change += s.gas->energy_change(volume, enclosed_volume(body.topology.faces, trial) - volume);
    }
    if (change <= kArmijo * alpha * slope) {
      for (std::size_t i = 0; i < n; ++i) x[i] += alpha * motion[i];
      return true;
    }
  }
  return false;
}

}  // namespace

void VertexBlockDescent::sweep_body(const Model& model, std::size_t b, double h_hat, std::vector<Vec3>& all_x) {
  const Body& body = model.bodies[b];
  const VertexBlocks& blocks = blocks_[b];
  BodySolve s{blocks,
              Model::of(body, model.mass_kg),
              Model::of(body, target_),
              Model::of(body, base_),
              h_hat,
              kNegligibleStep * body.rest.mean_edge_m,
              1.0 / (h_hat * h_hat),
              std::nullopt,
              smooth_floor_ ? &*smooth_floor_ : nullptr,
              smooth_colliders_};
  if (body.params.pressure_J != 0.0) s.gas = GasLaw{body.params.pressure_J, guarded_volume(0.0, body.rest.volume_m3)};
  const std::span<Vec3> x = Model::of(body, all_x);
  for (int sweep = 0; sweep < sweeps_; ++sweep) {
    if (coarse_) affine_correction(body, s, x, coarse_motion_, coarse_scratch_, collider_lags_);
    double volume = s.gas ? enclosed_volume(body.topology.faces, x) : 0.0;  // afresh each sweep: no drift
    for (const int i : blocks.colouring.vertices) {
      const auto vi = static_cast<std::size_t>(i);
      const Vec3 xi = x[vi];
      const double m = s.mass_kg[vi];
      // 1. ∇_i E and H_i at x_i: inertia, constraints (lagging each direction and approach), gas, floor.
      Vec3 gradient = (m * s.inverse_h2) * (xi - s.target[vi]);
      Block3 hessian;
      hessian.add_diagonal(m * s.inverse_h2);
      const Vec3 base_i = s.base[vi];
      const int first = blocks.constraint_start[vi], last = blocks.constraint_start[vi + 1];
      for (int e = first; e < last; ++e) {
        const auto ve = static_cast<std::size_t>(e), slot = static_cast<std::size_t>(e - first);
        const auto j = static_cast<std::size_t>(blocks.other_end[ve]);
        const Vec3 d = xi - x[j];
        const double length = d.norm();
        lagged_length_[slot] = length;
        if (length == 0.0) {  // coincident ends: no direction, no force, no curvature
          lagged_axis_[slot] = Vec3::Zero();
          lagged_rate_[slot] = 0.0;
          continue;
        }
        const Vec3 axis = d / length;
        const double k = blocks.stiffness_N_per_m[ve], c_over_h = blocks.damping_N_s_per_m[ve] / h_hat;
        const double rate = ((xi - base_i) - (x[j] - s.base[j])).dot(axis);  // ĥ × the approach speed [m]
        lagged_axis_[slot] = axis;
        lagged_rate_[slot] = rate;
        gradient += (k * (length - blocks.rest_length_m[ve]) + c_over_h * rate) * axis;
        const double transverse = k * std::max(0.0, 1.0 - blocks.rest_length_m[ve] / length);
        hessian.add_diagonal(transverse);
        hessian.add_outer(k + c_over_h - transverse, axis);
      }
      Vec3 volume_gradient = Vec3::Zero();
      if (s.gas) {
        volume_gradient = six_volume_gradient(blocks, i, x) / 6.0;  // g_i [m²]
        gradient -= s.gas->pressure(volume) * volume_gradient;
        hessian.add_outer(s.gas->stiffness(volume), volume_gradient);
      }
      FloorLag floor_lag;
      if (s.floor) floor_lag = add_floor_terms(*s.floor, m, xi, base_i, h_hat, gradient, hessian);
      add_collider_terms(s.colliders, m, xi, base_i, h_hat, gradient, hessian, collider_lags_);
      // 2. The Newton step and its line search on E's change.
      ++statistics_.vertex_solves;
      const Vec3 direction = -hessian.solve(gradient);
      const double slope = gradient.dot(direction);  // ∇E·Δ < 0
      if (!(slope < 0.0)) continue;                  // converged to round-off (or not finite): stay
      if (direction.squaredNorm() <= s.negligible_step_m * s.negligible_step_m) {
        x[vi] = xi + direction;
        if (s.gas) volume += volume_gradient.dot(direction);
        continue;
      }
      double alpha = 1.0;
      bool moved = false;
      for (int halving = 0; halving <= kMostHalvings; ++halving, alpha *= 0.5) {
        const Vec3 step = alpha * direction;
        const Vec3 moved_x = xi + step;
        double change = 0.5 * m * s.inverse_h2 * step.dot(2.0 * (xi - s.target[vi]) + step);  // inertia
        for (int e = first; e < last; ++e) {
          const auto ve = static_cast<std::size_t>(e), slot = static_cast<std::size_t>(e - first);
          const double k = blocks.stiffness_N_per_m[ve], rest = blocks.rest_length_m[ve];
          const double before = lagged_length_[slot];
          const double after = (moved_x - x[static_cast<std::size_t>(blocks.other_end[ve])]).norm();
          change += 0.5 * k * (after - before) * (after + before - 2.0 * rest);  // ½k((l₁−L0)² − (l₀−L0)²)
          const double along = step.dot(lagged_axis_[slot]);
          change += 0.5 * blocks.damping_N_s_per_m[ve] / h_hat * along *
                    (2.0 * lagged_rate_[slot] + along);  // c/(2ĥ) Δ(rate²)
        }
        if (s.gas) change += s.gas->energy_change(volume, volume_gradient.dot(step));
        if (s.floor) change += floor_energy_change(*s.floor, floor_lag, m, xi, step, base_i, h_hat);
        if (!s.colliders.empty())
          change += collider_energy_change(s.colliders, collider_lags_, m, xi, step, base_i, h_hat);
        if (change <= kArmijo * alpha * slope) {
          x[vi] = moved_x;
          if (s.gas) volume += volume_gradient.dot(step);  // exact: V is affine in x_i
          moved = true;
          break;
        }
        ++statistics_.halvings;
      }
      if (!moved) ++statistics_.refused_moves;
    }
  }
}

void VertexBlockDescent::step(Dynamics& dynamics, State& state, double dt) {
  const Model& model = dynamics.model();
  prepare_once(model);
  const softbody::ProfileScope profile(softbody::ProfilePhase::constraint_sweeps);
  const IntegratorCarry& carry = state.carry;
  const bool bdf2 = carry.previous_x.size() == state.x.size() && carry.previous_v.size() == state.x.size() &&
                    std::abs(carry.previous_dt_s - dt) <= 1e-12 * dt;
  const double h_hat = set_targets(model, state, dt, bdf2);
  start_x_ = state.x;
  start_v_ = state.v;
  state.x = target_;  // the initial guess: y
  for (std::size_t b = 0; b < model.bodies.size(); ++b) sweep_body(model, b, h_hat, state.x);
  for (std::size_t i = 0; i < state.x.size(); ++i) state.v[i] = (state.x[i] - base_[i]) / h_hat;  // v' = (x' − x̃)/ĥ
  state.carry.previous_x.swap(start_x_);
  state.carry.previous_v.swap(start_v_);
  state.carry.previous_dt_s = dt;
  ++statistics_.steps;
  if (bdf2) ++statistics_.bdf2_steps;
}

}  // namespace sim
