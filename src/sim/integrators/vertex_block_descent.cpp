// Vertex block descent: its steps within the driver's (impacts, doubling), their BDF2 targets, the sweeps, and one
// vertex's Newton step with its line search.
#include "sim/integrators/vertex_block_descent.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/profile.hpp"
#include "sim/contact/collider_shape.hpp"
#include "sim/forces/forces.hpp"
#include "sim/integrators/affine_correction.hpp"
#include "sim/integrators/correction_lanes.hpp"
#include "sim/integrators/joint_affine_correction.hpp"
#include "sim/integrators/vertex_move_lanes.hpp"
#include "sim/step/breathing_mode.hpp"
#include "sim/step/chunked_sum.hpp"

namespace sim {
namespace {

// A Newton step shorter than this fraction of the body's mean edge is taken without a line search: E's change is then
// below its own round-off (about k ε l |l − L0| for a spring), so the test could only refuse a harmless move.
constexpr double kNegligibleStep = 1e-8;
// Around an impact on the smooth floor, a smooth collider or another body (smooth contact) the steps shrink to ω h ≤
// solver.impact_phase (ω = 1/τ, the contact's spring per unit mass; the impact lasts about π/ω). On the floor and a
// collider a step counts as an impact where the vertices in or reaching it within the step carry normal momentum
// whose force change within the contact's time constant, Σ m |v·n| ω, exceeds the body's mass times
// kImpactAcceleration (the body at 1 cm/s at the default τ = 2 ms, docs/notes/2026-12-05-vbd.md): a roll or a rest,
// whose vertices touch down slowly, keeps full steps, and a stiffer contact, which lets go at slower speeds, keeps its
// short steps until the body has left it (docs/notes/2026-12-08-vbd-stiff-floor-release.md).
constexpr double kImpactAcceleration = 5.0;  // m/s²
// The smooth contact between bodies: an impact where that momentum exceeds the body's at this speed (its default τ is
// 0.5 ms; the rule above is not measured there).
constexpr double kBodyImpactSpeed = 0.01;  // m/s
// The steps within a driver's step dt are dt / 2^level, level 0 to kDeepestLevel, so that they always tile it.
constexpr int kDeepestLevel = 12;
// A run starts at this level with backward Euler (whose first step leaves a free fall ½ h² g off for good; the gas's
// first push is the fastest motion of a run that starts at the rest shape) and doubles from there, except where the
// full steps would damp out every body's breathing anyway (step).
constexpr int kStartLevel = 4;
// The steps double only where BDF2's local error at twice the step, (2/9)(2h)³|x‴| ≈ (16/9) h |Δ²v|, is below this
// fraction of the body's mean edge at every vertex (a motion that is still settling, e.g. a buckling start, gained
// energy where the steps doubled regardless).
constexpr double kGrowthTolerance = 1e-2;
// The smooth body contacts (their nearest triangles, frames, dashpot weights and friction forces) are found at the
// step's start for its first sweep and lagged at the iterate before every later one, so that the sweeps' fixed point is
// BDF2 of the contact force. Lagged once per step (at its start) two stacked balls cost 10-25 % less at 4-8 sweeps and
// stack as well, but 1000 sweeps then leave a BDF2 residual of 168 N of 179 N (docs/notes/2026-12-05-vbd-contact.md).
constexpr bool kLagEverySweep = true;
// The coarse level's matrix is assembled at every this-many-th step within one call of step() (and where h changes),
// and its correction taken before every this-many-th sweep of a step (the first included). On the bounce
// (scenes/bounce_smooth.json, 4 sweeps) at icosphere:5 and :6 every 8th matrix and every 2nd sweep cost 0.76x what
// every 4th matrix and every sweep did, with the same volume errors and centres of mass within 0.06 cm
// (docs/notes/2026-12-05-vbd-coarse-linear.md; every 4th matrix against every one:
// docs/notes/2026-12-05-vbd-levels.md).
constexpr long long kCoarseMatrixSteps = 8;
constexpr int kCoarseEverySweeps = 2;
// Where the sweeps go on until still ("converge", "auto"), an impact's steps take those corrections (the coarse level's
// or the affine one) before their first this-many sweeps only: the later sweeps settle the contact patch, which a
// correction on the body's smooth fields does not move. On the bounce with "auto" the sweeps per step stayed the same
// (5.51 at icosphere:4, 8.29 -> 8.33 at :5) for 0.88x the CPU time at both, the centre of mass 0.71 -> 0.69 cm and
// 0.39 -> 0.48 cm off through the first impact (after the first sweep only: 0.66 cm and 0.81 cm;
// docs/notes/2026-12-07-vbd-vertex-order.md).
constexpr int kImpactCorrectedSweeps = 3;

// Whether a and b are the same step size (both made by std::ldexp of one dt).
bool same_step(double a, double b) { return std::abs(a - b) <= 1e-12 * std::max(a, b); }

bool has_history(const std::vector<Vec3>& x, const std::vector<Vec3>& v, double dt, std::size_t n) {
  return x.size() == n && v.size() == n && dt > 0.0;
}

// The lowest height of the free path y + v_y t + ½ g_y t² over [0, h] [m]: an end, or its vertex where g_y > 0.
double lowest_on_free_path(double y, double v_y, double g_y, double h) {
  if (g_y > 0.0 && v_y < 0.0 && -v_y / g_y < h) return y - 0.5 * v_y * v_y / g_y;
  return std::min(y, y + h * v_y + 0.5 * g_y * h * h);
}

}  // namespace

void VertexBlockDescent::prepare_once(const Model& model) {
  if (blocks_.size() == model.bodies.size()) return;
  blocks_.clear();
  coarse_spaces_.clear();
  int most_constraints = 0;
  for (const Body& body : model.bodies) {
    blocks_.push_back(vertex_blocks(body));
    most_constraints = std::max(most_constraints, blocks_.back().most_constraints);
    const int cells = aggregates_ == kAutoAggregates ? auto_coarse_cells(body.vertex_count) : aggregates_;
    coarse_spaces_.push_back(cells > 0 ? smooth_coarse_space(blocks_.back(), cells, body.rest.position_m)
                                       : CoarseSpace{});
  }
  lags_.resize(static_cast<std::size_t>(most_constraints));
  smooth_floor_.reset();
  if (model.floor && model.floor->contact == FloorContact::Smooth) smooth_floor_ = resolve_smooth_floor(*model.floor);
  smooth_colliders_.clear();
  for (const Collider& collider : model.colliders) {
    if (collider.contact == FloorContact::Smooth) smooth_colliders_.push_back(resolve_smooth_collider(collider));
  }
  lags_.colliders.resize(smooth_colliders_.size());
  contacts_.build(model);
}

void VertexBlockDescent::pose_smooth_colliders(const Model& model, double time_s) {
  std::size_t c = 0;
  for (const Collider& collider : model.colliders) {
    if (collider.contact != FloorContact::Smooth) continue;
    if (collider.motion.moving()) smooth_colliders_[c] = resolve_smooth_collider(collider, time_s);
    ++c;
  }
}

double VertexBlockDescent::set_targets(const Model& model, State& state, double h, double ratio,
                                       const std::vector<Vec3>& x_previous, const std::vector<Vec3>& v_previous) {
  const std::size_t n = state.x.size();
  target_.resize(n);
  base_.resize(n);
  // Variable-step BDF2 with ω = h_n/h_{n−1} (Hairer, Nørsett & Wanner, "Solving ODEs I", Sect. III.5):
  //   x' − x̃ = ĥ v', x̃ = ((1+ω)² x_n − ω² x_{n−1})/(1+2ω), ĥ = h (1+ω)/(1+2ω); ω = 1: (4x_n − x_{n−1})/3, 2h/3.
  const bool bdf2 = ratio > 0.0;
  const double a = bdf2 ? (1.0 + ratio) * (1.0 + ratio) / (1.0 + 2.0 * ratio) : 1.0;  // weight of step n
  const double b = a - 1.0;                                                           // of step n − 1
  const double h_hat = bdf2 ? h * (1.0 + ratio) / (1.0 + 2.0 * ratio) : h;
  const Vec3 fall = (h_hat * h_hat) * model.gravity_m_per_s2;  // ĥ² g [m]
  start_x_.resize(n);
  start_v_.resize(n);
  // One pass on the threads: x̃ and y, the step's start kept (the next step's history), and y as the first iterate.
  chunked_for(runner_, n, [&](std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last; ++i) {
      if (bdf2) {
        base_[i] = a * state.x[i] - b * x_previous[i];                                // x̃
        target_[i] = base_[i] + h_hat * (a * state.v[i] - b * v_previous[i]) + fall;  // x̃ + ĥ ṽ + ĥ² g
      } else {
        base_[i] = state.x[i];
        target_[i] = state.x[i] + h * state.v[i] + fall;
      }
      start_x_[i] = state.x[i];
      start_v_[i] = state.v[i];
      state.x[i] = target_[i];
    }
  });
  return h_hat;
}

