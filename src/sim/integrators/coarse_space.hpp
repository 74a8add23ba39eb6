// A coarse level for vbd's sweeps (sim/integrators/vertex_block_descent.hpp): smooth displacement fields spanned by a
// few hundred aggregates of vertices, and one Galerkin Newton step of the body's step energy restricted to them.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "sim/integrators/motion_search.hpp"
#include "sim/integrators/vertex_blocks.hpp"
#include "sim/integrators/vertex_energy.hpp"
#include "sim/model/body.hpp"

namespace sim {

// The coarse space: δx_i = Σ_a w_ia t_a, one translation t_a per aggregate a (3 unknowns each), with weights that are
// a partition of unity (Σ_a w_ia = 1, so it holds every translation of the body) and smooth over the mesh; and, where
// built with the body's placed positions, its linear motions too: three more aggregates with the weights
// (X_i − C)/R (X the placed mesh, C its centroid, R its largest distance from C), δx_i = A (X_i − C)/R, so that one
// correction takes the breathing, a squash and a turn of the whole body as well as the cells' smooth fields.
// Built by smoothed aggregation (Vaněk, Mandel & Brezina, Computing 56, 1996): the aggregates are the Voronoi cells
// of seeds spread by farthest-point sampling in hops over the constraint graph; each vertex starts with weight 1 on its
// own cell, and each smoothing pass replaces a vertex's weights by (1 − ω) its own + ω the mean of its neighbours'
// (ω = 2/3), which keeps the partition of unity and turns the cells' steps into ramps a few rings wide.
struct CoarseSpace {
  int aggregates = 0;  // the cells, and the three linear fields where it has them
  // Vertex i's weights are entries [weight_start[i], weight_start[i + 1]), aggregates ascending.
  std::vector<int> weight_start;
  std::vector<int> aggregate;
  std::vector<double> weight;
  // The 3×3 blocks (a, b), a ≥ b, of Pᵀ H P that a vertex's or a constraint's term can reach (a pair of one vertex's
  // aggregates, or of the two ends' together): block_slot[a · aggregates + b] is the block's place in the assembly's
  // compact storage (CoarsePart::blocks), −1 where no term reaches it; block_pair[slot] is its (a, b). A few thousand
  // of the dense matrix's blocks, so that the assembly writes to a store that stays in cache.
  std::vector<int> block_slot;
  std::vector<std::array<int, 2>> block_pair;
};

// Smoothing passes: ramps about this many rings wide between the cells. Measured on one step at icosphere:5
// (docs/notes/2026-12-05-vbd-coarse.md): after 16 sweeps with 256 cells the residual is 0.090 of its start with 0
// passes, 0.047 with 4 and 0.039 with 8, whose assembly costs about twice as much.
inline constexpr int kCoarseSmoothingPasses = 4;

// `solver.coarse_space: "auto"`: kAutoCoarseCells cells for a body of at least kAutoCoarseFromVertices vertices, none
// below. Measured on scenes/bounce_smooth.json through the first impact, 4 sweeps
// (docs/notes/2026-12-05-vbd-levels.md): at icosphere:5 and :6 the cells bring the centre of mass from 4.2 and 3.3 cm
// to 0.47 and 0.17 cm and the volume at :6 from 1.7 % to 0.42 %, for 1.8x the cost then (1.05x and 1.02x since the
// cells hold the linear motions and correct before every other sweep: docs/notes/2026-12-05-vbd-coarse-linear.md); at
// :3 and :4 the sweeps alone are within the goals (0.10 and 0.95 cm), and with cells :4 is no closer (the converged
// step is 2.5 cm off there).
inline constexpr int kAutoCoarseCells = 128;
inline constexpr int kAutoCoarseFromVertices = 5000;
inline int auto_coarse_cells(int vertex_count) {
  return vertex_count >= kAutoCoarseFromVertices ? kAutoCoarseCells : 0;
}

// The coarse space of a body laid out as `blocks` with `aggregates` cells (at most its vertex count) and `smoothing`
// passes, with the linear fields of the placed mesh `positions` unless it is empty.
CoarseSpace smooth_coarse_space(const VertexBlocks& blocks, int aggregates, std::span<const Vec3> positions = {},
                                int smoothing = kCoarseSmoothingPasses);

// One constraint's w_i − w_j, sparse: its aggregates and weights.
struct CoarseDifference {
  std::vector<int> aggregate;
  std::vector<double> weight;
};
// A chunk's part of Pᵀ H P (its blocks' upper triangles, in CoarseSpace's slots) and of Pᵀ∇V, with its
// own scratch. Each part on cache lines of its own: the chunks run on different threads, and `difference`'s vectors
// write their ends at every constraint (two adjacent parts made each thread 2× slower at icosphere:6).
struct alignas(64) CoarsePart {
  std::vector<double> blocks;
  Eigen::VectorXd u;
  CoarseDifference difference;
};
// The buffers one correction fills, kept between calls so that a step allocates nothing once sizes settle.
struct CoarseScratch {
  std::vector<Vec3> edge_force;                      // per constraint, its force on its first end's ∇E [N]
  std::vector<CoarsePart> parts;                     // the assembly's chunks (vertices', then constraints')
  Eigen::MatrixXd matrix;                            // Pᵀ H P [N/m], its lower triangle
  Eigen::LLT<Eigen::MatrixXd, Eigen::Lower> factor;  // of the matrix as last assembled
  bool factored = false;
  Eigen::VectorXd rhs, solution, volume_gradient;
  std::vector<Eigen::VectorXd> projection_sums;  // −Pᵀ ∇E's partial sums, per chunk
  MotionScratch search;                          // P q per vertex [m], and the line search's buffers
};

// One coarse Newton step with its line search on body `body`'s positions x: (Pᵀ H P) q = −Pᵀ ∇E with the sweeps'
// clamped, lagged H (positive definite: its inertia part alone is) and the gas's rank-one term, then a search on E's
// change along P q. Pᵀ H P is assembled and factored at x where `refresh_matrix`, else the last one is reused (any
// positive definite matrix gives a descent direction; the line search keeps the step). Returns whether it moved (it
// never raises E). `known_volume`: V(x) where the caller knows it exactly (else a pass over the faces finds it).
bool coarse_correction(const Body& body, const BodySolve& s, const CoarseSpace& space, std::span<Vec3> x,
                       bool refresh_matrix, CoarseScratch& scratch, std::optional<double> known_volume = std::nullopt);

}  // namespace sim
