// The affine coarse correction: a Galerkin Newton step of one body restricted to affine motions, and its line search.
#include "sim/integrators/affine_correction.hpp"

#include <Eigen/Dense>

#include "sim/forces/forces.hpp"
#include "sim/integrators/vertex_contacts.hpp"

namespace sim {
namespace {

using Matrix12 = Eigen::Matrix<double, 12, 12>;
using Vector12 = Eigen::Matrix<double, 12, 1>;

// The coarse system's parts that sum over vertices and edges, gathered as moments and spread into K once:
//   inertia  Σ_i w_i B_iᵀ B_i:       Σ w, Σ w r, Σ w r rᵀ (r = x_i − c)
//   edges    Σ_e (B_i − B_j)ᵀ H_e (B_i − B_j) with H_e = T I + α n̂n̂ᵀ and (B_i − B_j) q = A d:
//            T I ⊗ d dᵀ gives Σ T d dᵀ on K_AA's diagonal blocks; α n̂n̂ᵀ ⊗ d dᵀ = (α/|d|²) vec(d dᵀ) vec(d dᵀ)ᵀ,
//            gathered over the six distinct entries p of d dᵀ as Σ (α/|d|²) p pᵀ.
struct CoarseMoments {
  double mass = 0.0;
  Vec3 first = Vec3::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();                         // Σ w r rᵀ + Σ_e T d dᵀ
  Eigen::Matrix<double, 6, 6> along = Eigen::Matrix<double, 6, 6>::Zero();  // Σ (α/|d|²) p pᵀ (upper triangle)

