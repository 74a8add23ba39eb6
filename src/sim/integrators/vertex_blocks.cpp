// Building a body's vertex-block layout.
#include "sim/integrators/vertex_blocks.hpp"

#include <algorithm>
#include <span>

namespace sim {
namespace {

// Row starts from per-row counts: start[i + 1] = start[i] + count[i].
std::vector<int> row_starts(const std::vector<int>& count) {
  std::vector<int> start(count.size() + 1, 0);
  for (std::size_t i = 0; i < count.size(); ++i) start[i + 1] = start[i] + count[i];
  return start;
}

void lay_out_constraints(const DistanceConstraints& constraints, int vertex_count, VertexBlocks& blocks) {
  std::vector<int> count(static_cast<std::size_t>(vertex_count), 0);
  for (const auto& [i, j] : constraints.ends) {
    ++count[static_cast<std::size_t>(i)];
    ++count[static_cast<std::size_t>(j)];
  }
  blocks.most_constraints = count.empty() ? 0 : *std::max_element(count.begin(), count.end());
  blocks.constraint_start = row_starts(count);
  const auto entries = static_cast<std::size_t>(blocks.constraint_start.back());
  blocks.other_end.resize(entries);
  blocks.constraint.resize(entries);
  blocks.rest_length_m.resize(entries);
  blocks.stiffness_N_per_m.resize(entries);
  blocks.damping_N_s_per_m.resize(entries);
  std::vector<int> next(blocks.constraint_start.begin(), blocks.constraint_start.end() - 1);
  for (std::size_t e = 0; e < constraints.size(); ++e) {
    const auto [i, j] = constraints.ends[e];
    for (const auto& [at, other] : {std::array{i, j}, std::array{j, i}}) {
      const auto entry = static_cast<std::size_t>(next[static_cast<std::size_t>(at)]++);
      blocks.other_end[entry] = other;
      blocks.constraint[entry] = static_cast<int>(e);
      blocks.rest_length_m[entry] = constraints.rest_length_m[e];
      blocks.stiffness_N_per_m[entry] = constraints.stiffness_N_per_m[e];
      blocks.damping_N_s_per_m[entry] = constraints.damping_N_s_per_m[e];
    }
  }
}

void lay_out_faces(const std::vector<Triangle>& faces, int vertex_count, VertexBlocks& blocks) {
  std::vector<int> count(static_cast<std::size_t>(vertex_count), 0);
  for (const Triangle& f : faces) {
    for (const int corner : f) ++count[static_cast<std::size_t>(corner)];
  }
  blocks.face_start = row_starts(count);
  blocks.face_others.resize(static_cast<std::size_t>(blocks.face_start.back()));
  std::vector<int> next(blocks.face_start.begin(), blocks.face_start.end() - 1);
  for (const auto& [a, b, c] : faces) {
    blocks.face_others[static_cast<std::size_t>(next[static_cast<std::size_t>(a)]++)] = {b, c};
    blocks.face_others[static_cast<std::size_t>(next[static_cast<std::size_t>(b)]++)] = {c, a};
    blocks.face_others[static_cast<std::size_t>(next[static_cast<std::size_t>(c)]++)] = {a, b};
  }
}

// Where each face entry's corners sit in the vertex's constraint row (the first entry with that other end).
void find_face_slots(VertexBlocks& blocks) {
  blocks.face_slots.resize(blocks.face_others.size());
  const auto slot_of = [&](std::size_t i, int other) {
    for (int e = blocks.constraint_start[i]; e < blocks.constraint_start[i + 1]; ++e) {
      if (blocks.other_end[static_cast<std::size_t>(e)] == other) return e - blocks.constraint_start[i];
    }
    return -1;
  };
  for (std::size_t i = 0; i + 1 < blocks.face_start.size(); ++i) {
    for (int f = blocks.face_start[i]; f < blocks.face_start[i + 1]; ++f) {
      const auto [b, c] = blocks.face_others[static_cast<std::size_t>(f)];
      blocks.face_slots[static_cast<std::size_t>(f)] = {slot_of(i, b), slot_of(i, c)};
    }
  }
}

// Breadth-first distances (in edges) from the seeds at once over the constraint rows; `nearest`, where given, gets
// each vertex's seed (the first seed to reach it). Vertices no seed reaches keep −1.
std::vector<int> distances_from(const VertexBlocks& blocks, std::span<const int> seeds, std::vector<int>* nearest) {
  const std::size_t n = blocks.constraint_start.size() - 1;
  std::vector<int> distance(n, -1), queue;
  queue.reserve(n);
  if (nearest != nullptr) nearest->assign(n, -1);
  for (std::size_t k = 0; k < seeds.size(); ++k) {
    const auto seed = static_cast<std::size_t>(seeds[k]);
    if (distance[seed] >= 0) continue;
    distance[seed] = 0;
    if (nearest != nullptr) (*nearest)[seed] = static_cast<int>(k);
    queue.push_back(seeds[k]);
  }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const auto i = static_cast<std::size_t>(queue[head]);
    for (int e = blocks.constraint_start[i]; e < blocks.constraint_start[i + 1]; ++e) {
      const auto j = static_cast<std::size_t>(blocks.other_end[static_cast<std::size_t>(e)]);
      if (distance[j] >= 0) continue;
      distance[j] = distance[i] + 1;
      if (nearest != nullptr) (*nearest)[j] = (*nearest)[i];
      queue.push_back(static_cast<int>(j));
    }
  }
  return distance;
}

}  // namespace

