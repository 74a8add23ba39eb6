// vbd's coarse level: the smoothed aggregates of a body's vertices, and one Galerkin Newton step on them.
#include "sim/integrators/coarse_space.hpp"

#include <algorithm>
#include <climits>
#include <type_traits>
#include <utility>

#include "sim/forces/forces.hpp"
#include "sim/integrators/correction_lanes.hpp"
#include "sim/integrators/vertex_contacts.hpp"
#include "sim/integrators/vertex_move_lanes.hpp"
#include "sim/step/chunked_sum.hpp"

namespace sim {
namespace {

constexpr double kSmoothingWeight = 2.0 / 3.0;  // ω of a smoothing pass (damped Jacobi on the graph's Laplacian)

// Vertex i's neighbours over the constraint graph are blocks.other_end[constraint_start[i] .. constraint_start[i+1]).
std::span<const int> neighbours(const VertexBlocks& blocks, std::size_t i) {
  const auto begin = static_cast<std::size_t>(blocks.constraint_start[i]);
  const auto end = static_cast<std::size_t>(blocks.constraint_start[i + 1]);
  return std::span<const int>(blocks.other_end).subspan(begin, end - begin);
}

// The cell of each vertex: seeds by farthest-point sampling in hops (the first at vertex 0, each next one the lowest
// index farthest from all before), each vertex in the cell of its nearest seed (the earlier seed on a tie).
std::vector<int> aggregate_cells(const VertexBlocks& blocks, int seeds, int& cells) {
  const std::size_t n = blocks.constraint_start.size() - 1;
  std::vector<int> hops(n, INT_MAX), cell(n, -1), queue;
  queue.reserve(n);
  std::size_t seed = 0;
  cells = 0;
  while (cells < seeds && hops[seed] > 0) {
    hops[seed] = 0;
    cell[seed] = cells;
    queue.assign(1, static_cast<int>(seed));
    for (std::size_t head = 0; head < queue.size(); ++head) {  // breadth first, only where strictly nearer
      const auto v = static_cast<std::size_t>(queue[head]);
      for (const int u : neighbours(blocks, v)) {
        const auto vu = static_cast<std::size_t>(u);
        if (hops[v] + 1 < hops[vu]) {
          hops[vu] = hops[v] + 1;
          cell[vu] = cells;
          queue.push_back(u);
        }
      }
    }
    ++cells;
    seed = static_cast<std::size_t>(std::max_element(hops.begin(), hops.end()) - hops.begin());
  }
  return cell;
}

using Weights = std::vector<std::pair<int, double>>;  // (aggregate, weight), aggregates ascending

// Sorts by aggregate and merges repeated aggregates.
void merge_repeats(Weights& w) {
  std::sort(w.begin(), w.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::size_t kept = 0;
  for (std::size_t k = 0; k < w.size(); ++k) {
    if (kept > 0 && w[kept - 1].first == w[k].first) {
      w[kept - 1].second += w[k].second;
    } else {
      w[kept++] = w[k];
    }
  }
  w.resize(kept);
}

// A block's entries in the compact storage: Σ w_a w_b H over symmetric H is symmetric, so each block keeps its upper
// triangle xx, xy, xz, yy, yz, zz (Block3's), and entry (r, c) of the block is kBlockEntry[r][c].
constexpr int kBlockEntries = 6;
constexpr int kBlockEntry[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};

// += scale × block into the kBlockEntries entries at `entries`.
void add_block(double* entries, double scale, const Block3& h) {
  const double upper[kBlockEntries] = {h.xx, h.xy, h.xz, h.yy, h.yz, h.zz};
  for (int k = 0; k < kBlockEntries; ++k) entries[k] += scale * upper[k];
}

// += Σ over pairs a ≥ b of the sparse weights (aggregates ascending) of w_a w_b × block, into the space's slots of
// `blocks`: the lower triangle of wᵀ ⊗ block ⊗ w, which is all that the Cholesky factorisation reads.
void add_outer_blocks(const CoarseSpace& space, std::vector<double>& blocks, std::span<const int> aggregates,
                      std::span<const double> weights, const Block3& h) {
  for (std::size_t p = 0; p < aggregates.size(); ++p) {
    const auto row = static_cast<std::size_t>(aggregates[p]) * static_cast<std::size_t>(space.aggregates);
    for (std::size_t r = 0; r <= p; ++r) {
      const auto slot = static_cast<std::size_t>(space.block_slot[row + static_cast<std::size_t>(aggregates[r])]);
      add_block(&blocks[kBlockEntries * slot], weights[p] * weights[r], h);
    }
  }
}

// Marks the blocks (a, b), a ≥ b, of every pair of the ascending aggregates `reach` as reached.
void mark_pairs(std::span<const int> reach, int aggregates, std::vector<int>& block_slot) {
  for (std::size_t p = 0; p < reach.size(); ++p) {
    for (std::size_t r = 0; r <= p; ++r) block_slot[static_cast<std::size_t>(reach[p] * aggregates + reach[r])] = 0;
  }
}

// space.block_slot and block_pair: the blocks that a vertex's weights or a constraint's two ends' weights together
// reach (a superset of the weight difference's, which leaves out the aggregates where both ends weigh the same).
void number_blocks(const VertexBlocks& blocks, CoarseSpace& space) {
  const std::size_t n = blocks.constraint_start.size() - 1;
  const int aggregates = space.aggregates;
  space.block_slot.assign(static_cast<std::size_t>(aggregates) * static_cast<std::size_t>(aggregates), -1);
  std::vector<int> reach;
  for (std::size_t i = 0; i < n; ++i) {
    const auto own = std::span<const int>(space.aggregate)
                         .subspan(static_cast<std::size_t>(space.weight_start[i]),
                                  static_cast<std::size_t>(space.weight_start[i + 1] - space.weight_start[i]));
    mark_pairs(own, aggregates, space.block_slot);
    for (const int j : neighbours(blocks, i)) {
      const auto vj = static_cast<std::size_t>(j);
      reach.assign(own.begin(), own.end());
      reach.insert(reach.end(), space.aggregate.begin() + space.weight_start[vj],
                   space.aggregate.begin() + space.weight_start[vj + 1]);
      std::sort(reach.begin(), reach.end());
      reach.erase(std::unique(reach.begin(), reach.end()), reach.end());
      mark_pairs(reach, aggregates, space.block_slot);
    }
  }
  space.block_pair.clear();
  for (int a = 0; a < aggregates; ++a) {
    for (int b = 0; b <= a; ++b) {
      int& slot = space.block_slot[static_cast<std::size_t>(a * aggregates + b)];
      if (slot < 0) continue;
      slot = static_cast<int>(space.block_pair.size());
      space.block_pair.push_back({a, b});
    }
  }
}

// Appends to each vertex's weights the three linear fields (X_i − C)/R as aggregates first .. first + 2.
void add_linear_fields(std::span<const Vec3> positions, int first, std::vector<Weights>& weights) {
  Vec3 centre = Vec3::Zero();
  for (const Vec3& p : positions) centre += p;
  centre /= static_cast<double>(positions.size());
  double radius = 0.0;
  for (const Vec3& p : positions) radius = std::max(radius, (p - centre).norm());
  const double scale = radius > 0.0 ? 1.0 / radius : 1.0;
  for (std::size_t i = 0; i < weights.size(); ++i) {
    const Vec3 r = scale * (positions[i] - centre);
    for (int axis = 0; axis < 3; ++axis) weights[i].emplace_back(first + axis, r[axis]);
  }
}

}  // namespace

CoarseSpace smooth_coarse_space(const VertexBlocks& blocks, int aggregates, std::span<const Vec3> positions,
                                int smoothing) {
  const std::size_t n = blocks.constraint_start.size() - 1;
  CoarseSpace space;
  int cells = 0;
  const std::vector<int> cell = aggregate_cells(blocks, std::max(1, aggregates), cells);
  space.aggregates = cells;
  std::vector<Weights> weights(n), smoothed(n);
  for (std::size_t i = 0; i < n; ++i) weights[i] = {{cell[i], 1.0}};
  for (int pass = 0; pass < smoothing; ++pass) {
    for (std::size_t i = 0; i < n; ++i) {
      Weights& w = smoothed[i];
      w.clear();
      for (const auto& [a, value] : weights[i]) w.emplace_back(a, (1.0 - kSmoothingWeight) * value);
      const std::span<const int> around = neighbours(blocks, i);
      const double share = around.empty() ? 0.0 : kSmoothingWeight / static_cast<double>(around.size());
      if (around.empty()) w[0].second += kSmoothingWeight;
      for (const int j : around) {
        for (const auto& [a, value] : weights[static_cast<std::size_t>(j)]) w.emplace_back(a, share * value);
      }
      merge_repeats(w);
    }
    weights.swap(smoothed);
  }
  if (!positions.empty()) {
    add_linear_fields(positions, cells, weights);
    space.aggregates += 3;
  }
  space.weight_start.assign(1, 0);
  for (const Weights& w : weights) {
    for (const auto& [a, value] : w) {
      space.aggregate.push_back(a);
      space.weight.push_back(value);
    }
    space.weight_start.push_back(static_cast<int>(space.aggregate.size()));
  }
  number_blocks(blocks, space);
  return space;
}

namespace {

// Vertex i's weights: its aggregates (ascending) and their weights.
std::pair<std::span<const int>, std::span<const double>> weights_of(const CoarseSpace& space, std::size_t i) {
  const auto begin = static_cast<std::size_t>(space.weight_start[i]);
  const auto count = static_cast<std::size_t>(space.weight_start[i + 1]) - begin;
  return {std::span<const int>(space.aggregate).subspan(begin, count),
          std::span<const double>(space.weight).subspan(begin, count)};
}

// w_i − w_j of a constraint's two ends, merged over the two ascending lists, without its zero entries (where both ends
// have the same weight).
void weight_difference(const CoarseSpace& space, std::size_t i, std::size_t j, CoarseDifference& difference) {
  const auto [ai, wi] = weights_of(space, i);
  const auto [aj, wj] = weights_of(space, j);
  difference.aggregate.clear();
  difference.weight.clear();
  std::size_t p = 0, r = 0;
  while (p < ai.size() || r < aj.size()) {
    int a = 0;
    double value = 0.0;
    if (r == aj.size() || (p < ai.size() && ai[p] < aj[r])) {
      a = ai[p];
      value = wi[p++];
    } else if (p == ai.size() || aj[r] < ai[p]) {
      a = aj[r];
      value = -wj[r++];
    } else {
      a = ai[p];
      value = wi[p++] - wj[r++];
    }
    if (value != 0.0) {
      difference.aggregate.push_back(a);
      difference.weight.push_back(value);
    }
  }
}

// Vertices [first, last) of Pᵀ H P (inertia, floor, colliders, contacts) into part.matrix, and Pᵀ∇V into part.u.
void add_vertex_blocks(const BodySolve& s, const CoarseSpace& space, std::span<const Vec3> x, std::size_t first,
                       std::size_t last, CoarsePart& part) {
  for (std::size_t i = first; i < last; ++i) {
    const double m = s.mass_kg[i];
    Vec3 unused = Vec3::Zero();
    Block3 hessian;
    hessian.add_diagonal(m * s.inverse_h2);
    if (s.floor && x[i].y() < s.floor->height_m) {
      add_floor_terms(*s.floor, m, x[i], s.base[i], s.h_hat, unused, hessian);
    }
    for (const SmoothCollider& collider : s.colliders) {
      add_collider_terms(collider, m, x[i], s.base[i], s.h_hat, unused, hessian);
    }
    if (s.contacts) s.contacts->add_terms(s.first_vertex + static_cast<int>(i), unused, hessian);
    const auto [aggregates, weights] = weights_of(space, i);
    add_outer_blocks(space, part.blocks, aggregates, weights, hessian);
    if (!s.gas) continue;
    const Vec3 six_gradient = six_volume_gradient(s.blocks, i, x);  // 6 ∂V/∂x_i
    for (std::size_t p = 0; p < aggregates.size(); ++p) {
      part.u.segment<3>(3 * aggregates[p]) += (weights[p] / 6.0) * six_gradient;
    }
  }
}

// Constraints [first, last) of Pᵀ H P: H_e = T I + (k + c/ĥ − T) n̂n̂ᵀ on (w_i − w_j) ⊗ (w_i − w_j).
void add_constraint_blocks(const Body& body, const BodySolve& s, const CoarseSpace& space, std::span<const Vec3> x,
                           std::size_t first, std::size_t last, CoarsePart& part) {
  const DistanceConstraints& constraints = body.constraints;
  for (std::size_t e = first; e < last; ++e) {
    const auto [i, j] = constraints.ends[e];
    const auto vi = static_cast<std::size_t>(i), vj = static_cast<std::size_t>(j);
    const Vec3 d = x[vi] - x[vj];
    const double length = d.norm();
    if (length == 0.0) continue;
    weight_difference(space, vi, vj, part.difference);
    if (part.difference.aggregate.empty()) continue;
    const double k = constraints.stiffness_N_per_m[e], c_over_h = constraints.damping_N_s_per_m[e] / s.h_hat;
    const double transverse = k * std::max(0.0, 1.0 - constraints.rest_length_m[e] / length);
    Block3 hessian;
    hessian.add_diagonal(transverse);
    hessian.add_outer(k + c_over_h - transverse, d / length);
    add_outer_blocks(space, part.blocks, part.difference.aggregate, part.difference.weight, hessian);
  }
}

// K's lower triangle += the blocks (a diagonal block's upper entries are left out).
void add_lower_blocks(const CoarseSpace& space, const std::vector<double>& blocks, Eigen::MatrixXd& K) {
  for (std::size_t slot = 0; slot < space.block_pair.size(); ++slot) {
    const auto [a, b] = space.block_pair[slot];
    const double* entries = &blocks[kBlockEntries * slot];
    for (int c = 0; c < 3; ++c) {
      for (int r = a == b ? c : 0; r < 3; ++r) K(3 * a + r, 3 * b + c) += entries[kBlockEntry[r][c]];
    }
  }
}

// The assembly's chunks of vertices and of constraints: each holds a whole matrix, which costs a pass to clear and one
// to add, so there are few (a fixed number: the sum's bits must not depend on the threads).
constexpr std::size_t kMatrixChunks = 2;

// Pᵀ H P's parts at x: its vertices and constraints in kMatrixChunks chunks each into scratch.parts, on s.runner's
// threads (factor_matrix adds them). Returns how many parts it filled.
std::size_t assemble_parts(const Body& body, const BodySolve& s, const CoarseSpace& space, std::span<const Vec3> x,
                           CoarseScratch& scratch) {
  const auto unknowns = static_cast<Eigen::Index>(3 * space.aggregates);
  const std::size_t vertex_chunks = std::min<std::size_t>(kMatrixChunks, x.size());
  const std::size_t constraint_chunks = std::min<std::size_t>(kMatrixChunks, body.constraints.size());
  const std::size_t filled = vertex_chunks + constraint_chunks;
  std::vector<CoarsePart>& parts = scratch.parts;
  if (parts.size() < filled) parts.resize(filled);
  for (std::size_t c = 0; c < filled; ++c) {
    parts[c].blocks.assign(kBlockEntries * space.block_pair.size(), 0.0);
    parts[c].u.setZero(unknowns);
  }
  for_each_chunk(s.runner, x.size(), static_cast<int>(vertex_chunks),
                 [&](std::size_t c, std::size_t first, std::size_t last) {
                   add_vertex_blocks(s, space, x, first, last, parts[c]);
                 });
  for_each_chunk(s.runner, body.constraints.size(), static_cast<int>(constraint_chunks),
                 [&](std::size_t c, std::size_t first, std::size_t last) {
                   add_constraint_blocks(body, s, space, x, first, last, parts[vertex_chunks + c]);
                 });
  return filled;
}

// Pᵀ H P's lower triangle into scratch.matrix, the first `parts` of scratch.parts (assemble_parts) added in chunk order
// with the gas's rank-one term at V = `volume`, and its Cholesky factor into scratch.factor: serial work, which
// coarse_correction runs beside the constraints' forces.
void factor_matrix(const BodySolve& s, const CoarseSpace& space, double volume, std::size_t parts,
                   CoarseScratch& scratch) {
  const auto unknowns = static_cast<Eigen::Index>(3 * space.aggregates);
  Eigen::MatrixXd& K = scratch.matrix;
  K.setZero(unknowns, unknowns);
  Eigen::VectorXd& u = scratch.volume_gradient;
  u.setZero(unknowns);
  for (std::size_t c = 0; c < parts; ++c) {
    add_lower_blocks(space, scratch.parts[c].blocks, K);
    u += scratch.parts[c].u;
  }
  // The gas's rank-one part of the curvature, nRT/V² (Pᵀ∇V)(Pᵀ∇V)ᵀ.
  if (s.gas) K.selfadjointView<Eigen::Lower>().rankUpdate(u, s.gas->stiffness(volume));
  scratch.factor.compute(K);
  scratch.factored = scratch.factor.info() == Eigen::Success;
}

// take_edge_forces' default: its chunks alone, each on its fixed thread.
struct NothingBeside {
  void operator()() const {}
};

// Each constraint's spring and damper term of ∇E at its first end, (k (l − L0) + (c/ĥ) ĥ l̇) d/l with d = x_i − x_j
// [N] (its second end takes the negative), into scratch.edge_force, and its lags for the line search
// (take_edge_lag) into scratch.search, in chunks on s.runner's threads; beside() on one of them where given.
template <class Beside = NothingBeside>
void take_edge_forces(const Body& body, const BodySolve& s, std::span<const Vec3> x, CoarseScratch& scratch,
                      Beside&& beside = {}) {
  const DistanceConstraints& constraints = body.constraints;
  MotionScratch& search = scratch.search;
  scratch.edge_force.resize(constraints.size());
  search.size_edge_lags(constraints.size());
  const double inverse_h = 1.0 / s.h_hat;
  const auto forces = [&](std::size_t first, std::size_t last) {
    for (std::size_t e = edge_forces_in_lanes(constraints, s, x, first, last, search, scratch.edge_force); e < last;
         ++e) {
      take_edge_lag(constraints, s, x, e, search);
      const double length = search.edge_length_m[e];
      if (length == 0.0) {
        scratch.edge_force[e] = Vec3::Zero();
        continue;
      }
      const auto [i, j] = constraints.ends[e];
      const auto vi = static_cast<std::size_t>(i), vj = static_cast<std::size_t>(j);
      const Vec3 axis = (x[vi] - x[vj]) / length;
      const double rate = ((x[vi] - s.base[vi]) - (x[vj] - s.base[vj])).dot(axis);  // ĥ × the approach speed [m]
      scratch.edge_force[e] = (constraints.stiffness_N_per_m[e] * (length - constraints.rest_length_m[e]) +
                               constraints.damping_N_s_per_m[e] * inverse_h * rate) *
                              axis;
    }
  };
  if constexpr (std::is_same_v<std::decay_t<Beside>, NothingBeside>) {
    chunked_for(s.runner, constraints.size(), forces);
  } else {
    for_each_chunk_beside(s.runner, constraints.size(), beside,
                          [&](std::size_t, std::size_t first, std::size_t last) { forces(first, last); });
  }
}

// ∇E per vertex at x (its own terms, and its constraints' from take_edge_forces, with V(x) = `volume`) projected as
// −Pᵀ ∇E into scratch.projection_sums, one partial sum per chunk on s.runner's threads, and the floor's and colliders'
// lags at x for the line search (MotionScratch).
void project_gradient(const Body& body, const BodySolve& s, const CoarseSpace& space, std::span<const Vec3> x,
                      double volume, CoarseScratch& scratch) {
  const VertexBlocks& blocks = s.blocks;
  const std::size_t n = x.size();
  const auto unknowns = static_cast<Eigen::Index>(3 * space.aggregates);
  MotionScratch& search = scratch.search;
  const double gas_per_six = s.gas ? s.gas->pressure(volume) / 6.0 : 0.0;  // P/6: the force per 6 ∂V/∂x_i [Pa]
  search.size_contact_lags(s, n);
  scratch.projection_sums.resize(static_cast<std::size_t>(chunk_count(n)));
  for_each_chunk(s.runner, n, [&](std::size_t c, std::size_t first, std::size_t last) {
    Eigen::VectorXd& part = scratch.projection_sums[c];
    part.setZero(unknowns);
    Vec3 six_gradients[kLanes];  // 6 ∂V/∂x_i of the group of four that i is in, where the lanes computed them
    bool in_lanes = false;
    for (std::size_t i = first; i < last; ++i) {
      const std::size_t lane = (i - first) % kLanes;
      if (s.gas && lane == 0) {
        in_lanes = i + kLanes <= last && six_volume_gradients_in_lanes(blocks, i, x, six_gradients);
      }
      const double m = s.mass_kg[i];
      Vec3 gradient = (m * s.inverse_h2) * (x[i] - s.target[i]);
      Block3 unused;
      if (s.floor) search.floor_lags[i] = add_floor_terms(*s.floor, m, x[i], s.base[i], s.h_hat, gradient, unused);
      for (std::size_t k = 0; k < s.colliders.size(); ++k) {
        search.collider_lags[k * n + i] =
            add_collider_terms(s.colliders[k], m, x[i], s.base[i], s.h_hat, gradient, unused);
      }
      if (s.contacts) s.contacts->add_terms(s.first_vertex + static_cast<int>(i), gradient, unused);
      for (int entry = blocks.constraint_start[i]; entry < blocks.constraint_start[i + 1]; ++entry) {
        const auto e = static_cast<std::size_t>(blocks.constraint[static_cast<std::size_t>(entry)]);
        const Vec3& force = scratch.edge_force[e];
        gradient += static_cast<std::size_t>(body.constraints.ends[e][0]) == i ? force : Vec3(-force);
      }
      if (s.gas) gradient -= gas_per_six * (in_lanes ? six_gradients[lane] : six_volume_gradient(blocks, i, x));
      const auto [aggregates, weights] = weights_of(space, i);
      for (std::size_t p = 0; p < aggregates.size(); ++p) part.segment<3>(3 * aggregates[p]) -= weights[p] * gradient;
    }
  });
}

// −Pᵀ ∇E into q: the chunks' partial sums (project_gradient) in chunk order.
void sum_projection(const CoarseScratch& scratch, Eigen::VectorXd& q) {
  q = scratch.projection_sums[0];
  for (std::size_t c = 1; c < scratch.projection_sums.size(); ++c) q += scratch.projection_sums[c];
}

}  // namespace

bool coarse_correction(const Body& body, const BodySolve& s, const CoarseSpace& space, std::span<Vec3> x,
                       bool refresh_matrix, CoarseScratch& scratch, std::optional<double> known_volume) {
  const std::size_t n = x.size();
  const bool matrix = refresh_matrix || scratch.factor.rows() != 3 * space.aggregates;
  double volume = 0.0;
  if (s.gas) {
    volume = known_volume ? *known_volume
                          : enclosed_volume_in_lanes(body.topology.faces, x, s.runner, scratch.search.volume_sums);
  }
  scratch.search.volume_after = volume;  // where it does not move
  if (matrix) {
    // The parts on the threads; their sum and its factorisation (serial: about 2 ms at 131 aggregates) on one of them,
    // while the others take the constraints' forces, which do not depend on it.
    const std::size_t parts = assemble_parts(body, s, space, x, scratch);
    take_edge_forces(body, s, x, scratch, [&] { factor_matrix(s, space, volume, parts, scratch); });
  } else {
    take_edge_forces(body, s, x, scratch);
  }
  if (!scratch.factored) return false;
  project_gradient(body, s, space, x, volume, scratch);
  Eigen::VectorXd& q = scratch.solution;  // −Pᵀ ∇E, then q
  sum_projection(scratch, q);
  scratch.rhs = q;
  scratch.factor.solveInPlace(q);
  const double descent = -scratch.rhs.dot(q);  // ∇E·P q = −(−Pᵀ∇E)·q < 0
  if (!(descent < 0.0)) return false;
  std::vector<Vec3>& motion = scratch.search.motion;
  motion.resize(n);
  chunked_for(s.runner, n, [&](std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last; ++i) {
      const auto [aggregates, weights] = weights_of(space, i);
      Vec3 sum = Vec3::Zero();
      for (std::size_t p = 0; p < aggregates.size(); ++p) sum += weights[p] * q.segment<3>(3 * aggregates[p]);
      motion[i] = sum;
    }
  });
  return search_along_motion(body, s, x, volume, descent, scratch.search);
}

}  // namespace sim
