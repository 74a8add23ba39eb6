// The line search of vbd's coarse corrections (sim/integrators/affine_correction.hpp, coarse_space.hpp): the step
// energy's change along a motion of a whole body, and the backtracking on it.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include <Eigen/Dense>

#include "sim/integrators/vertex_energy.hpp"
#include "sim/model/body.hpp"

namespace sim {

// The buffers one search fills, kept between calls so that a step allocates nothing once sizes settle.
struct MotionScratch {
  std::vector<Vec3> motion;  // the motion per vertex, filled by the caller [m]
  // Where the motion is affine, δx = A (x − c) + t, its A, set by the caller: then V(x + α motion) = det(I + αA) V(x)
  // (a closed surface), so the search needs no volume pass. Otherwise unset.
  std::optional<Eigen::Matrix3d> linear_part;
  // The lags, taken at x by the caller in the pass over the constraints and the vertices that its gradient makes
  // anyway (take_edge_lag; add_floor_terms and add_collider_terms return theirs), once for the whole search.
  // Per constraint: l [m], 1/l [1/m] and ĥ × its approach speed [m].
  std::vector<double> edge_length_m, edge_inverse_length, edge_rate_m;
  void size_edge_lags(std::size_t constraints) {
    edge_length_m.resize(constraints);
    edge_inverse_length.resize(constraints);
    edge_rate_m.resize(constraints);
  }
  double volume_after = 0.0;               // V where the search left x [m³]
  std::vector<Vec3> trial;                 // x + α motion, for the gas's volume [m]
  std::vector<FloorLag> floor_lags;        // per vertex, with a floor
  std::vector<ColliderLag> collider_lags;  // per smooth collider, per vertex: collider c's at [c n + i]
  void size_contact_lags(const BodySolve& s, std::size_t vertices) {
    if (s.floor) floor_lags.resize(vertices);
    collider_lags.resize(s.colliders.size() * vertices);
  }
  std::vector<double> energy_sums, volume_sums;  // partial sums per chunk (sim/step/chunked_sum.hpp)
};

// Moves body `body`'s positions x by α scratch.motion with the largest α of 1, ½, ¼, … (down to 1e-3) whose change of
// E is a sufficient decrease (Armijo, kArmijo α slope); `slope` = ∇E·motion < 0 [J], `volume` = V(x) [m³] (unused
// without gas). The dampers' directions and the floor's and colliders' weights are lagged at x, as the vertices' own
// line searches lag them (scratch's lags, which the caller took at x). Returns whether it moved; scratch.volume_after
// is V at the new x.
bool search_along_motion(const Body& body, const BodySolve& s, std::span<Vec3> x, double volume, double slope,
                         MotionScratch& scratch);

// Constraint e's lags at x (its length, inverse and ĥ × approach speed) into scratch, sized by size_edge_lags, for a
// pass over the constraints that the caller makes anyway.
void take_edge_lag(const DistanceConstraints& constraints, const BodySolve& s, std::span<const Vec3> x, std::size_t e,
                   MotionScratch& scratch);

// The search's part for a search over several bodies at once (joint_affine_correction.hpp): E's change along
// α scratch.motion with scratch's lags.
double motion_energy_change(const Body& body, const BodySolve& s, std::span<const Vec3> x, double volume, double alpha,
                            MotionScratch& scratch);

}  // namespace sim
