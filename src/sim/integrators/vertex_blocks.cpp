// Building a body's vertex-block layout.
#include "sim/integrators/vertex_blocks.hpp"

#include <algorithm>

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
  blocks.rest_length_m.resize(entries);
  blocks.stiffness_N_per_m.resize(entries);
  blocks.damping_N_s_per_m.resize(entries);
  std::vector<int> next(blocks.constraint_start.begin(), blocks.constraint_start.end() - 1);
  for (std::size_t e = 0; e < constraints.size(); ++e) {
    const auto [i, j] = constraints.ends[e];
    for (const auto& [at, other] : {std::array{i, j}, std::array{j, i}}) {
      const auto entry = static_cast<std::size_t>(next[static_cast<std::size_t>(at)]++);
      blocks.other_end[entry] = other;
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

}  // namespace

VertexBlocks vertex_blocks(const Body& body) {
  VertexBlocks blocks;
  blocks.colouring = colour_vertices(body.constraints.ends, body.topology.faces, body.vertex_count);
  lay_out_constraints(body.constraints, body.vertex_count, blocks);
  lay_out_faces(body.topology.faces, body.vertex_count, blocks);
  find_face_slots(blocks);
  return blocks;
}

}  // namespace sim
