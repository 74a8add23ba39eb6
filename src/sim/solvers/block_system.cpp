// The block system's pattern, built once, its in-place assembly and its product.
#include "sim/solvers/block_system.hpp"

#include <algorithm>

namespace sim {

void BlockSystem::build(std::size_t vertex_count, std::span<const std::array<int, 2>> pairs) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(9 * (pairs.size() + vertex_count));
  auto add_block = [&entries](int row_vertex, int column_vertex) {
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) entries.emplace_back(3 * row_vertex + r, 3 * column_vertex + c, 0.0);
    }
  };
  for (std::size_t v = 0; v < vertex_count; ++v) add_block(static_cast<int>(v), static_cast<int>(v));
  for (const auto& [i, j] : pairs) add_block(std::min(i, j), std::max(i, j));
  const auto size = static_cast<Eigen::Index>(3 * vertex_count);
  matrix_.resize(size, size);
  matrix_.setFromTriplets(entries.begin(), entries.end());  // duplicates summed: a pair listed twice is fine
  matrix_.makeCompressed();

  auto locate = [this](int row_vertex, int column_vertex) {
    BlockColumns block{};
    for (int c = 0; c < 3; ++c) {
      block[c] = &matrix_.coeffRef(3 * row_vertex, 3 * column_vertex + c) - matrix_.valuePtr();
    }
    return block;
  };
  diagonal_.resize(vertex_count);
  for (std::size_t v = 0; v < vertex_count; ++v) diagonal_[v] = locate(static_cast<int>(v), static_cast<int>(v));
  couplings_.resize(pairs.size());
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    const auto [i, j] = pairs[p];
    couplings_[p].transposed = j < i;
    couplings_[p].upper = locate(std::min(i, j), std::max(i, j));
  }
}

void BlockSystem::set_zero() { std::fill(matrix_.valuePtr(), matrix_.valuePtr() + matrix_.nonZeros(), 0.0); }

void BlockSystem::add_diagonal(int v, const Mat3& block) {
  double* values = matrix_.valuePtr();
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) values[diagonal_[v][c] + r] += block(r, c);
  }
}

void BlockSystem::add_coupling(std::size_t p, const Mat3& block) {
  double* values = matrix_.valuePtr();
  const Coupling& coupling = couplings_[p];
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) values[coupling.upper[c] + r] += coupling.transposed ? block(c, r) : block(r, c);
  }
}

BlockSystem::Mat3 BlockSystem::diagonal_block(int v) const {
  const double* values = matrix_.valuePtr();
  Mat3 block;
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) block(r, c) = values[diagonal_[v][c] + r];
  }
  return block;
}

void BlockSystem::multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  y.noalias() = matrix_.selfadjointView<Eigen::Upper>() * x;
}

}  // namespace sim