BodySolve VertexBlockDescent::body_solve(const Model& model, std::size_t b, double h_hat) const {
  const Body& body = model.bodies[b];
  BodySolve s{blocks_[b],
              Model::of(body, model.mass_kg),
              Model::of(body, target_),
              Model::of(body, base_),
              h_hat,
              kNegligibleStep * body.rest.mean_edge_m,
              1.0 / (h_hat * h_hat),
              std::nullopt,
              smooth_floor_ ? &*smooth_floor_ : nullptr,
              smooth_colliders_};
  if (body.params.pressure_J != 0.0) s.gas = GasLaw{body.params.pressure_J, guarded_volume(0.0, body.rest.volume_m3)};
  s.first_vertex = body.first_vertex;
  s.runner = runner_;
  return s;
}

double VertexBlockDescent::sweep_body(const Model& model, std::size_t b, double h_hat, std::vector<Vec3>& all_x,
                                      int first_sweep, int count, std::optional<double> carried_volume) {
  const Body& body = model.bodies[b];
  BodySolve s = body_solve(model, b, h_hat);
  if (contacts_.active()) s.contacts = &contacts_;
  const std::span<Vec3> x = Model::of(body, all_x);
  for (int sweep = first_sweep; sweep < first_sweep + count; ++sweep) {
    // The affine correction before every sweep where the body has no coarse level (whose space holds the affine
    // motions too; it corrects before every kCoarseEverySweeps-th sweep): its matrix assembled at the step's first
    // sweep, or where the scratch holds another body's.
    const bool corrected = !(impact_step_ && sweeps_until_still()) || sweep < kImpactCorrectedSweeps;
    const bool coarse_level = coarse_spaces_[b].aggregates > 0;
    const bool own_affine = coarse_ && !joint_affine_ && !coarse_level && corrected;
    if (own_affine) {
      affine_correction(body, s, x, coarse_scratch_, sweep == 0 || affine_body_ != b, carried_volume);
      affine_body_ = b;
    }
    const bool coarse_now = coarse_level && sweep % kCoarseEverySweeps == 0 && corrected;
    if (coarse_now) {
      // Its matrix is assembled afresh where the scratch holds another body's, at a step of another h, and at every
      // kCoarseMatrixSteps-th step within one call of step() (the first included, so that a run resumed from a copied
      // State refreshes where the original did); otherwise the last matrix stays (a lagged matrix still gives a
      // descent direction, and the search keeps only a move that lowers E).
      bool refresh = coarse_level_body_ != b;
      if (sweep == 0) {
        refresh = refresh || h_hat != coarse_matrix_h_ || coarse_matrix_age_ % kCoarseMatrixSteps == 0;
        ++coarse_matrix_age_;
        coarse_matrix_h_ = h_hat;
      }
      coarse_correction(body, s, coarse_spaces_[b], x, refresh, coarse_level_scratch_, carried_volume);
      coarse_level_body_ = b;
    }
    if (own_affine || coarse_now) ++statistics_.corrections;
    // V at the sweep's start: the correction's, which ends with a volume pass or an exact change; else where the sweep
    // before ended, its colours having kept it exact (V is affine in each vertex; the pass over the faces took 7 % of
    // a flight step at icosphere:5); else a pass. A correction starts from the sweep before's V too.
    double volume = 0.0;
    if (s.gas) {
      if (coarse_now) {
        volume = coarse_level_scratch_.search.volume_after;
      } else if (own_affine) {
        volume = coarse_scratch_.search.volume_after;
      } else if (carried_volume) {
        volume = *carried_volume;
      } else {
        volume = enclosed_volume_in_lanes(body.topology.faces, x, runner_, volume_sums_);
      }
    }
    sweep_colours(s, shares_[b], lane_groups_[b], x, volume);
    carried_volume = volume;
  }
  return carried_volume.value_or(0.0);
}

