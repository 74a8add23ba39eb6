// The lane loop of vbd's sweeps at eight lanes (AVX-512F), for sure_moves_in_lanes (vertex_move_lanes.hpp) to call
// where lane_width() is 8.
#pragma once

#include <span>

#include "sim/integrators/lane_groups.hpp"
#include "sim/integrators/vertex_energy.hpp"
#include "sim/integrators/vertex_moves.hpp"

namespace sim::avx512_lanes {

// sure_moves_in_lanes for count ≤ 8 vertices. Only on a CPU with AVX-512F.
unsigned sure_moves_in_eight(const BodySolve& s, const LaneGroups& groups, int group, const int* vertices, int count,
                             std::span<const Vec3> x, double volume, VertexMove* moves, MoveCounts& counts);

}  // namespace sim::avx512_lanes
