// Four or eight vertices of one colour moved at once, one per SIMD lane (AVX2, four doubles; AVX-512F, eight): each
// lane does vertex_move's arithmetic in vertex_move's order, so a lane's step is the same bits as vertex_move's at
// either width.
#pragma once

#include <span>

#include "sim/integrators/lane_groups.hpp"
#include "sim/integrators/vertex_energy.hpp"
#include "sim/integrators/vertex_moves.hpp"

namespace sim {

inline constexpr int kLanes = 4;  // AVX2's lanes (kMostLanes, lane_groups.hpp: AVX-512's)

// Whether the lanes serve body `s` on this machine: the CPU has AVX2, and the body's terms are inertia, springs,
// dampers, the gas and at most a smooth floor (no smooth colliders or body contacts, whose terms take their own paths).
bool lanes_serve(const BodySolve& s);

// Whether this CPU runs the lanes (AVX2), and eight of them (AVX-512F).
bool lanes_available();
bool wide_lanes_available();

// Whether the lanes run now: this CPU has AVX2 and they are enabled (the edge lanes of the coarse corrections,
// correction_lanes.hpp, follow the same switch).
bool lanes_on();

// Switches the lanes off (false) or on again, for the whole program: the tests and benchmarks that compare them with
// the scalar path. On by default.
void enable_lanes(bool enabled);

// Switches the eight lanes off (false: four where the lanes run) or on again, for the whole program, as enable_lanes.
// On by default.
void enable_wide_lanes(bool enabled);

// How many vertices sure_moves_in_lanes takes at once now: 8 where the lanes run and the CPU has AVX-512F (unless
// switched off), else 4 (the width of the LaneGroups to build, lane_groups.hpp).
int lane_width();

// The moves of group `group` of `groups` (lane_groups.hpp, groups.width = lane_width()): its vertices[0 .. count) of
// one colour, from x with the body's volume V, for the lanes whose Newton step is certain without a line search
// (sure_descent) and touches no floor: their moves[l] are set and bit l of the result. The others (a step for the line
// search, a negligible or non-descending step, a vertex in or reaching the floor's range, coincident ends) are left to
// vertex_move. Adds the moves it made to counts.
unsigned sure_moves_in_lanes(const BodySolve& s, const LaneGroups& groups, int group, const int* vertices, int count,
                             std::span<const Vec3> x, double volume, VertexMove* moves, MoveCounts& counts);

// six_volume_gradient(blocks, i, x) of the four vertices i = first .. first + 3 into six_gradient[0 .. 4), by the
// lanes' sums of the gas terms. Returns whether it did (false where the lanes do not run).
bool six_volume_gradients_in_lanes(const VertexBlocks& blocks, std::size_t first, std::span<const Vec3> x,
                                   Vec3* six_gradient);

}  // namespace sim