bool VertexBlockDescent::sweep_was_still(std::span<const Body> bodies, const std::vector<Vec3>& all_x) const {
  for (const Body& body : bodies) {
    const double step_scale = holds_its_error() ? std::min(1.0, step_s_ / kConvergedMoveStep) : 1.0;
    const double allowed = kConvergedMove * step_scale * body.rest.mean_edge_m;  // [m]
    const auto x = Model::of(body, all_x), before = Model::of(body, sweep_start_);
    for (std::size_t i = 0; i < x.size(); ++i) {
      if ((x[i] - before[i]).squaredNorm() > allowed * allowed) return false;
    }
  }
  return true;
}

void VertexBlockDescent::sweep_body_to_the_end(const Model& model, std::size_t b, double h_hat, std::vector<Vec3>& x) {
  if (!sweeps_until_still()) {
    sweep_body(model, b, h_hat, x, 0, sweeps_);
    statistics_.sweeps += sweeps_;
    return;
  }
  const Body& body = model.bodies[b];
  const std::span<const Body> just_this(&body, 1);
  sweep_start_.resize(x.size());
  std::optional<double> volume;  // where the sweep before ended
  for (int sweep = 0; sweep < kMostConvergeSweeps; ++sweep) {
    const auto now = Model::of(body, std::as_const(x));
    std::copy(now.begin(), now.end(), Model::of(body, sweep_start_).begin());
    volume = sweep_body(model, b, h_hat, x, sweep, 1, volume);
    ++statistics_.sweeps;
    if (sweep + 1 >= kLeastConvergeSweeps && sweep_was_still(just_this, x)) return;
  }
}