// The seeds: each the vertex farthest from those before, lowest index on ties; an unreached vertex counts as farthest,
// so that every piece of a body gets a seed. Each vertex's patch is its nearest seed.
std::vector<int> surface_patches(const VertexBlocks& blocks, int count) {
  const std::size_t n = blocks.constraint_start.size() - 1;
  std::vector<int> seeds, patch;
  if (n == 0) return patch;
  seeds.push_back(0);
  std::vector<int> distance = distances_from(blocks, seeds, nullptr);
  while (seeds.size() < static_cast<std::size_t>(count) && seeds.size() < n) {
    std::size_t farthest = 0;
    for (std::size_t i = 1; i < n; ++i) {
      const bool unreached = distance[i] < 0, best_unreached = distance[farthest] < 0;
      if (best_unreached) break;
      if (unreached || distance[i] > distance[farthest]) farthest = i;
    }
    if (distance[farthest] == 0) break;  // every vertex is a seed's own
    seeds.push_back(static_cast<int>(farthest));
    const std::vector<int> from_new = distances_from(blocks, std::span<const int>(&seeds.back(), 1), nullptr);
    for (std::size_t i = 0; i < n; ++i) {
      if (from_new[i] >= 0 && (distance[i] < 0 || from_new[i] < distance[i])) distance[i] = from_new[i];
    }
  }
  distances_from(blocks, seeds, &patch);
  return patch;
}

ThreadShares thread_shares(const VertexBlocks& blocks, int threads) {
  const VertexColouring& colouring = blocks.colouring;
  ThreadShares shares;
  shares.threads = threads;
  if (threads <= 1) return shares;
  const std::vector<int> patch = surface_patches(blocks, threads);
  shares.slots.resize(colouring.vertices.size());
  shares.part_start.assign(static_cast<std::size_t>(colouring.colours() * (threads + 1)), 0);
  for (int c = 0; c < colouring.colours(); ++c) {
    const int first = colouring.colour_start[static_cast<std::size_t>(c)];
    const int size = colouring.colour_start[static_cast<std::size_t>(c) + 1] - first;
    const auto thread_of = [&](int slot) {
      const auto vertex = static_cast<std::size_t>(colouring.vertices[static_cast<std::size_t>(first + slot)]);
      return std::max(patch[vertex], 0);  // a piece of the body beyond the seeds goes to thread 0
    };
    int* starts = &shares.part_start[static_cast<std::size_t>(c * (threads + 1))];
    for (int slot = 0; slot < size; ++slot) ++starts[thread_of(slot) + 1];
    for (int t = 0; t < threads; ++t) starts[t + 1] += starts[t];
    std::vector<int> next(starts, starts + threads);
    for (int slot = 0; slot < size; ++slot) {
      shares.slots[static_cast<std::size_t>(first + next[static_cast<std::size_t>(thread_of(slot))]++)] = slot;
    }
  }
  return shares;
}

VertexBlocks vertex_blocks(const Body& body) {
  VertexBlocks blocks;
  blocks.colouring = colour_vertices(body.constraints.ends, body.topology.faces, body.vertex_count);
  lay_out_constraints(body.constraints, body.vertex_count, blocks);
  lay_out_faces(body.topology.faces, body.vertex_count, blocks);
  find_face_slots(blocks);
  return blocks;
}

}  // namespace sim
