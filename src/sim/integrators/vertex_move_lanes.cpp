// Four vertices' Newton steps at once, one per AVX2 lane, in vertex_move's arithmetic (see vertex_energy.cpp: each
// expression below is the one there, evaluated in the same order, without fused multiply-adds, so each lane gives the
// same bits as the scalar code).
#include "sim/integrators/vertex_move_lanes.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include "sim/integrators/lane_math.hpp"

namespace sim {
namespace {

std::atomic<bool> lanes_enabled{true};

}  // namespace

void enable_lanes(bool enabled) { lanes_enabled.store(enabled, std::memory_order_relaxed); }

#if defined(__x86_64__)

namespace {

using namespace lane_math;

// The lanes' symmetric 3×3 blocks (Block3's upper triangle).
struct LaneBlock {
  Lane xx, xy, xz, yy, yz, zz;
};
// Where `valid`: += a u uᵀ, as Block3::add_outer.
SOFTBODY_LANES_TARGET inline void add_outer(LaneBlock& h, Lane valid, Lane a, const Lane3& u) {
  const Lane ax = a * u.x, ay = a * u.y, az = a * u.z;
  h.xx = select(valid, h.xx + ax * u.x, h.xx);
  h.xy = select(valid, h.xy + ax * u.y, h.xy);
  h.xz = select(valid, h.xz + ax * u.z, h.xz);
  h.yy = select(valid, h.yy + ay * u.y, h.yy);
  h.yz = select(valid, h.yz + ay * u.z, h.yz);
  h.zz = select(valid, h.zz + az * u.z, h.zz);
}

// Row `slot` of each lane's compressed rows starting at start[l] with count[l] entries: the entry's index, or (past
// the row's end) the row's first entry or 0, valid indices that the mask discards.
inline void row_entries(const int* start, const int* count, int slot, std::size_t* index) {
  for (int l = 0; l < kLanes; ++l) {
    const int within = count[l] == 0 ? 0 : std::min(slot, count[l] - 1);
    index[l] = static_cast<std::size_t>(count[l] == 0 ? 0 : start[l] + within);
  }
}

// The four lanes' vertices and their rows of constraints and faces.
struct LaneRows {
  std::size_t vertex[kLanes];
  int first[kLanes], valence[kLanes], face_first[kLanes], faces[kLanes];
  int most = 0, most_faces = 0;  // the longest rows
};

LaneRows lane_rows(const VertexBlocks& b, const int* vertices, int count) {
  LaneRows rows;
  for (int l = 0; l < kLanes; ++l) {
    const auto v = static_cast<std::size_t>(vertices[l < count ? l : 0]);  // lanes past count repeat the first
    rows.vertex[l] = v;
    rows.first[l] = b.constraint_start[v];
    rows.valence[l] = b.constraint_start[v + 1] - rows.first[l];
    rows.face_first[l] = b.face_start[v];
    rows.faces[l] = b.face_start[v + 1] - rows.face_first[l];
    rows.most = std::max(rows.most, rows.valence[l]);
    rows.most_faces = std::max(rows.most_faces, rows.faces[l]);
  }
  return rows;
}

// vertex_terms' results in lanes, and the lanes already handed back to vertex_move.
struct LaneTerms {
  Lane3 xi, moved;        // x_i, ĥ v'_i = x_i − x̃_i [m]
  Lane3 gradient;         // ∇_i E [N]
  LaneBlock hessian;      // H_i [N/m]
  Lane3 volume_gradient;  // g_i [m²] (zero without gas)
  Lane shortest;          // the shortest constraint [m]
  Lane spring_variation;  // Σ k L0 / l² [N/m²]
  Lane refused;           // all bits set where the lane is handed back
};

// The inertia m (x − y)/ĥ², as vertex_terms starts.
SOFTBODY_LANES_TARGET LaneTerms inertia_terms(const BodySolve& s, std::span<const Vec3> x, const LaneRows& rows,
                                              int count) {
  const std::size_t* v = rows.vertex;
  LaneTerms t;
  t.refused = _mm256_cmp_pd(lanes_of(0, 1, 2, 3), splat(count), _CMP_NLT_UQ);  // the lanes past count
  t.xi = gather(x, v);
  const Lane3 target = gather(s.target, v);
  t.moved = minus(t.xi, gather(s.base, v));
  const Lane inertia =
      lanes_of(s.mass_kg[v[0]], s.mass_kg[v[1]], s.mass_kg[v[2]], s.mass_kg[v[3]]) * splat(s.inverse_h2);
  t.gradient = {inertia * (t.xi.x - target.x), inertia * (t.xi.y - target.y), inertia * (t.xi.z - target.z)};
  const Lane zero = splat(0.0);
  t.hessian = {zero + inertia, zero, zero, zero + inertia, zero, zero + inertia};
  t.volume_gradient = {zero, zero, zero};
  return t;
}

// Each constraint's spring and damper, in row order, as vertex_terms' loop (a compressed spring's transverse
// curvature clamped at zero).
SOFTBODY_LANES_TARGET void add_constraint_terms(const BodySolve& s, std::span<const Vec3> x, const LaneRows& rows,
                                                LaneTerms& t) {
  const VertexBlocks& b = s.blocks;
  const Lane zero = splat(0.0), inverse_h = splat(1.0 / s.h_hat);
  const Lane valences = lanes_of(rows.valence[0], rows.valence[1], rows.valence[2], rows.valence[3]);
  t.shortest = select(less(zero, valences), splat(std::numeric_limits<double>::infinity()), zero);
  t.spring_variation = zero;
  for (int slot = 0; slot < rows.most; ++slot) {
    std::size_t e[kLanes], j[kLanes];
    row_entries(rows.first, rows.valence, slot, e);
    for (int l = 0; l < kLanes; ++l) j[l] = static_cast<std::size_t>(b.other_end[e[l]]);
    const Lane valid = less(splat(slot), valences);
    const Lane3 xj = gather(x, j);
    const Lane3 d = minus(t.xi, xj);
    const Lane length = _mm256_sqrt_pd(dot(d, d));
    t.shortest = select(valid, select(less(length, t.shortest), length, t.shortest), t.shortest);
    t.refused = any_of(t.refused, _mm256_and_pd(valid, _mm256_cmp_pd(length, zero, _CMP_EQ_OQ)));
    const Lane inverse_length = splat(1.0) / length, rest = gather(b.rest_length_m, e);
    const Lane3 axis{inverse_length * d.x, inverse_length * d.y, inverse_length * d.z};
    const Lane k = gather(b.stiffness_N_per_m, e), c_over_h = gather(b.damping_N_s_per_m, e) * inverse_h;
    t.spring_variation =
        select(valid, t.spring_variation + k * rest * inverse_length * inverse_length, t.spring_variation);
    const Lane rate = dot(minus(t.moved, minus(xj, gather(s.base, j))), axis);  // ĥ × the approach speed [m]
    const Lane force = k * (length - rest) + c_over_h * rate;
    Lane3& g = t.gradient;
    g = {select(valid, g.x + force * axis.x, g.x), select(valid, g.y + force * axis.y, g.y),
         select(valid, g.z + force * axis.z, g.z)};
    const Lane stretch = splat(1.0) - rest * inverse_length;
    const Lane transverse = k * select(less(zero, stretch), stretch, zero);
    LaneBlock& h = t.hessian;
    h.xx = select(valid, h.xx + transverse, h.xx);
    h.yy = select(valid, h.yy + transverse, h.yy);
    h.zz = select(valid, h.zz + transverse, h.zz);
    add_outer(h, valid, k + c_over_h - transverse, axis);
  }
}

// 6 ∂V/∂x_i = Σ_f (x_b − x_i) × (x_c − x_i) over each lane's faces, as six_volume_gradient (vertex_energy.hpp) sums
// them.
SOFTBODY_LANES_TARGET Lane3 six_volume_gradient_sums(const VertexBlocks& b, std::span<const Vec3> x,
                                                     const LaneRows& rows, const Lane3& xi) {
  const Lane zero = splat(0.0);
  const Lane face_counts = lanes_of(rows.faces[0], rows.faces[1], rows.faces[2], rows.faces[3]);
  Lane3 sum{zero, zero, zero};
  for (int slot = 0; slot < rows.most_faces; ++slot) {
    std::size_t f[kLanes], corner_b[kLanes], corner_c[kLanes];
    row_entries(rows.face_first, rows.faces, slot, f);
    for (int l = 0; l < kLanes; ++l) {
      corner_b[l] = static_cast<std::size_t>(b.face_others[f[l]][0]);
      corner_c[l] = static_cast<std::size_t>(b.face_others[f[l]][1]);
    }
    const Lane valid = less(splat(slot), face_counts);
    const Lane3 u = minus(gather(x, corner_b), xi), w = minus(gather(x, corner_c), xi);
    sum = {select(valid, sum.x + (u.y * w.z - u.z * w.y), sum.x), select(valid, sum.y + (u.z * w.x - u.x * w.z), sum.y),
           select(valid, sum.z + (u.x * w.y - u.y * w.x), sum.z)};
  }
  return sum;
}

// The gas at volume V: g_i = Σ_f (x_b − x_i) × (x_c − x_i) / 6 (the same bits as vertex_terms' from the edge vectors:
// both factors negated), −P g_i in ∇E and nRT/V² g_i g_iᵀ in H.
SOFTBODY_LANES_TARGET void add_gas_terms(const BodySolve& s, std::span<const Vec3> x, const LaneRows& rows,
                                         double volume, LaneTerms& t) {
  const Lane3 sum = six_volume_gradient_sums(s.blocks, x, rows, t.xi);
  const Lane sixth = splat(1.0 / 6.0);
  t.volume_gradient = {sum.x * sixth, sum.y * sixth, sum.z * sixth};
  const Lane pressure = splat(s.gas->pressure(volume));
  Lane3& g = t.gradient;
  g = {g.x - pressure * t.volume_gradient.x, g.y - pressure * t.volume_gradient.y,
       g.z - pressure * t.volume_gradient.z};
  add_outer(t.hessian, _mm256_castsi256_pd(_mm256_set1_epi64x(-1)), splat(s.gas->stiffness(volume)), t.volume_gradient);
}

// −H⁻¹ ∇E by the adjugate, as Block3::solve and its negation in vertex_move.
SOFTBODY_LANES_TARGET Lane3 newton_step(const LaneBlock& h, const Lane3& g) {
  const Lane c_xx = h.yy * h.zz - h.yz * h.yz, c_xy = h.xz * h.yz - h.xy * h.zz, c_xz = h.xy * h.yz - h.xz * h.yy;
  const Lane c_yy = h.xx * h.zz - h.xz * h.xz, c_yz = h.xy * h.xz - h.xx * h.yz, c_zz = h.xx * h.yy - h.xy * h.xy;
  const Lane inverse_det = splat(1.0) / (h.xx * c_xx + h.xy * c_xy + h.xz * c_xz);
  return {negate(inverse_det * (c_xx * g.x + c_xy * g.y + c_xz * g.z)),
          negate(inverse_det * (c_xy * g.x + c_yy * g.y + c_yz * g.z)),
          negate(inverse_det * (c_xz * g.x + c_yz * g.y + c_zz * g.z))};
}

// The lanes whose step vertex_move would not take as sure: no descent, a negligible step (taken there without a
// search), or sure_descent's bound failing (the floor reached after the step included).
SOFTBODY_LANES_TARGET Lane unsure_steps(const BodySolve& s, const LaneTerms& t, const Lane3& step, Lane slope,
                                        double volume) {
  const Lane zero = splat(0.0);
  Lane unsure = _mm256_cmp_pd(slope, zero, _CMP_NLT_UQ);
  const Lane step2 = dot(step, step);
  unsure = any_of(unsure, _mm256_cmp_pd(step2, splat(s.negligible_step_m * s.negligible_step_m), _CMP_LE_OQ));
  if (s.floor) {
    unsure = any_of(unsure, _mm256_cmp_pd(splat(s.floor->height_m) - (t.xi.y + step.y), zero, _CMP_GT_OQ));
  }
  const Lane length = _mm256_sqrt_pd(step2);
  unsure = any_of(unsure, _mm256_cmp_pd(length, splat(0.5) * t.shortest, _CMP_NLT_UQ));
  const Lane margin = t.shortest - length, margin2 = margin * margin;
  const Lane allowed = splat(-0.5) * slope * margin2;
  const Lane length2 = length * length;
  Lane spent = splat(kSpringHessianVariation) * length * length2 * t.spring_variation * t.shortest * t.shortest;
  if (s.gas) {
    const Lane start = splat(volume), guard = splat(s.gas->guard_m3);
    const Lane after = start + dot(t.volume_gradient, step);
    const Lane least = select(less(after, guard), guard, after);
    const Lane gas = splat(s.gas->nRT_J) * dot(t.volume_gradient, t.volume_gradient) * (start - least) *
                     (start + least) / (least * least * start * start);
    spent = select(less(after, start), spent + gas * length2 * margin2, spent);
  }
  return any_of(unsure, _mm256_cmp_pd(spent, allowed, _CMP_NLE_UQ));
}

SOFTBODY_LANES_TARGET unsigned sure_moves_avx2(const BodySolve& s, const int* vertices, int count,
                                               std::span<const Vec3> x, double volume, VertexMove* moves,
                                               MoveCounts& counts) {
  const VertexBlocks& b = s.blocks;
  if (b.other_end.empty() || (s.gas && b.face_others.empty())) return 0;
  if (s.gas && volume <= s.gas->guard_m3) return 0;  // sure_descent refuses every vertex there
  // 1. ∇_i E and H_i at x_i (vertex_terms); a vertex within the smooth floor's range is handed back.
  const LaneRows rows = lane_rows(b, vertices, count);
  LaneTerms t = inertia_terms(s, x, rows, count);
  add_constraint_terms(s, x, rows, t);
  if (s.gas) add_gas_terms(s, x, rows, volume, t);
  if (s.floor) t.refused = any_of(t.refused, _mm256_cmp_pd(splat(s.floor->height_m) - t.xi.y, splat(0.0), _CMP_NLE_UQ));
  // 2. The Newton step, taken where it is sure (vertex_move, sure_descent).
  const Lane3 step = newton_step(t.hessian, t.gradient);
  const Lane slope = dot(t.gradient, step);
  const Lane refused = any_of(t.refused, unsure_steps(s, t, step, slope, volume));
  // 3. The sure lanes' moves: α = 1, E's change bounded by ¼ ∇E·Δ, V's change g_i·Δ.
  alignas(32) double sx[kLanes], sy[kLanes], sz[kLanes], dv[kLanes], bound[kLanes];
  _mm256_store_pd(sx, step.x);
  _mm256_store_pd(sy, step.y);
  _mm256_store_pd(sz, step.z);
  _mm256_store_pd(dv, dot(t.volume_gradient, step));
  _mm256_store_pd(bound, splat(0.25) * slope);
  const unsigned taken = ~static_cast<unsigned>(_mm256_movemask_pd(refused)) & ((1u << kLanes) - 1u);
  for (int l = 0; l < kLanes; ++l) {
    if ((taken & (1u << l)) == 0) continue;
    moves[l].step = Vec3(sx[l], sy[l], sz[l]);
    moves[l].volume_change_m3 = s.gas ? dv[l] : 0.0;
    moves[l].energy_bound_J = bound[l];
    ++counts.vertex_solves;
    ++counts.sure_steps;
    ++counts.lane_moves;
  }
  return taken;
}

// six_volume_gradient of vertices first .. first + 3 (six_volume_gradients_in_lanes).
SOFTBODY_LANES_TARGET void six_volume_gradients_avx2(const VertexBlocks& blocks, std::size_t first,
                                                     std::span<const Vec3> x, Vec3* six_gradient) {
  int vertices[kLanes];
  for (int l = 0; l < kLanes; ++l) vertices[l] = static_cast<int>(first) + l;
  const LaneRows rows = lane_rows(blocks, vertices, kLanes);
  const Lane3 sum = six_volume_gradient_sums(blocks, x, rows, gather(x, rows.vertex));
  double sx[kLanes], sy[kLanes], sz[kLanes];
  _mm256_storeu_pd(sx, sum.x);
  _mm256_storeu_pd(sy, sum.y);
  _mm256_storeu_pd(sz, sum.z);
  for (int l = 0; l < kLanes; ++l) six_gradient[l] = Vec3(sx[l], sy[l], sz[l]);
}

bool cpu_has_avx2() {
  static const bool has = __builtin_cpu_supports("avx2");
  return has;
}

}  // namespace

bool lanes_available() { return cpu_has_avx2(); }

bool lanes_on() { return lanes_enabled.load(std::memory_order_relaxed) && cpu_has_avx2(); }

bool lanes_serve(const BodySolve& s) { return lanes_on() && s.colliders.empty() && s.contacts == nullptr; }

bool six_volume_gradients_in_lanes(const VertexBlocks& blocks, std::size_t first, std::span<const Vec3> x,
                                   Vec3* six_gradient) {
  if (!lanes_on()) return false;
  six_volume_gradients_avx2(blocks, first, x, six_gradient);
  return true;
}
unsigned sure_moves_in_lanes(const BodySolve& s, const int* vertices, int count, std::span<const Vec3> x, double volume,
                             VertexMove* moves, MoveCounts& counts) {
  return sure_moves_avx2(s, vertices, count, x, volume, moves, counts);
}

#else

bool lanes_available() { return false; }

bool lanes_on() { return false; }

bool lanes_serve(const BodySolve&) { return false; }

bool six_volume_gradients_in_lanes(const VertexBlocks&, std::size_t, std::span<const Vec3>, Vec3*) { return false; }

unsigned sure_moves_in_lanes(const BodySolve&, const int*, int, std::span<const Vec3>, double, VertexMove*,
                             MoveCounts&) {
  return 0;
}

#endif

}  // namespace sim