void VertexBlockDescent::sweep_in_contact(const Model& model, double h_hat, std::vector<Vec3>& x) {
  joint_affine_ = coarse_ && model.bodies.size() > 1 && model.bodies.size() <= kMostJointBodies;
  const bool until_still = sweeps_until_still();
  for (int sweep = 0; sweep < (until_still ? kMostConvergeSweeps : sweeps_); ++sweep) {
    if (until_still) sweep_start_ = x;
    if (sweep == 0) {
      contacts_.lag(model, x, base_, h_hat, start_x_);
    } else if (kLagEverySweep) {
      contacts_.lag(model, x, base_, h_hat);
    }
    if (joint_affine_) {
      joint_solves_.clear();
      for (std::size_t b = 0; b < model.bodies.size(); ++b) joint_solves_.push_back(body_solve(model, b, h_hat));
      joint_affine_correction(model, joint_solves_, contacts_, x, joint_scratch_);
    }
    // The sweeps visit the vertices one by one: the colouring does not separate the vertices of a contact, so a loop
    // that moves a colour's vertices at once must take those in contacts one by one (vertex_contacts.hpp).
    for (std::size_t b = 0; b < model.bodies.size(); ++b) sweep_body(model, b, h_hat, x, sweep, 1);
    statistics_.sweeps += static_cast<long long>(model.bodies.size());
    if (until_still && sweep + 1 >= kLeastConvergeSweeps && sweep_was_still(model.bodies, x)) return;
  }
}

void VertexBlockDescent::sweep_colours(const BodySolve& s, const ThreadShares& shares, const LaneGroups& groups,
                                       std::span<Vec3> x, double& volume) {
  const VertexColouring& colouring = s.blocks.colouring;
  for (int c = 0; c < colouring.colours(); ++c) {
    const auto first = static_cast<std::size_t>(colouring.colour_start[static_cast<std::size_t>(c)]);
    const auto last = static_cast<std::size_t>(colouring.colour_start[static_cast<std::size_t>(c) + 1]);
    if (s.contacts == nullptr) {
      // One part per thread, each the colour's vertices in the thread's patches of the surface (ThreadShares), where
      // each gets at least kLeastVerticesPerThread: a hand-over costs a few microseconds.
      const std::span<const int> colour(colouring.vertices.data() + first, last - first);
      ColourParts parts;
      parts.groups = &groups;
      parts.colour = c;
      if (shares.splits(c)) {
        parts.slots = std::span<const int>(shares.slots.data() + first, last - first);
        parts.bounds =
            std::span<const int>(shares.part_start.data() + static_cast<std::size_t>(c * (shares.threads + 1)),
                                 static_cast<std::size_t>(shares.threads + 1));
      }
      ++statistics_.colours_at_once;
      if (move_colour_at_once(s, colour, x, volume, *runner_, parts, colour_scratch_, statistics_)) continue;
      ++statistics_.colours_one_by_one;
    }
    for (std::size_t k = first; k < last; ++k) visit_vertex(s, colouring.vertices[k], x, volume);
  }
}

