// A body laid out for vertex block descent: its vertices in colour order, and per vertex the constraints and faces
// that touch it, in compressed rows, so that one vertex's local solve reads one contiguous run of each.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "sim/model/body.hpp"
#include "sim/solvers/vertex_colouring.hpp"

namespace sim {

struct VertexBlocks {
  VertexColouring colouring;  // the visiting order: no two vertices of a colour share a constraint or a face
  // Vertex i's constraints (edges and bending links) are entries [constraint_start[i], constraint_start[i + 1]):
  std::vector<int> constraint_start;      // vertex count + 1
  std::vector<int> other_end;             // the constraint's other vertex (local index)
  std::vector<int> constraint;            // the constraint's index in the body's DistanceConstraints
  std::vector<double> rest_length_m;      // L0 [m]
  std::vector<double> stiffness_N_per_m;  // k [N/m]
  std::vector<double> damping_N_s_per_m;  // c [N·s/m]
  // Vertex i's faces are entries [face_start[i], face_start[i + 1]) of face_others: the face's two other corners in
  // its counter-clockwise order after i, so that (x_b − x_i) × (x_c − x_i) is twice its outward area vector.
  std::vector<int> face_start;  // vertex count + 1
  std::vector<std::array<int, 2>> face_others;
  // The same two corners as entries of vertex i's constraint row (e − constraint_start[i]), so that the gas's gradient
  // reuses the edge vectors the springs computed; −1 where a corner is not among the constraints.
  std::vector<std::array<int, 2>> face_slots;
  int most_constraints = 0;  // the largest number of constraints at one vertex
};

// Each vertex's patch of the surface: `count` patches grown breadth-first over the constraints from seeds spread far
// apart (farthest-point sampling), so that a patch is one region whose border is short.
std::vector<int> surface_patches(const VertexBlocks& blocks, int count);

// A colour's vertices go to several threads only where each gets at least this many (a hand-over costs a few
// microseconds).
inline constexpr int kLeastVerticesPerThread = 256;

// The vertices of every colour split among `threads` threads by surface patch (one patch per thread, patch t to thread
// t), so that each thread keeps to one region of the surface in every colour and sweep and only the regions' border
// reads what the other thread wrote. Work that gathers in one region (an impact's line searches) is shared out when a
// colour is moved: a thread done with its own part takes chunks of the others' (move_colour_at_once). For one thread
// it is empty: the colour is walked in order.
struct ThreadShares {
  int threads = 1;
  // Per colour c, its slots (positions in the colour, 0-based) grouped by thread, ascending within a thread (so that
  // a thread walks memory forward): entries [colour_start[c], colour_start[c + 1]) of slots.
  std::vector<int> slots;
  // Thread t of colour c takes slots[colour_start[c] + part_start[c (threads + 1) + t] ...
  // colour_start[c] + part_start[c (threads + 1) + t + 1]).
  std::vector<int> part_start;
  // Whether colour c goes to the threads as split above (each thread at least kLeastVerticesPerThread of its vertices);
  // otherwise one thread walks it in order.
  bool splits(int c) const {
    if (threads <= 1) return false;
    const int size = part_start[static_cast<std::size_t>(c * (threads + 1) + threads)];  // the colour's vertices
    return size >= kLeastVerticesPerThread * threads;
  }
};
ThreadShares thread_shares(const VertexBlocks& blocks, int threads);

// The layout of `body` (its constraint set and faces, built by add_body()).
VertexBlocks vertex_blocks(const Body& body);

}  // namespace sim
