// The affine coarse correction of several bodies at once, coupled by their smooth contacts (vbd's sweeps with the
// smooth contact between bodies, sim/integrators/vertex_block_descent.hpp).
#pragma once

#include <span>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "sim/integrators/affine_correction.hpp"
#include "sim/integrators/vertex_contacts.hpp"
#include "sim/model/model.hpp"

namespace sim {

// A stack of bodies passes its weight down one body per sweep when each body's affine correction holds the others
// where they are (measured: two balls stacked at 1/60 s with 4 sweeps sag 9 cm), so before each sweep one Newton step
// on every body's affine motions at once: the bodies' own systems (affine_correction.hpp, their contact terms left
// out) on the block diagonal, and each contact's K coupling the bodies of its vertices. A contact moves r by
// Σ_b (A_b u_b + s_b t_b), u_b = Σ_{j ∈ b} c_j (x_j − c_b), s_b = Σ_{j ∈ b} c_j (c_j as in vertex_contacts.hpp; for a
// self-contact s_b = 0), so it adds P_aᵀ K P_b to block (a, b) and P_bᵀ ∇_r E_c to body b's gradient, P_b q = A_b u_b
// + s_b t_b. A line search on E's change over all the bodies keeps the step a descent. It takes the place of the
// bodies' own affine corrections (measured on two stacked balls: the same stack at about half the cost of both).
inline constexpr std::size_t kMostJointBodies = 16;  // the dense system has 12 unknowns per body

struct JointAffineScratch {
  std::vector<AffineScratch> bodies;  // per body: its system's buffers and its motion's line search
  std::vector<AffineSystem> systems;  // per body
  Eigen::MatrixXd matrix;
  Eigen::LDLT<Eigen::MatrixXd> factor;  // of the matrix (its storage kept between calls)
  Eigen::VectorXd gradient, rhs, step;
  std::vector<Vec3> motion;  // every vertex of the model [m]
};

// One joint step on the positions x (every vertex of the model); `solves`: per body, its BodySolve without contacts.
// Returns whether it moved (never where it would raise E). Does nothing for more than kMostJointBodies bodies (then the
// bodies take their own affine corrections).
bool joint_affine_correction(const Model& model, std::span<const BodySolve> solves, const VertexContacts& contacts,
                             std::span<Vec3> x, JointAffineScratch& scratch);

}  // namespace sim