void VertexBlockDescent::visit_vertex(const BodySolve& s, int i, std::span<Vec3> x, double& volume) {
  const VertexMove move = vertex_move(s, i, x, volume, lags_, statistics_);
  x[static_cast<std::size_t>(i)] += move.step;
  volume += move.volume_change_m3;  // exact: V is affine in x_i
}

double VertexBlockDescent::impact_omega(const Model& model, const State& state, double h) const {
  const Vec3 g = model.gravity_m_per_s2;
  double omega = 0.0;
  for (const Body& body : model.bodies) {
    if (!smooth_floor_ && smooth_colliders_.empty()) break;
    const auto x = Model::of(body, state.x);
    const auto v = Model::of(body, state.v);
    const auto m = Model::of(body, model.mass_kg);
    // The body's mass, and Σ m |v_y| of the vertices in or reaching the floor within h, in chunks on the threads.
    const auto add_chunk = [&](std::size_t first, std::size_t last, FloorApproach& sum) {
      for (std::size_t i = first; i < last; ++i) {
        sum.mass_kg += m[i];
        if (smooth_floor_ && lowest_on_free_path(x[i].y(), v[i].y(), g.y(), h) < smooth_floor_->height_m)
          sum.approach_kg_m_per_s += m[i] * std::abs(v[i].y());
      }
    };
    const FloorApproach sums = chunked_sum(runner_, x.size(), FloorApproach{}, approach_sums_, add_chunk);
    // A contact of ω² = omega2 met with normal momentum `approach` [kg m/s] is an impact where approach × ω exceeds
    // the body's mass times kImpactAcceleration.
    const double least_push = kImpactAcceleration * sums.mass_kg;  // [N]
    const auto take_if_impact = [&](double approach, double omega2) {
      const double contact_omega = std::sqrt(omega2);
      if (approach * contact_omega > least_push) omega = std::max(omega, contact_omega);
    };
    if (smooth_floor_) take_if_impact(sums.approach_kg_m_per_s, smooth_floor_->omega2);
    for (const SmoothCollider& collider : smooth_colliders_) {
      double approach = 0.0;  // Σ m |v·n| of the vertices inside it at the free path's start, middle or end
      for (std::size_t i = 0; i < x.size(); ++i) {
        const Vec3 middle = x[i] + 0.5 * h * v[i] + 0.125 * h * h * g, end = x[i] + h * v[i] + 0.5 * h * h * g;
        if (!is_inside(collider.geometry, x[i]) && !is_inside(collider.geometry, middle) &&
            !is_inside(collider.geometry, end)) {
          continue;
        }
        approach += m[i] * std::abs(v[i].dot(nearest_surface(collider.geometry, x[i]).normal));
      }
      take_if_impact(approach, collider.omega2);
    }
  }
  return std::max(omega, contacts_.impact_omega(model, state.x, state.v, h, kBodyImpactSpeed));
}

bool VertexBlockDescent::smooth_enough_to_double(const Model& model, const State& state, double h) const {
  const IntegratorCarry& carry = state.carry;
  const double tolerance = kGrowthTolerance;
  for (const Body& body : model.bodies) {
    const double allowed = tolerance * body.rest.mean_edge_m;
    const auto v = Model::of(body, state.v), v1 = Model::of(body, carry.previous_v),
               v2 = Model::of(body, carry.older_v);
    for (std::size_t i = 0; i < v.size(); ++i) {
      const double second_difference = (v[i] - 2.0 * v1[i] + v2[i]).norm();  // h² x‴ [m/s]
      if (16.0 / 9.0 * h * second_difference > allowed) return false;
    }
  }
  return true;
}

