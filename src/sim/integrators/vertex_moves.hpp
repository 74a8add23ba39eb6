// One vertex's move in vbd's sweeps, and a colour's moves taken at once (on threads), with the safeguard on their
// joint change of the gas's energy.
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "sim/integrators/lane_groups.hpp"
#include "sim/integrators/vertex_energy.hpp"
#include "sim/step/chunk_claims.hpp"
#include "sim/step/part_runner.hpp"

namespace sim {

// What the local solves counted.
struct MoveCounts {
  long long vertex_solves = 0;  // local Newton steps tried
  long long sure_steps = 0;     // of those, steps taken without a line search (sure_descent)
  long long lane_moves = 0;     // of those, steps taken four at a time (sim/integrators/vertex_move_lanes.hpp)
  long long halvings = 0;       // line-search step halvings
  long long refused_moves = 0;  // local steps no halving made lower E: the vertex stayed

  MoveCounts& operator+=(const MoveCounts& other);
};

// A vertex's Newton step after its line search, not yet applied.
struct VertexMove {
  Vec3 step = Vec3::Zero();       // Δx_i [m]
  double volume_change_m3 = 0.0;  // g_i·Δ: V's exact change (V is affine in x_i) [m³]
  // An upper bound on E's change along the step, ≤ 0 [J]: the searched change where the line search ran, ¼ ∇E·Δ where
  // the step was sure (sure_descent), 0 for a step below round-off or none.
  double energy_bound_J = 0.0;
};

// Vertex i's Newton step on E as a function of x_i alone, H_i Δ = −∇_i E, at x with the body's volume V, and its
// backtracking line search (Armijo, α = 1, ½, ...; skipped where sure_descent proves the step or it is negligible).
VertexMove vertex_move(const BodySolve& s, int i, std::span<const Vec3> x, double volume, ConstraintLags& lags,
                       MoveCounts& counts);

// Scratch for colours moved at once: per part its lags, counts and chunks not yet taken, per vertex of the colour its
// start and bounds.
struct ColourScratch {
  std::vector<ConstraintLags> lags;
  std::vector<MoveCounts> counts;
  std::unique_ptr<ChunkClaims[]> claims;  // atomics: sized once by hand, not a vector
  int claim_parts = 0;                    // claims' size
  std::vector<Vec3> start;                // x_i before the moves [m]
  std::vector<double> volume_change;      // [m³]
  std::vector<double> energy_bound;       // [J]
};

// How a colour's vertices are split among threads: part p, thread p's own (what is left of it goes to the threads done
// with theirs), is the slots (positions in the colour) slots[bounds[p] .. bounds[p + 1]); no bounds: one part, the
// colour in order. The lanes take each part's vertices in the groups of
// `groups` (lane_groups.hpp) for colour `colour`, of the lanes' width (lane_width(), vertex_move_lanes.hpp).
struct ColourParts {
  std::span<const int> slots;
  std::span<const int> bounds;
  const LaneGroups* groups = nullptr;
  int colour = 0;
};

// A colour's vertices (no two share a constraint, a face or a bending link) moved at once, each by its vertex_move
// from x with the body's V at the colour's start: the springs, dampers, inertia, floor and colliders of one vertex
// touch no other vertex of the colour, so only the gas couples their moves. Their joint change of E is
//   ΔE ≤ Σ_i bound_i + R(S),  S = Σ_i ΔV_i,  R(S) = E_gas(V + S) − E_gas(V) − E_gas'(V) S ≥ 0,
// as each local change counted E_gas(V + ΔV_i) − E_gas(V) = E_gas'(V) ΔV_i + R(ΔV_i) with R(ΔV_i) ≥ 0 (E_gas is
// convex in V). Where that bound is not below zero the moves are undone (x as it was) and it returns false: the
// caller then visits the colour one vertex at a time. Otherwise volume += S. The parts run on runner's
// threads, in chunks that a thread done with its own part takes from the others'; every vertex moves from the colour's
// start and every sum runs in the colour's order, so the result is the same bits on any split, number of threads and
// hand-out of chunks. Not for body contacts (they couple vertices of one colour).
bool move_colour_at_once(const BodySolve& s, std::span<const int> colour, std::span<Vec3> x, double& volume,
                         PartRunner& runner, const ColourParts& parts, ColourScratch& scratch, MoveCounts& counts);

}  // namespace sim
