// Linearised backward Euler: assemble M − h ∂f/∂v − h² ∂f/∂x, solve for Δv by conjugate gradients.
#include "sim/integrators/implicit_euler.hpp"

#include <algorithm>

#include "core/profile.hpp"
#include "sim/forces/spring_jacobian.hpp"

namespace sim {
namespace {

constexpr double kSolverTolerance = 1e-10;  // CG stops at |r| <= tol·|b|: far below the method's O(h) error
constexpr int kMaxSolverIterations = 1000;

}  // namespace

void ImplicitEuler::build_pattern(const Model& model, std::size_t vertex_count) {
  std::vector<Eigen::Triplet<double>> entries;
  auto add_pattern_block = [&entries](int row_vertex, int column_vertex) {
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) entries.emplace_back(3 * row_vertex + r, 3 * column_vertex + c, 0.0);
    }
  };
  edges_.clear();
  for (const Body& body : model.bodies) {
    const DistanceConstraints& constraints = body.constraints;  // the edges, then the bending links
    for (std::size_t e = 0; e < constraints.size(); ++e) {
      EdgeBlocks blocks;
      blocks.i = body.first_vertex + constraints.ends[e][0];
      blocks.j = body.first_vertex + constraints.ends[e][1];
      blocks.rest_length_m = constraints.rest_length_m[e];
      blocks.stiffness_N_per_m = constraints.stiffness_N_per_m[e];
      blocks.damping_N_s_per_m = constraints.damping_N_s_per_m[e];
      add_pattern_block(blocks.i, blocks.j);
      add_pattern_block(blocks.j, blocks.i);
      edges_.push_back(blocks);
    }
  }
  for (std::size_t v = 0; v < vertex_count; ++v) add_pattern_block(static_cast<int>(v), static_cast<int>(v));
  const auto size = static_cast<Eigen::Index>(3 * vertex_count);
  matrix_.resize(size, size);
  matrix_.setFromTriplets(entries.begin(), entries.end());  // sums duplicates: shared edges are fine
  matrix_.makeCompressed();

  // A block's three columns are adjacent in each of its rows (every block is a full 3×3), so the
  // offset of its first column in each row locates the whole block.
  auto locate = [this](int row_vertex, int column_vertex) {
    BlockRows block{};
    for (int r = 0; r < 3; ++r) {
      block[r] = &matrix_.coeffRef(3 * row_vertex + r, 3 * column_vertex) - matrix_.valuePtr();
    }
    return block;
  };
  for (EdgeBlocks& blocks : edges_) {
    blocks.ii = locate(blocks.i, blocks.i);
    blocks.jj = locate(blocks.j, blocks.j);
    blocks.ij = locate(blocks.i, blocks.j);
    blocks.ji = locate(blocks.j, blocks.i);
  }
  diagonal_.resize(vertex_count);
  for (std::size_t v = 0; v < vertex_count; ++v) diagonal_[v] = locate(static_cast<int>(v), static_cast<int>(v));
  rhs_.setZero(size);
  guess_.setZero(size);
  solver_.setTolerance(kSolverTolerance);
  solver_.setMaxIterations(kMaxSolverIterations);
  pattern_vertices_ = vertex_count;
}

void ImplicitEuler::add_block(const BlockRows& block, const Eigen::Matrix3d& value, double sign) {
  double* values = matrix_.valuePtr();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) values[block[r] + c] += sign * value(r, c);
  }
}

// Matrix A = M + h² K + h C with K = −∂f/∂x (springs, clamped) and C = −∂f/∂v (dampers), both as
// graph Laplacians of 3×3 edge blocks; rhs b = h (f0 − h K v0).
void ImplicitEuler::assemble(const State& state, std::span<const double> mass_kg, double dt) {
  std::fill(matrix_.valuePtr(), matrix_.valuePtr() + matrix_.nonZeros(), 0.0);
  for (std::size_t v = 0; v < diagonal_.size(); ++v)
    add_block(diagonal_[v], mass_kg[v] * Eigen::Matrix3d::Identity(), 1.0);
  for (std::size_t v = 0; v < force_.size(); ++v) rhs_.segment<3>(static_cast<Eigen::Index>(3 * v)) = dt * force_[v];
  for (const EdgeBlocks& e : edges_) {
    const Vec3 d = state.x[e.i] - state.x[e.j];
    const Eigen::Matrix3d stiffness = spring_stiffness_block(d, e.rest_length_m, e.stiffness_N_per_m);
    const Eigen::Matrix3d block = dt * dt * stiffness + dt * damper_block(d, e.damping_N_s_per_m);
    add_block(e.ii, block, 1.0);
    add_block(e.jj, block, 1.0);
    add_block(e.ij, block, -1.0);
    add_block(e.ji, block, -1.0);
    const Vec3 kv = stiffness * (state.v[e.i] - state.v[e.j]);  // (K v0)_i for this edge; −it on j
    rhs_.segment<3>(3 * e.i) -= dt * dt * kv;
    rhs_.segment<3>(3 * e.j) += dt * dt * kv;
  }
}

void ImplicitEuler::step(Dynamics& dynamics, State& state, double dt) {
  const std::size_t n = state.x.size();
  if (pattern_vertices_ != n) build_pattern(dynamics.model(), n);  // first step, or another model
  dynamics.forces(state, force_);
  assemble(state, dynamics.model().mass_kg, dt);
  Eigen::VectorXd& delta_v = state.carry.velocity_change;
  {
    const softbody::ProfileScope profile(softbody::ProfilePhase::constraint_sweeps);
    solver_.compute(matrix_);
    if (delta_v.size() != static_cast<Eigen::Index>(3 * n)) delta_v.setZero(static_cast<Eigen::Index>(3 * n));
    guess_ = delta_v;  // the last step's Δv: a warm start, deterministic
    delta_v = solver_.solveWithGuess(rhs_, guess_);
  }
  for (std::size_t i = 0; i < n; ++i) {
    state.v[i] += delta_v.segment<3>(static_cast<Eigen::Index>(3 * i));
    state.x[i] += dt * state.v[i];
  }
}

}  // namespace sim