double VertexBlockDescent::volume_error_ratio(const Model& model, const State& state) const {
  const IntegratorCarry& carry = state.carry;
  double worst = 0.0;
  for (const Body& body : model.bodies) {
    if (body.params.pressure_J == 0.0) continue;
    const std::span<const Triangle> faces = body.topology.faces;
    const double rate = volume_rate(faces, Model::of(body, state.x), Model::of(body, state.v));  // V'_n [m³/s]
    const double rate1 = volume_rate(faces, Model::of(body, carry.previous_x), Model::of(body, carry.previous_v));
    const double rate2 = volume_rate(faces, Model::of(body, carry.older_x), Model::of(body, carry.older_v));
    // BDF2's local error per step (2/9) h³ V‴ ≈ (2/9) h |V'_n − 2 V'_{n−1} + V'_{n−2}|, per unit time [m³/s]
    const double error_rate = 2.0 / 9.0 * std::abs(rate - 2.0 * rate1 + rate2);
    const double volume = enclosed_volume(faces, Model::of(body, state.x));
    worst = std::max(worst, error_rate / (kVolumeErrorRate * volume));
  }
  return worst;
}

int vbd_impact_level(double dt, double omega, double impact_phase) {
  const double pieces = dt * omega / impact_phase;
  return std::min(static_cast<int>(std::ceil(std::log2(std::max(pieces, 1.0)))), kDeepestLevel);
}

VertexBlockDescent::StepLevel VertexBlockDescent::next_level(const Model& model, const State& state, double dt,
                                                             int level, long long done) const {
  const IntegratorCarry& carry = state.carry;
  const double h = std::ldexp(dt, -level);
  if (const double omega = impact_omega(model, state, h); omega > 0.0) {
    return {std::max(vbd_impact_level(dt, omega, impact_phase_), level), true};
  }
  const bool two_steps_of_h = same_step(carry.previous_dt_s, h) && same_step(carry.older_dt_s, h) &&
                              has_history(carry.older_x, carry.older_v, carry.older_dt_s, state.x.size());
  // Holding its own error: halve where the volume's local error is above its tolerance, and double only where twice
  // the step's error (4× at second order) would be within half of it.
  double volume_error = 0.0;
  if (holds_its_error() && two_steps_of_h) {
    volume_error = volume_error_ratio(model, state);
    if (volume_error > 1.0) return {std::min(level + 1, kDeepestLevel), false};
  }
  // Double where the two steps before were both h (a BDF2 step of 2h from two steps back) and 2h ends on its grid.
  const long long double_ticks = 2LL << (kDeepestLevel - level);
  const bool can_double = level > 0 && done % double_ticks == 0 && two_steps_of_h && 4.0 * volume_error <= 0.5;
  if (can_double && smooth_enough_to_double(model, state, h) && impact_omega(model, state, 2.0 * h) == 0.0) {
    return {level - 1, false};
  }
  return {level, false};
}

namespace {

// The level of the step before, where it was one of dt's (dt / 2^level), else 0.
int previous_level(const State& state, double dt) {
  for (int level = 0; level <= kDeepestLevel; ++level) {
    if (same_step(std::ldexp(dt, -level), state.carry.previous_dt_s)) return level;
  }
  return 0;
}

// Whether BDF2's steps of dt damp out every body's breathing (sim::damped_out_by_bdf2) at state.
bool damps_out_every_breathing(const Model& model, const State& state, double dt) {
  for (const Body& body : model.bodies) {
    if (!damped_out_by_bdf2(breathing_mode(body, Model::of(body, state.x)), dt)) return false;
  }
  return true;
}

// state's BDF2 history as a free fall's one step of dt back, x₋₁ = x₀ − dt v₀ + ½ dt² g, v₋₁ = v₀ − dt g [m, m/s]:
// BDF2 from it is exact for a free fall from the first step.
void set_free_fall_history(const Model& model, State& state, double dt) {
  IntegratorCarry& carry = state.carry;
  const std::size_t n = state.x.size();
  const Vec3 g = model.gravity_m_per_s2;
  carry.previous_x.resize(n);
  carry.previous_v.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    carry.previous_x[i] = state.x[i] - dt * state.v[i] + (0.5 * dt * dt) * g;
    carry.previous_v[i] = state.v[i] - dt * g;
  }
  carry.previous_dt_s = dt;
}

}  // namespace

