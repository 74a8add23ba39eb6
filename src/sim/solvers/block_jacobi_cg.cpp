// Block-Jacobi preconditioned conjugate gradients with the rank-one terms applied as products.
#include "sim/solvers/block_jacobi_cg.hpp"

#include <cmath>

#include <Eigen/Cholesky>

#include "core/profile.hpp"

namespace sim {

void BlockJacobiCg::build_preconditioner(const BlockSystem& a, std::span<const RankOneTerm> terms) {
  inverse_diagonal_.resize(a.vertex_count());
  for (std::size_t v = 0; v < a.vertex_count(); ++v) inverse_diagonal_[v] = a.diagonal_block(static_cast<int>(v));
  for (const RankOneTerm& term : terms) {
    for (std::size_t i = 0; i < term.u.size(); ++i) {
      inverse_diagonal_[static_cast<std::size_t>(term.vertex(i))] += term.u[i] * term.u[i].transpose();
    }
  }
  for (Eigen::Matrix3d& block : inverse_diagonal_) {
    const Eigen::LLT<Eigen::Matrix3d> cholesky(block);
    // A block that is not positive definite (the exact Hessian of compressed springs) would make the
    // preconditioner indefinite: its diagonal's magnitudes stand in.
    block = cholesky.info() == Eigen::Success
                ? Eigen::Matrix3d(block.inverse())
                : Eigen::Matrix3d(block.diagonal().cwiseAbs().cwiseInverse().asDiagonal());
  }
}

void BlockJacobiCg::apply(const BlockSystem& a, std::span<const RankOneTerm> terms, const Eigen::VectorXd& in,
                          Eigen::VectorXd& out) {
  a.multiply(in, out);
  for (const RankOneTerm& term : terms) {
    double u_in = 0.0;
    for (std::size_t i = 0; i < term.u.size(); ++i)
      u_in += term.u[i].dot(in.segment<3>(BlockSystem::dof(term.vertex(i))));
    for (std::size_t i = 0; i < term.u.size(); ++i)
      out.segment<3>(BlockSystem::dof(term.vertex(i))) += u_in * term.u[i];
  }
}

void BlockJacobiCg::precondition(const Eigen::VectorXd& in, Eigen::VectorXd& out) const {
  for (std::size_t v = 0; v < inverse_diagonal_.size(); ++v) {
    const Eigen::Index dof = BlockSystem::dof(static_cast<int>(v));
    out.segment<3>(dof) = inverse_diagonal_[v] * in.segment<3>(dof);
  }
}

CgResult BlockJacobiCg::solve(const BlockSystem& a, std::span<const RankOneTerm> terms, const Eigen::VectorXd& b,
                              Eigen::VectorXd& x, double tolerance, int max_iterations, CgStart start) {
  const softbody::ProfileScope profile(softbody::ProfilePhase::constraint_sweeps);
  const Eigen::Index n = b.size();
  if (r_.size() != n) {
    r_.setZero(n);
    z_.setZero(n);
    p_.setZero(n);
    q_.setZero(n);
  }
  const bool warm = start == CgStart::Given && x.size() == n;
  if (x.size() != n) x.resize(n);
  build_preconditioner(a, terms);
  CgResult result;
  const double stop = tolerance * b.norm();
  if (warm && stop > 0.0) {
    apply(a, terms, x, q_);
    r_ = b - q_;  // r = b − S x
  } else {
    x.setZero();
    r_ = b;  // r = b − S·0
  }
  if (r_.norm() <= stop) {
    result.converged = true;
    return result;
  }
  precondition(r_, z_);
  p_ = z_;
  double rz = r_.dot(z_);
  for (int k = 0; k < max_iterations; ++k) {
    apply(a, terms, p_, q_);
    const double curvature = p_.dot(q_);  // pᵀ S p
    if (!(curvature > 0.0)) {
      result.negative_curvature = true;
      return result;
    }
    const double alpha = rz / curvature;
    x += alpha * p_;
    r_ -= alpha * q_;
    result.iterations = k + 1;
    if (r_.norm() <= stop) {
      result.converged = true;
      return result;
    }
    precondition(r_, z_);
    const double rz_next = r_.dot(z_);
    p_ = z_ + (rz_next / rz) * p_;
    rz = rz_next;
  }
  return result;
}

}  // namespace sim
