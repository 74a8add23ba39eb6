// The sweeps' lane groups and their rows, slot by slot.
#include "sim/integrators/lane_groups.hpp"

#include <algorithm>
#include <cassert>
#include <cstddef>

namespace sim {
namespace {

// Appends the group of the colour's vertices at `slots` (count ≤ width of them) and its rows.
void add_group(const VertexBlocks& b, const int* colour, const int* slots, int count, LaneGroups& out) {
  const int width = out.width;
  LaneGroups::Group g;
  g.slot_first = static_cast<int>(out.other_end.size()) / width;
  g.face_slot_first = static_cast<int>(out.face_corners.size()) / (2 * width);
  int first[kMostLanes], face_first[kMostLanes];
  for (int l = 0; l < width; ++l) {
    const auto v = static_cast<std::size_t>(colour[slots[l < count ? l : 0]]);
    first[l] = b.constraint_start[v];
    g.valence[l] = b.constraint_start[v + 1] - first[l];
    face_first[l] = b.face_start[v];
    g.faces[l] = b.face_start[v + 1] - face_first[l];
    g.most = std::max(g.most, g.valence[l]);
    g.most_faces = std::max(g.most_faces, g.faces[l]);
  }
  for (int slot = 0; slot < g.most; ++slot) {
    for (int l = 0; l < width; ++l) {
      const auto e = static_cast<std::size_t>(row_entry(first[l], g.valence[l], slot));
      out.other_end.push_back(b.other_end[e]);
      out.rest_length_m.push_back(b.rest_length_m[e]);
      out.stiffness_N_per_m.push_back(b.stiffness_N_per_m[e]);
      out.damping_N_s_per_m.push_back(b.damping_N_s_per_m[e]);
    }
  }
  for (int slot = 0; slot < g.most_faces; ++slot) {
    for (int corner = 0; corner < 2; ++corner) {
      for (int l = 0; l < width; ++l) {
        const auto f = static_cast<std::size_t>(row_entry(face_first[l], g.faces[l], slot));
        out.face_corners.push_back(b.face_others[f][static_cast<std::size_t>(corner)]);
      }
    }
  }
  out.groups.push_back(g);
}

// Appends the groups of the colour's vertices at slots[0 .. count), `width` at a time.
void add_groups(const VertexBlocks& b, const int* colour, const int* slots, int count, LaneGroups& out) {
  for (int k = 0; k < count; k += out.width) add_group(b, colour, slots + k, std::min(out.width, count - k), out);
}

}  // namespace

LaneGroups lane_groups(const VertexBlocks& blocks, const ThreadShares& shares, int width) {
  assert(width == 4 || width == 8);
  const VertexColouring& colouring = blocks.colouring;
  LaneGroups out;
  out.width = width;
  out.threads = shares.threads;
  for (int c = 0; c < colouring.colours(); ++c) {
    const int first = colouring.colour_start[static_cast<std::size_t>(c)];
    const int size = colouring.colour_start[static_cast<std::size_t>(c) + 1] - first;
    const int* colour = colouring.vertices.data() + first;
    if (!shares.splits(c)) {  // walked in order by one thread
      std::vector<int> in_order(static_cast<std::size_t>(size));
      for (int slot = 0; slot < size; ++slot) in_order[static_cast<std::size_t>(slot)] = slot;
      out.colour_group.push_back(static_cast<int>(out.groups.size()));
      add_groups(blocks, colour, in_order.data(), size, out);
      if (shares.threads > 1) out.part_group.insert(out.part_group.end(), static_cast<std::size_t>(shares.threads), -1);
      continue;
    }
    out.colour_group.push_back(-1);
    const int* starts = &shares.part_start[static_cast<std::size_t>(c * (shares.threads + 1))];
    for (int t = 0; t < shares.threads; ++t) {
      out.part_group.push_back(static_cast<int>(out.groups.size()));
      add_groups(blocks, colour, shares.slots.data() + first + starts[t], starts[t + 1] - starts[t], out);
    }
  }
  return out;
}

}  // namespace sim
