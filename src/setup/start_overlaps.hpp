// Bodies that start inside one another or inside a collider. The contacts are made for surfaces that meet: the impulse
// contact between bodies pushes a vertex found inside out at most collisions.push_speed, the smooth one with its stiff
// spring, and a collider moves each vertex inside to its nearest surface, so a deep overlap at the start takes seconds
// to undo, starts with a jolt, or holds a body inside a collider. Said as notes before the run.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "sim/model/model.hpp"
#include "sim/model/state.hpp"

namespace setup {

// Vertices tested per pair, fewer for large second bodies: the winding number costs one pass over its faces.
inline constexpr int kOverlapSamples = 256;
inline constexpr double kOverlapFaceVisits = 4e6;  // at most this many vertex-face evaluations per pair
// The whole scene's budget of vertex-face evaluations (about a second), and the pairs named one by one before the rest
// are counted in one note.
inline constexpr double kOverlapBudget = 3e7;
inline constexpr int kOverlapNotes = 8;

// For each pair of bodies whose bounding boxes overlap, a sample of each one's vertices inside the other's box (at
// most kOverlapSamples, evenly strided) tested by the generalised winding number against the other's faces (inside:
// above ½); where any is inside, a note "A and B start inside each other (about P % of the first's vertices inside
// the second, Q % of the second's inside the first) ...", with `names[b]` the scene key of model body b; the first
// kOverlapNotes pairs by name, the rest counted, and the test stopped where it has spent `budget` vertex-face
// evaluations (said in a note).
void note_overlapping_bodies(const sim::Model& model, const sim::State& state, std::span<const std::string> names,
                             std::vector<std::string>& notes, double budget = kOverlapBudget);

// For each body and collider (at its pose at t = 0), where any of the body's vertices is inside the collider, a note
// "NAME starts inside colliders.C (about P % of its vertices) ...".
void note_bodies_in_colliders(const sim::Model& model, const sim::State& state, std::span<const std::string> names,
                              std::vector<std::string>& notes);

}  // namespace setup
