// Conjugate gradients on a block system plus rank-one terms, block-Jacobi preconditioned, matrix-free.
#pragma once

#include <span>
#include <vector>

#include <Eigen/Core>

#include "core/vec.hpp"
#include "sim/solvers/block_system.hpp"

namespace sim {

using softbody::Vec3;

// A rank-one term u uᵀ of the operator, u non-zero only on vertices first_vertex .. first_vertex + |u| − 1, or,
// where `vertices` is given (as long as u), on those vertices: u[i] on vertex vertices[i].
struct RankOneTerm {
  int first_vertex = 0;
  std::span<const Vec3> u;
  std::span<const int> vertices;
  int vertex(std::size_t i) const { return vertices.empty() ? first_vertex + static_cast<int>(i) : vertices[i]; }
};

struct CgResult {
  int iterations = 0;
  bool converged = false;           // |r| <= tolerance · |b|
  bool negative_curvature = false;  // a direction p with pᵀ S p <= 0 was met: S is not positive definite
};

// Where a solve starts: from x = 0, or from the x it is given (a warm start, e.g. the last step's solution).
enum class CgStart { Zero, Given };

// Solves S x = b for S = A + Σ_t u_t u_tᵀ (A a BlockSystem; the rank-one terms are applied as products, so S is
// never formed: A x + u (uᵀx)), from x = 0 or a given x, by preconditioned conjugate gradients (Hestenes & Stiefel
// 1952; Saad, Iterative Methods for Sparse Linear Systems, Alg. 9.1) with the inverse of each vertex's 3×3 diagonal
// block of S as the preconditioner. Stops at |r| <= tolerance · |b|, after max_iterations, or at the first search
// direction of non-positive curvature (then x is the last iterate); b = 0 gives x = 0. Started from zero, every iterate
// x_k with S positive definite has bᵀx_k > 0: with b = −∇E, a descent direction for any k. The work vectors are sized
// on the first solve and reused (no allocation after it for the same size).
class BlockJacobiCg {
 public:
  CgResult solve(const BlockSystem& a, std::span<const RankOneTerm> terms, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                 double tolerance, int max_iterations, CgStart start = CgStart::Zero);

 private:
  void apply(const BlockSystem& a, std::span<const RankOneTerm> terms, const Eigen::VectorXd& in, Eigen::VectorXd& out);
  void precondition(const Eigen::VectorXd& in, Eigen::VectorXd& out) const;
  void build_preconditioner(const BlockSystem& a, std::span<const RankOneTerm> terms);

  std::vector<Eigen::Matrix3d> inverse_diagonal_;  // per vertex
  Eigen::VectorXd r_, z_, p_, q_;
};

}  // namespace sim
