// The affine coarse correction: a Galerkin Newton step of one body restricted to affine motions, and its line search.
#include "sim/integrators/affine_correction.hpp"

#include <Eigen/Dense>

#include "sim/forces/forces.hpp"
#include "sim/integrators/correction_lanes.hpp"
#include "sim/integrators/vertex_contacts.hpp"
#include "sim/step/chunked_sum.hpp"

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

  CoarseMoments& operator+=(const CoarseMoments& other) {
    mass += other.mass;
    first += other.first;
    second += other.second;
    along += other.along;
    return *this;
  }
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

// Σ m_i x_i and Σ m_i over a range of vertices.
struct MassSums {
  Vec3 moment = Vec3::Zero();  // [kg m]
  double mass = 0.0;           // [kg]
  MassSums& operator+=(const MassSums& other) {
    moment += other.moment;
    mass += other.mass;
    return *this;
  }
};

// A range's part of the coarse system: its gradient, its moments and the contact blocks spread into K directly.
struct CoarseSums {
  Vector12 gradient = Vector12::Zero();
  Matrix12 contact_blocks = Matrix12::Zero();
  CoarseMoments moments;
  CoarseSums& operator+=(const CoarseSums& other) {
    gradient += other.gradient;
    contact_blocks += other.contact_blocks;
    moments += other.moments;
    return *this;
  }
};

AffineScratch::AffineScratch() = default;
AffineScratch::~AffineScratch() = default;
AffineScratch::AffineScratch(AffineScratch&&) noexcept = default;
AffineScratch& AffineScratch::operator=(AffineScratch&&) noexcept = default;

namespace {

Vec3 centre_of_mass(const BodySolve& s, std::span<const Vec3> x, AffineScratch& scratch) {
  const MassSums sums = chunked_sum(s.runner, x.size(), MassSums{}, scratch.mass_sums,
                                    [&](std::size_t first, std::size_t last, MassSums& part) {
                                      for (std::size_t i = first; i < last; ++i) {
                                        part.moment += s.mass_kg[i] * x[i];
                                        part.mass += s.mass_kg[i];
                                      }
                                    });
  return sums.moment / sums.mass;
}

// Vertices [first, last): inertia, floor, colliders and contacts with bodies; the floor's and colliders' lags at x
// for the line search (MotionScratch).
void add_vertex_terms(const BodySolve& s, std::span<const Vec3> x, const Vec3& centre, bool assemble, std::size_t first,
                      std::size_t last, MotionScratch& search, CoarseSums& sums) {
  const std::size_t n = x.size();
  for (std::size_t i = first; i < last; ++i) {
    const Vec3 r = x[i] - centre;
    const double m = s.mass_kg[i];
    if (assemble) sums.moments.add_inertia(m * s.inverse_h2, r);
    Vec3 gradient = (m * s.inverse_h2) * (x[i] - s.target[i]);
    if (s.floor) {
      Block3 hessian;
      search.floor_lags[i] = add_floor_terms(*s.floor, m, x[i], s.base[i], s.h_hat, gradient, hessian);
      if (assemble && x[i].y() < s.floor->height_m) add_block(hessian, r, sums.contact_blocks);
    }
    for (std::size_t c = 0; c < s.colliders.size(); ++c) {
      Block3 hessian;
      search.collider_lags[c * n + i] =
          add_collider_terms(s.colliders[c], m, x[i], s.base[i], s.h_hat, gradient, hessian);
      if (assemble) add_block(hessian, r, sums.contact_blocks);
    }
    if (s.contacts) {  // each vertex's own block c_j² K (a self-contact's cross terms left out: still a descent)
      Block3 hessian;
      s.contacts->add_terms(s.first_vertex + static_cast<int>(i), gradient, hessian);
      if (assemble) add_block(hessian, r, sums.contact_blocks);
    }
    add_gradient(gradient, r, sums.gradient);
  }
}

// Constraints [first, last): (B_i − B_j) = [I ⊗ dᵀ | 0], so each adds K_e ⊗ d dᵀ and f_e ⊗ d to the A part. Each
// edge's length, inverse and rate are kept for the line search (MotionScratch).
void add_constraint_terms(const Body& body, const BodySolve& s, std::span<const Vec3> x, bool assemble,
                          std::size_t first, std::size_t last, MotionScratch& search, CoarseSums& sums) {
  const DistanceConstraints& constraints = body.constraints;
  const double inverse_h = 1.0 / s.h_hat;
  for (std::size_t e = first; e < last; ++e) {
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
      for (int a = 0; a < 3; ++a) sums.gradient(3 * row + a) += f[row] * d[a];
    }
    if (!assemble) continue;
    const double transverse = k * std::max(0.0, 1.0 - constraints.rest_length_m[e] * inverse_length);
    const double along = k + c_over_h - transverse;
    sums.moments.add_edge(transverse, along * inverse_length * inverse_length, d);
  }
}

}  // namespace

