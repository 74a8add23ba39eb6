// One vertex's Newton step with its line search, and a colour's steps taken at once with their joint safeguard.
#include "sim/integrators/vertex_moves.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sim/integrators/vertex_move_lanes.hpp"

namespace sim {
namespace {

constexpr int kMostHalvings = 10;  // then the vertex stays where it is for this visit

// A split colour's parts are taken in chunks of this many lane groups (ChunkClaims): a thread walks its own part's
// chunks from the front and then takes the other parts' from their back, so that a part whose vertices cost more (line
// searches near a contact) does not keep the other threads waiting at the colour's end (0.25 of 3.1 s of colour passes
// at icosphere:6 on two threads, 0.07 with). Which thread moves a chunk changes no bit.
constexpr int kStealChunkGroups = 16;

}  // namespace

MoveCounts& MoveCounts::operator+=(const MoveCounts& other) {
  vertex_solves += other.vertex_solves;
  sure_steps += other.sure_steps;
  lane_moves += other.lane_moves;
  halvings += other.halvings;
  refused_moves += other.refused_moves;
  return *this;
}

VertexMove vertex_move(const BodySolve& s, int i, std::span<const Vec3> x, double volume, ConstraintLags& lags,
                       MoveCounts& counts) {
  const auto vi = static_cast<std::size_t>(i);
  // 1. ∇_i E and H_i at x_i.
  const VertexTerms terms = vertex_terms(s, i, x, volume, lags);
  // 2. The Newton step and its line search on E's change.
  ++counts.vertex_solves;
  const Vec3 direction = -terms.hessian.solve(terms.gradient);
  const double slope = terms.gradient.dot(direction);  // ∇E·Δ < 0
  if (!(slope < 0.0)) return {};                       // converged to round-off (or not finite): stay
  VertexMove move;
  double alpha = 1.0;
  const bool negligible = direction.squaredNorm() <= s.negligible_step_m * s.negligible_step_m;
  const bool sure = !negligible && sure_descent(s, terms, x[vi], volume, direction, slope);
  counts.sure_steps += sure ? 1 : 0;
  if (sure) move.energy_bound_J = 0.25 * slope;
  if (!negligible && !sure) {
    for (int halving = 0;; ++halving, alpha *= 0.5) {
      if (halving > kMostHalvings) {
        ++counts.refused_moves;
        return {};
      }
      const double change = vertex_energy_change(s, i, x, volume, terms, lags, alpha * direction);
      if (change <= kArmijo * alpha * slope) {
        move.energy_bound_J = change;
        break;
      }
      ++counts.halvings;
    }
  }
  move.step = alpha * direction;
  if (s.gas) move.volume_change_m3 = terms.volume_gradient.dot(move.step);
  return move;
}

namespace {

void size_scratch(const BodySolve& s, std::size_t vertices, int parts, ColourScratch& scratch) {
  if (scratch.lags.size() < static_cast<std::size_t>(parts)) scratch.lags.resize(static_cast<std::size_t>(parts));
  // Each part's lags with kLagPadding unused entries after them: the parts write theirs at every vertex visit, on
  // different threads, and two parts' small arrays could otherwise share a cache line on the heap.
  constexpr std::size_t kLagPadding = 16;
  for (ConstraintLags& lags : scratch.lags) {
    if (lags.offset.size() < static_cast<std::size_t>(s.blocks.most_constraints) + kLagPadding) {
      lags.resize(static_cast<std::size_t>(s.blocks.most_constraints) + kLagPadding);
    }
    if (lags.colliders.size() < s.colliders.size()) lags.colliders.resize(s.colliders.size());
  }
  scratch.counts.assign(static_cast<std::size_t>(parts), MoveCounts{});
  if (scratch.claim_parts < parts) {
    scratch.claims = std::make_unique<ChunkClaims[]>(static_cast<std::size_t>(parts));
    scratch.claim_parts = parts;
  }
  if (scratch.start.size() < vertices) {
    scratch.start.resize(vertices);
    scratch.volume_change.resize(vertices);
    scratch.energy_bound.resize(vertices);
  }
}

// R(S) = E_gas(V + S) − E_gas(V) − E_gas'(V) S ≥ 0 and the round-off of computing it (E_gas' = −P) [J].
struct GasCoupling {
  double excess_J = 0.0;
  double round_off_J = 0.0;
};
GasCoupling gas_coupling(const GasLaw& gas, double volume, double volume_step) {
  const double pressure = gas.pressure(volume);
  return {gas.energy_change(volume, volume_step) + pressure * volume_step,
          8.0 * std::numeric_limits<double>::epsilon() * pressure * std::abs(volume_step)};
}

}  // namespace

bool move_colour_at_once(const BodySolve& s, std::span<const int> colour, std::span<Vec3> x, double& volume,
                         PartRunner& runner, const ColourParts& parts, ColourScratch& scratch, MoveCounts& counts) {
  const std::size_t n = colour.size();
  const int part_count = parts.bounds.empty() ? 1 : static_cast<int>(parts.bounds.size()) - 1;
  size_scratch(s, n, part_count, scratch);
  const double start_volume = volume;
  const bool lanes = lanes_serve(s) && parts.groups != nullptr && parts.groups->width == lane_width();
  const int width = lanes ? parts.groups->width : kMostLanes;
  // A split colour's parts in chunks of kStealChunkGroups lane groups that any thread may take.
  const auto chunk = static_cast<std::size_t>(kStealChunkGroups * width);
  if (!parts.bounds.empty()) {
    for (int q = 0; q < part_count; ++q) {
      const auto size = static_cast<std::size_t>(parts.bounds[static_cast<std::size_t>(q) + 1] -
                                                 parts.bounds[static_cast<std::size_t>(q)]);
      scratch.claims[q].reset(static_cast<int>((size + chunk - 1) / chunk));
    }
  }
  runner.run(part_count, [&](int part) {
    ConstraintLags& lags = scratch.lags[static_cast<std::size_t>(part)];
    MoveCounts part_counts;  // on this thread's stack: the parts' counts share cache lines
    const auto apply = [&](std::size_t slot, const VertexMove& move) {
      const auto vi = static_cast<std::size_t>(colour[slot]);
      scratch.start[slot] = x[vi];
      x[vi] += move.step;
      scratch.volume_change[slot] = move.volume_change_m3;
      scratch.energy_bound[slot] = move.energy_bound_J;
    };
    const auto move_slot = [&](std::size_t slot) {
      apply(slot, vertex_move(s, colour[slot], x, start_volume, lags, part_counts));
    };
    // The part's slots lane_width() at a time (the last group may be shorter): the lanes take the vertices whose
    // step is sure, vertex_move the others.
    const auto move_slots = [&](auto slot_at, std::size_t count, int first_group) {
      for (std::size_t k = 0; k < count; k += static_cast<std::size_t>(width)) {
        const int lane_group = first_group + static_cast<int>(k / static_cast<std::size_t>(width));
        const int group = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(width), count - k));
        std::size_t slots[kMostLanes];
        int vertices[kMostLanes];
        VertexMove moves[kMostLanes];
        for (int l = 0; l < group; ++l) {
          slots[l] = slot_at(k + static_cast<std::size_t>(l));
          vertices[l] = colour[slots[l]];
        }
        const unsigned taken = lanes ? sure_moves_in_lanes(s, *parts.groups, lane_group, vertices, group, x,
                                                           start_volume, moves, part_counts)
                                     : 0;
        for (int l = 0; l < group; ++l) {
          if ((taken & (1u << l)) != 0) {
            apply(slots[l], moves[l]);
          } else {
            move_slot(slots[l]);
          }
        }
      }
    };
    const auto colour_index = static_cast<std::size_t>(parts.colour);
    if (parts.bounds.empty()) {
      move_slots([](std::size_t k) { return k; }, n, lanes ? parts.groups->colour_group[colour_index] : 0);
    } else {
      // Part q's chunk c: its slots from c × chunk on, its lane groups from its first one on.
      const auto move_chunk = [&](int q, int c) {
        const auto begin = static_cast<std::size_t>(parts.bounds[static_cast<std::size_t>(q)]);
        const auto end = static_cast<std::size_t>(parts.bounds[static_cast<std::size_t>(q) + 1]);
        const std::size_t first = static_cast<std::size_t>(c) * chunk;
        const int first_group =
            lanes ? parts.groups->part_group[colour_index * static_cast<std::size_t>(parts.groups->threads) +
                                             static_cast<std::size_t>(q)] +
                        static_cast<int>(first / static_cast<std::size_t>(width))
                  : 0;
        move_slots([&](std::size_t k) { return static_cast<std::size_t>(parts.slots[begin + first + k]); },
                   std::min(chunk, end - begin - first), first_group);
      };
      for (int c; (c = scratch.claims[part].take(true)) >= 0;) move_chunk(part, c);
      for (int other = 1; other < part_count; ++other) {
        const int q = (part + other) % part_count;
        for (int c; (c = scratch.claims[q].take(false)) >= 0;) move_chunk(q, c);
      }
    }
    scratch.counts[static_cast<std::size_t>(part)] = part_counts;
  });
  for (const MoveCounts& part_counts : scratch.counts) counts += part_counts;
  if (!s.gas) return true;
  double volume_step = 0.0, bound = 0.0;  // S [m³], Σ bound_i [J], in the colour's order
  for (std::size_t slot = 0; slot < n; ++slot) {
    volume_step += scratch.volume_change[slot];
    bound += scratch.energy_bound[slot];
  }
  const GasCoupling coupling = gas_coupling(*s.gas, start_volume, volume_step);
  if (bound + coupling.excess_J > coupling.round_off_J) {  // the joint move may raise E: undo it
    for (std::size_t slot = 0; slot < n; ++slot) x[static_cast<std::size_t>(colour[slot])] = scratch.start[slot];
    return false;
  }
  volume = start_volume + volume_step;
  return true;
}

}  // namespace sim