void VertexBlockDescent::set_up(const Model& model, PartRunner& runner) {
  prepare_once(model);
  if (shares_.size() != blocks_.size() || (!shares_.empty() && shares_.front().threads != runner.threads())) {
    shares_.clear();
    for (const VertexBlocks& blocks : blocks_) shares_.push_back(thread_shares(blocks, runner.threads()));
    lane_groups_.clear();
  }
  if (lane_groups_.size() != blocks_.size() || (!lane_groups_.empty() && lane_groups_.front().width != lane_width())) {
    lane_groups_.clear();
    for (std::size_t b = 0; b < blocks_.size(); ++b)
      lane_groups_.push_back(lane_groups(blocks_[b], shares_[b], lane_width()));
  }
}

void VertexBlockDescent::step(Dynamics& dynamics, State& state, double dt) {
  const Model& model = dynamics.model();
  runner_ = &dynamics.runner();
  set_up(model, *runner_);  // nothing where the workspace set it up
  coarse_matrix_age_ = 0;
  const softbody::ProfileScope profile(softbody::ProfilePhase::constraint_sweeps);
  // A run's first step: where the full steps damp out every body's breathing anyway, following its first swings in
  // small steps would only delay the same error (the peers' breathing at icosphere:3: 50 steps for 30 frames and
  // 1.04 % off in volume, at full steps 30 and 1.03 %; docs/notes/2026-12-06-vbd-start.md), so the run starts at the
  // full step from a free fall's history (previous_level then finds level 0); elsewhere at kStartLevel.
  const bool first_step = state.carry.previous_dt_s == 0.0;
  if (first_step && damps_out_every_breathing(model, state, dt)) set_free_fall_history(model, state, dt);
  int level = state.carry.previous_dt_s == 0.0 ? kStartLevel : previous_level(state, dt);
  const long long whole = 1LL << kDeepestLevel;  // dt in ticks of dt / 2^kDeepestLevel
  const double tick = std::ldexp(dt, -kDeepestLevel);
  for (long long done = 0; done < whole;) {
    pose_smooth_colliders(model, state.time_s + static_cast<double>(done) * tick);  // the step's start: its impacts
    const StepLevel next = next_level(model, state, dt, level, done);
    level = next.level;
    impact_step_ = next.impact;
    const long long ticks = 1LL << (kDeepestLevel - level);
    pose_smooth_colliders(model, state.time_s + static_cast<double>(done + ticks) * tick);  // its end: its solve
    take_step(model, state, std::ldexp(dt, -level));
    done += ticks;
  }
}

void VertexBlockDescent::take_step(const Model& model, State& state, double h) {
  IntegratorCarry& carry = state.carry;
  const std::size_t n = state.x.size();
  // BDF2 from the step before (at the same or a larger h: ratio ω ≤ 1), or, doubling, from the step before that.
  double ratio = 0.0;
  bool from_older = false;
  if (has_history(carry.previous_x, carry.previous_v, carry.previous_dt_s, n) &&
      h <= carry.previous_dt_s * (1.0 + 1e-12)) {
    ratio = same_step(h, carry.previous_dt_s) ? 1.0 : h / carry.previous_dt_s;
  } else if (same_step(h, 2.0 * carry.previous_dt_s) && same_step(carry.older_dt_s, carry.previous_dt_s) &&
             has_history(carry.older_x, carry.older_v, carry.older_dt_s, n)) {
    ratio = 1.0;
    from_older = true;
  }
  step_s_ = h;
  const double h_hat = set_targets(model, state, h, ratio, from_older ? carry.older_x : carry.previous_x,
                                   from_older ? carry.older_v : carry.previous_v);
  if (contacts_.active()) {
    sweep_in_contact(model, h_hat, state.x);
  } else {
    for (std::size_t b = 0; b < model.bodies.size(); ++b) sweep_body_to_the_end(model, b, h_hat, state.x);
  }
  chunked_for(runner_, n, [&](std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last; ++i) state.v[i] = (state.x[i] - base_[i]) / h_hat;  // v' = (x' − x̃)/ĥ
  });
  // The history moves one step on: older ← previous ← the step's start (start_x_ keeps the oldest as scratch).
  carry.older_x.swap(carry.previous_x);
  carry.older_v.swap(carry.previous_v);
  carry.older_dt_s = carry.previous_dt_s;
  carry.previous_x.swap(start_x_);
  carry.previous_v.swap(start_v_);
  carry.previous_dt_s = h;
  ++statistics_.steps;
  if (ratio > 0.0) ++statistics_.bdf2_steps;
}

}  // namespace sim