  void add_inertia(double w, const Vec3& r) {
    mass += w;
    first += w * r;
    add_outer(w, r);
  }
  void add_outer(double w, const Vec3& d) {
    for (int a = 0; a < 3; ++a) {
      for (int b = a; b < 3; ++b) second(a, b) += w * d[a] * d[b];
    }
  }
  void add_edge(double transverse, double along_weight, const Vec3& d) {
    add_outer(transverse, d);
    const double p[6] = {d.x() * d.x(), d.x() * d.y(), d.x() * d.z(), d.y() * d.y(), d.y() * d.z(), d.z() * d.z()};
    for (int u = 0; u < 6; ++u) {
      const double wp = along_weight * p[u];
      for (int v = u; v < 6; ++v) along(u, v) += wp * p[v];
    }
  }
  // K += the moments, spread over the 12 unknowns (A row-major, then t).
  void spread_into(Matrix12& K) const {
    static constexpr int kPair[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};  // the index of (a, b) in p
    const Eigen::Matrix3d second_full = second.selfadjointView<Eigen::Upper>();
    const Eigen::Matrix<double, 6, 6> along_full = along.selfadjointView<Eigen::Upper>();
    for (int row = 0; row < 3; ++row) {
      for (int a = 0; a < 3; ++a) {
        for (int col = 0; col < 3; ++col) {
          for (int b = 0; b < 3; ++b) {
            double value = along_full(kPair[row][a], kPair[col][b]);
            if (row == col) value += second_full(a, b);
            K(3 * row + a, 3 * col + b) += value;
          }
        }
        K(3 * row + a, 9 + row) += first[a];
        K(9 + row, 3 * row + a) += first[a];
      }
      K(9 + row, 9 + row) += mass;
    }
  }
};

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

}  // namespace

AffineSystem affine_system(const Body& body, const BodySolve& s, std::span<const Vec3> x, AffineScratch& scratch,
                           bool assemble) {
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
  CoarseMoments moments;
  // Vertices: inertia, floor, colliders and contacts with bodies.
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 r = x[i] - centre;
    const double m = s.mass_kg[i];
    if (assemble) moments.add_inertia(m * s.inverse_h2, r);
    Vec3 gradient = (m * s.inverse_h2) * (x[i] - s.target[i]);
    if (s.floor && x[i].y() < s.floor->height_m) {
      Block3 hessian;
      add_floor_terms(*s.floor, m, x[i], s.base[i], s.h_hat, gradient, hessian);
      if (assemble) add_block(hessian, r, K);
    }
    for (const SmoothCollider& collider : s.colliders) {
      Block3 hessian;
      add_collider_terms(collider, m, x[i], s.base[i], s.h_hat, gradient, hessian);
      if (assemble) add_block(hessian, r, K);
    }
    if (s.contacts) {  // each vertex's own block c_j² K (a self-contact's cross terms left out: still a descent)
      Block3 hessian;
      s.contacts->add_terms(s.first_vertex + static_cast<int>(i), gradient, hessian);
      if (assemble) add_block(hessian, r, K);
    }
    add_gradient(gradient, r, G);
  }
  // Constraints: (B_i − B_j) = [I ⊗ dᵀ | 0], so each adds K_e ⊗ d dᵀ and f_e ⊗ d to the A part.
  // Each edge's length, inverse and rate are kept for the line search (MotionScratch::edges_lagged).
  const DistanceConstraints& constraints = body.constraints;
  const double inverse_h = 1.0 / s.h_hat;
  MotionScratch& search = scratch.search;
  search.edge_length_m.resize(constraints.size());
  search.edge_inverse_length.resize(constraints.size());
  search.edge_rate_m.resize(constraints.size());
  for (std::size_t e = 0; e < constraints.size(); ++e) {
    const auto [i, j] = constraints.ends[e];
    const Vec3 d = x[static_cast<std::size_t>(i)] - x[static_cast<std::size_t>(j)];
    const double length = d.norm();
    search.edge_length_m[e] = length;
    search.edge_inverse_length[e] = 0.0;
    search.edge_rate_m[e] = 0.0;
    if (length == 0.0) continue;
    const double inverse_length = 1.0 / length;
    const Vec3 axis = inverse_length * d;
    const double k = constraints.stiffness_N_per_m[e], c_over_h = constraints.damping_N_s_per_m[e] * inverse_h;
    const double rate = ((x[static_cast<std::size_t>(i)] - s.base[static_cast<std::size_t>(i)]) -
                         (x[static_cast<std::size_t>(j)] - s.base[static_cast<std::size_t>(j)]))
                            .dot(axis);
    search.edge_inverse_length[e] = inverse_length;
    search.edge_rate_m[e] = rate;
    const Vec3 f = (k * (length - constraints.rest_length_m[e]) + c_over_h * rate) * axis;
    for (int row = 0; row < 3; ++row) {
      for (int a = 0; a < 3; ++a) G(3 * row + a) += f[row] * d[a];
    }
    if (!assemble) continue;
    const double transverse = k * std::max(0.0, 1.0 - constraints.rest_length_m[e] * inverse_length);
    const double along = k + c_over_h - transverse;
    moments.add_edge(transverse, along * inverse_length * inverse_length, d);
  }
  if (assemble) moments.spread_into(K);
  // Gas: ∇E = −P ∇V, and the rank-one part of its curvature, nRT/V² (Bᵀ∇V)(Bᵀ∇V)ᵀ. For a closed surface
  // V(x + A (x − c) + t) = det(I + A) V(x), so Bᵀ∇V = V vec(I): V on A's diagonal, 0 on t.
  double volume = 0.0;
  if (s.gas) {
    volume = enclosed_volume(body.topology.faces, x);
    static constexpr int kDiagonal[3] = {0, 4, 8};  // A_aa in q
    for (const int a : kDiagonal) {
      G(a) -= s.gas->pressure(volume) * volume;
      if (!assemble) continue;
      for (const int b : kDiagonal) K(a, b) += s.gas->stiffness(volume) * volume * volume;
    }
  }
  search.volume_after = volume;
  search.edges_lagged = true;
  return AffineSystem{K, G, centre, volume};
}

void affine_motion(const Vector12& q, std::span<const Vec3> x, const Vec3& centre, MotionScratch& search) {
  search.motion.resize(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) search.motion[i] = affine_motion(q, x[i] - centre);
  search.linear_part = (Eigen::Matrix3d() << q(0), q(1), q(2), q(3), q(4), q(5), q(6), q(7), q(8)).finished();
}

bool affine_correction(const Body& body, const BodySolve& s, std::span<Vec3> x, AffineScratch& scratch, bool assemble) {
  const AffineSystem system = affine_system(body, s, x, scratch, assemble);
  if (assemble) scratch.factor.compute(system.matrix);
  const Vector12 q = scratch.factor.solve(-system.gradient);
  const double slope = system.gradient.dot(q);
  if (!(slope < 0.0)) return false;
  affine_motion(q, x, system.centre, scratch.search);
  return search_along_motion(body, s, x, system.volume, slope, scratch.search);
}

}  // namespace sim
