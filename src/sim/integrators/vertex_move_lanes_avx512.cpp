// Eight vertices' Newton steps at once, one per AVX-512 lane: the lane loop (vertex_move_lanes.inc) at eight lanes.
// This file is compiled with -ffp-contract=off (CMakeLists.txt), as lane_math_avx512.hpp asks.
#include "sim/integrators/vertex_move_lanes_avx512.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sim/integrators/lane_math_avx512.hpp"

namespace sim::avx512_lanes {

#if defined(__x86_64__)

namespace {
using namespace lane_math_avx512;
#define LANES_TARGET SOFTBODY_WIDE_LANES_TARGET
#include "sim/integrators/vertex_move_lanes.inc"
#undef LANES_TARGET
}  // namespace

unsigned sure_moves_in_eight(const BodySolve& s, const LaneGroups& groups, int group, const int* vertices, int count,
                             std::span<const Vec3> x, double volume, VertexMove* moves, MoveCounts& counts) {
  return sure_moves(s, groups, group, vertices, count, x, volume, moves, counts);
}

#else

unsigned sure_moves_in_eight(const BodySolve&, const LaneGroups&, int, const int*, int, std::span<const Vec3>, double,
                             VertexMove*, MoveCounts&) {
  return 0;
}

#endif

}  // namespace sim::avx512_lanes