AffineSystem affine_system(const Body& body, const BodySolve& s, std::span<const Vec3> x, AffineScratch& scratch,
                           bool assemble, std::optional<double> known_volume) {
  const Vec3 centre = centre_of_mass(s, x, scratch);
  MotionScratch& search = scratch.search;
  search.size_contact_lags(s, x.size());
  CoarseSums sums = chunked_sum(s.runner, x.size(), CoarseSums{}, scratch.sums,
                                [&](std::size_t first, std::size_t last, CoarseSums& part) {
                                  add_vertex_terms(s, x, centre, assemble, first, last, search, part);
                                });
  const std::size_t edges = body.constraints.size();
  search.size_edge_lags(edges);
  sums += chunked_sum(s.runner, edges, CoarseSums{}, scratch.sums,
                      [&](std::size_t first, std::size_t last, CoarseSums& part) {
                        add_constraint_terms(body, s, x, assemble, first, last, search, part);
                      });
  Matrix12 K = Matrix12::Zero();
  Vector12 G = sums.gradient;
  if (assemble) {
    K = sums.contact_blocks;
    sums.moments.spread_into(K);
  }
  // Gas: ∇E = −P ∇V, and the rank-one part of its curvature, nRT/V² (Bᵀ∇V)(Bᵀ∇V)ᵀ. For a closed surface
  // V(x + A (x − c) + t) = det(I + A) V(x), so Bᵀ∇V = V vec(I): V on A's diagonal, 0 on t.
  double volume = 0.0;
  if (s.gas) {
    volume =
        known_volume ? *known_volume : enclosed_volume_in_lanes(body.topology.faces, x, s.runner, scratch.volume_sums);
    static constexpr int kDiagonal[3] = {0, 4, 8};  // A_aa in q
    for (const int a : kDiagonal) {
      G(a) -= s.gas->pressure(volume) * volume;
      if (!assemble) continue;
      for (const int b : kDiagonal) K(a, b) += s.gas->stiffness(volume) * volume * volume;
    }
  }
  search.volume_after = volume;
  return AffineSystem{K, G, centre, volume};
}

void affine_motion(const Vector12& q, std::span<const Vec3> x, const Vec3& centre, MotionScratch& search,
                   PartRunner* runner) {
  search.motion.resize(x.size());
  chunked_for(runner, x.size(), [&](std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last; ++i) search.motion[i] = affine_motion(q, x[i] - centre);
  });
  search.linear_part = (Eigen::Matrix3d() << q(0), q(1), q(2), q(3), q(4), q(5), q(6), q(7), q(8)).finished();
}

bool affine_correction(const Body& body, const BodySolve& s, std::span<Vec3> x, AffineScratch& scratch, bool assemble,
                       std::optional<double> known_volume) {
  const AffineSystem system = affine_system(body, s, x, scratch, assemble, known_volume);
  if (assemble) scratch.factor.compute(system.matrix);
  const Vector12 q = scratch.factor.solve(-system.gradient);
  const double slope = system.gradient.dot(q);
  if (!(slope < 0.0)) return false;
  affine_motion(q, x, system.centre, scratch.search, s.runner);
  return search_along_motion(body, s, x, system.volume, slope, scratch.search);
}

}  // namespace sim
