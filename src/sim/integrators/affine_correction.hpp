// The affine coarse correction of vbd's sweeps (sim/integrators/vertex_block_descent.hpp).
#pragma once

#include <Eigen/Dense>

#include <optional>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "sim/integrators/motion_search.hpp"
#include "sim/integrators/vertex_energy.hpp"
#include "sim/model/body.hpp"

namespace sim {

// The affine coarse correction (a two-level method: Gauss–Seidel smooths what is local, one Galerkin Newton step on a
// coarse space takes out what crosses the body, which a sweep moves by one ring of vertices only: the momentum a
// floor takes from the whole body, the gas's breathing, a squash). The coarse space is every affine motion of the
// body, δx_i = A (x_i − c) + t (A 3×3, t 3: q, 12 unknowns; c its centroid), δx = B q. The step solves
// (Bᵀ H B) q = −Bᵀ ∇E with the sweeps' clamped, lagged H (Bᵀ H B is positive definite: its inertia part alone is),
// then searches α on E's change along B q as a vertex does (sim/integrators/motion_search.hpp).
// The buffers one correction fills, kept between calls so that a step allocates nothing once sizes settle.
struct CoarseSums;  // a chunk's part of the assembly (affine_correction.cpp)
struct MassSums;    // a chunk's part of the centre of mass
struct AffineScratch {
  AffineScratch();
  ~AffineScratch();
  AffineScratch(AffineScratch&&) noexcept;
  AffineScratch& operator=(AffineScratch&&) noexcept;
  MotionScratch search;  // B q per vertex [m], the line search's buffers, and V after the call
  Eigen::LDLT<Eigen::Matrix<double, 12, 12>> factor;  // of Bᵀ H B, as the last assembly left it
  std::vector<CoarseSums> sums;                       // the assembly's partial sums, per chunk
  std::vector<MassSums> mass_sums;                    // the centre of mass's, per chunk
  std::vector<double> volume_sums;                    // the volume's, per chunk
};

// One coarse Newton step with its line search on body `body`'s positions x. Returns whether it moved. `assemble`:
// whether to assemble and factor Bᵀ H B afresh; otherwise the factor of the last call that did is reused (at the
// step's later sweeps: a lagged matrix is still positive definite, so the step is still a descent direction, and the
// search still takes only a move that lowers E). `known_volume`: V(x) where the caller knows it exactly (else a pass
// over the faces finds it).
bool affine_correction(const Body& body, const BodySolve& s, std::span<Vec3> x, AffineScratch& scratch,
                       bool assemble = true, std::optional<double> known_volume = std::nullopt);

// The coarse system of that step at x: Bᵀ H B and Bᵀ ∇E over the 12 unknowns (A row-major, then t), about the centre
// of mass c, and V(x) (0 without gas).
struct AffineSystem {
  Eigen::Matrix<double, 12, 12> matrix;
  Eigen::Matrix<double, 12, 1> gradient;
  Vec3 centre = Vec3::Zero();
  double volume = 0.0;
};
// With `assemble` false the matrix is left zero (the gradient only). Either way the constraints' lags for the line
// search are left in scratch.search, and so are the floor's and colliders'. `known_volume` as affine_correction's.
AffineSystem affine_system(const Body& body, const BodySolve& s, std::span<const Vec3> x, AffineScratch& scratch,
                           bool assemble = true, std::optional<double> known_volume = std::nullopt);
// B q: the motion A (x_i − c) + t of every vertex into search.motion, and A into search.linear_part.
void affine_motion(const Eigen::Matrix<double, 12, 1>& q, std::span<const Vec3> x, const Vec3& centre,
                   MotionScratch& search, PartRunner* runner = nullptr);

}  // namespace sim
