// Four or eight vertices' Newton steps at once, one per SIMD lane, in vertex_move's arithmetic (the lane loop,
// vertex_move_lanes.inc, at four lanes here and at eight in vertex_move_lanes_avx512.cpp), and the switches that choose
// between them and the scalar code.
#include "sim/integrators/vertex_move_lanes.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include "sim/integrators/lane_math.hpp"
#include "sim/integrators/vertex_move_lanes_avx512.hpp"

namespace sim {
namespace {

std::atomic<bool> lanes_enabled{true};
std::atomic<bool> wide_lanes_enabled{true};

}  // namespace

void enable_lanes(bool enabled) { lanes_enabled.store(enabled, std::memory_order_relaxed); }

void enable_wide_lanes(bool enabled) { wide_lanes_enabled.store(enabled, std::memory_order_relaxed); }

#if defined(__x86_64__)

// The lane loop at four lanes (vertex_move_lanes.inc).
namespace avx2_lanes {
namespace {
using namespace lane_math;
#define LANES_TARGET SOFTBODY_LANES_TARGET
#include "sim/integrators/vertex_move_lanes.inc"
#undef LANES_TARGET
}  // namespace
}  // namespace avx2_lanes

namespace {

using namespace lane_math;

// six_volume_gradient of vertices first .. first + 3 (six_volume_gradients_in_lanes), their faces from the blocks'
// rows (the lanes past a row's end take its last face, discarded).
SOFTBODY_LANES_TARGET void six_volume_gradients_avx2(const VertexBlocks& blocks, std::size_t first,
                                                     std::span<const Vec3> x, Vec3* six_gradient) {
  int face_first[kLanes], faces[kLanes], most_faces = 0;
  std::size_t vertex[kLanes];
  for (int l = 0; l < kLanes; ++l) {
    vertex[l] = first + static_cast<std::size_t>(l);
    face_first[l] = blocks.face_start[vertex[l]];
    faces[l] = blocks.face_start[vertex[l] + 1] - face_first[l];
    most_faces = std::max(most_faces, faces[l]);
  }
  const auto corners = [&](int slot, std::size_t* corner_b, std::size_t* corner_c) {
    for (int l = 0; l < kLanes; ++l) {
      const auto f = static_cast<std::size_t>(row_entry(face_first[l], faces[l], slot));
      corner_b[l] = static_cast<std::size_t>(blocks.face_others[f][0]);
      corner_c[l] = static_cast<std::size_t>(blocks.face_others[f][1]);
    }
  };
  const Lane3 sum = avx2_lanes::six_volume_gradient_sums(x, from_ints(faces), most_faces, gather(x, vertex), corners);
  double sx[kLanes], sy[kLanes], sz[kLanes];
  store(sx, sum.x);
  store(sy, sum.y);
  store(sz, sum.z);
  for (int l = 0; l < kLanes; ++l) six_gradient[l] = Vec3(sx[l], sy[l], sz[l]);
}

bool cpu_has_avx2() {
  static const bool has = __builtin_cpu_supports("avx2");
  return has;
}

bool cpu_has_avx512() {
  static const bool has = __builtin_cpu_supports("avx512f");
  return has;
}

}  // namespace

bool lanes_available() { return cpu_has_avx2(); }

bool wide_lanes_available() { return cpu_has_avx512(); }

bool lanes_on() { return lanes_enabled.load(std::memory_order_relaxed) && cpu_has_avx2(); }

bool lanes_serve(const BodySolve& s) { return lanes_on() && s.colliders.empty() && s.contacts == nullptr; }

int lane_width() {
  return lanes_on() && wide_lanes_enabled.load(std::memory_order_relaxed) && cpu_has_avx512() ? kMostLanes : kLanes;
}

bool six_volume_gradients_in_lanes(const VertexBlocks& blocks, std::size_t first, std::span<const Vec3> x,
                                   Vec3* six_gradient) {
  if (!lanes_on()) return false;
  six_volume_gradients_avx2(blocks, first, x, six_gradient);
  return true;
}

unsigned sure_moves_in_lanes(const BodySolve& s, const LaneGroups& groups, int group, const int* vertices, int count,
                             std::span<const Vec3> x, double volume, VertexMove* moves, MoveCounts& counts) {
  if (groups.width == kMostLanes) {
    return avx512_lanes::sure_moves_in_eight(s, groups, group, vertices, count, x, volume, moves, counts);
  }
  return avx2_lanes::sure_moves(s, groups, group, vertices, count, x, volume, moves, counts);
}

#else

bool lanes_available() { return false; }

bool wide_lanes_available() { return false; }

bool lanes_on() { return false; }

int lane_width() { return kLanes; }

bool lanes_serve(const BodySolve&) { return false; }

bool six_volume_gradients_in_lanes(const VertexBlocks&, std::size_t, std::span<const Vec3>, Vec3*) { return false; }

unsigned sure_moves_in_lanes(const BodySolve&, const LaneGroups&, int, const int*, int, std::span<const Vec3>, double,
                             VertexMove*, MoveCounts&) {
  return 0;
}

#endif

}  // namespace sim
