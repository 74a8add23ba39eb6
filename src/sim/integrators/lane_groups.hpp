// The sweeps' vertices in the groups that the lanes take them in (move_colour_at_once: a colour's vertices, or one
// thread's part of them, `width` at a time), each group's constraint and face rows laid out slot by slot with one lane
// per vertex, so that the lanes load a slot's other ends, rest lengths, stiffnesses and dampings with one load each
// instead of one per lane.
#pragma once

#include <algorithm>
#include <vector>

#include "sim/integrators/vertex_blocks.hpp"

namespace sim {

inline constexpr int kMostLanes = 8;  // the widest lanes (AVX-512's eight doubles)

// Entry `slot` of a compressed row of `count` entries from `start`, as the lanes read it: past the row's end its last
// entry, 0 for an empty row (valid indices whose values the lanes' masks discard).
inline int row_entry(int start, int count, int slot) { return count == 0 ? 0 : start + std::min(slot, count - 1); }

struct LaneGroups {
  // One group: up to `width` vertices of one colour; the lanes past them repeat the first vertex's rows (their results
  // are discarded).
  struct Group {
    int most = 0, most_faces = 0;                          // the longest constraint and face rows
    int slot_first = 0, face_slot_first = 0;               // its first slots in the arrays below
    int valence[kMostLanes] = {}, faces[kMostLanes] = {};  // each lane's row lengths
  };
  int width = 0;    // the lanes per group (4 or 8, vertex_move_lanes.hpp's lane_width())
  int threads = 1;  // the thread shares' (ThreadShares::threads)
  // Colour c walked in order takes groups[colour_group[c] ..]; where ThreadShares::splits(c), its part for thread t
  // (ColourParts) takes groups[part_group[c threads + t] ..] instead. Each colour has only the groups it is walked in
  // (−1 in the other's entries).
  std::vector<int> colour_group, part_group;
  std::vector<Group> groups;
  // Slot s of a group holds its lanes' entries at [(slot_first + s) width, (slot_first + s + 1) width): each lane's
  // row_entry(.., s) of VertexBlocks' rows.
  std::vector<int> other_end;
  std::vector<double> rest_length_m, stiffness_N_per_m, damping_N_s_per_m;
  // Face slot s: the lanes' first other corners at [2 (face_slot_first + s) width, .. + width), the second after them.
  std::vector<int> face_corners;
};

// The groups of `width` lanes for the colouring of `blocks`: each colour walked in order, or split as shares splits it
// where it goes to the threads (ThreadShares::splits).
LaneGroups lane_groups(const VertexBlocks& blocks, const ThreadShares& shares, int width);

}  // namespace sim
