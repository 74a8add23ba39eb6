// The implicit integrator's sparse part (M + h² K + h C): a symmetric matrix of 3×3 vertex
// blocks, assembled in place.
#pragma once

#include <array>
#include <span>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace sim {

// One 3×3 block per vertex (diagonal) and per coupled pair of vertices (an edge), stored as the upper
// triangle of a compressed column matrix in the vertices' own order (vertex v's unknowns at 3v .. 3v + 2).
// The pattern is built once per model; later assemblies only overwrite values.
class BlockSystem {
 public:
  using Mat3 = Eigen::Matrix3d;
  using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

  // The pattern of `vertex_count` diagonal blocks and one coupling block per pair (i, j), i ≠ j.
  void build(std::size_t vertex_count, std::span<const std::array<int, 2>> pairs);
  std::size_t vertex_count() const { return diagonal_.size(); }
  Eigen::Index size() const { return matrix_.rows(); }
  // Where vertex v's three unknowns start in the system's vectors.
  static Eigen::Index dof(int v) { return 3 * static_cast<Eigen::Index>(v); }

  void set_zero();
  // Adds `block` to the diagonal block of vertex v.
  void add_diagonal(int v, const Mat3& block);
  // Adds `block` to the coupling block (i, j) of pair p as given to build() (and its transpose to (j, i)).
  void add_coupling(std::size_t p, const Mat3& block);
  // The diagonal block of vertex v (its full 3×3 is stored).
  Mat3 diagonal_block(int v) const;

  // The upper triangle of A.
  const SparseMatrix& upper_triangle() const { return matrix_; }
  // y = A x (y sized by the caller).
  void multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const;

 private:
  // The value offset of each of a block's three columns (its three rows are adjacent in each column).
  using BlockColumns = std::array<Eigen::Index, 3>;
  struct Coupling {
    BlockColumns upper{};     // the block in the upper triangle
    bool transposed = false;  // it holds (j, i) = (i, j)ᵀ: j < i
  };

  std::vector<BlockColumns> diagonal_;
  std::vector<Coupling> couplings_;
  SparseMatrix matrix_;
};

}  // namespace sim
