// Loops over an index range split into chunks whose number depends only on the range's length (or is the caller's fixed
// count): the chunks run on a PartRunner's threads (or in turn without one) and their partial sums are added in chunk
// order, so that a sum has the same bits on any number of threads.
#pragma once

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "sim/step/part_runner.hpp"

namespace sim {

inline constexpr std::size_t kLeastChunk = 512;  // indices per chunk at least (a hand-over costs a few microseconds)
inline constexpr int kMostChunks = 8;            // chunks at most, so that 2 to 8 threads share them evenly

inline int chunk_count(std::size_t n) {
  return static_cast<int>(std::clamp<std::size_t>(n / kLeastChunk, 1, kMostChunks));
}

// Calls visit(c, first, last) for each of `chunks` chunks c, [first, last) of [0, n), on runner's threads where runner
// is set.
template <class Visit>
void for_each_chunk(PartRunner* runner, std::size_t n, int chunk_total, Visit&& visit) {
  const auto chunks = static_cast<std::size_t>(chunk_total);
  auto body = [&](int part) {
    const auto c = static_cast<std::size_t>(part);
    visit(c, n * c / chunks, n * (c + 1) / chunks);
  };
  if (runner != nullptr) {
    runner->run(static_cast<int>(chunks), body);
  } else {
    for (std::size_t c = 0; c < chunks; ++c) body(static_cast<int>(c));
  }
}

// The same over chunk_count(n) chunks.
template <class Visit>
void for_each_chunk(PartRunner* runner, std::size_t n, Visit&& visit) {
  for_each_chunk(runner, n, chunk_count(n), std::forward<Visit>(visit));
}

// side() on one thread beside visit(c, first, last) for each of chunk_count(n) chunks c, which any thread takes (the
// one that ran side() too, once it is done): a serial task that would otherwise keep the other threads waiting runs
// while they do the chunks. Which thread takes a chunk changes no result. Without a runner: side(), then the chunks.
template <class Side, class Visit>
void for_each_chunk_beside(PartRunner* runner, std::size_t n, Side&& side, Visit&& visit) {
  const auto chunks = static_cast<std::size_t>(chunk_count(n));
  auto body = [&](int claim) {
    if (claim == 0) {
      side();
      return;
    }
    const auto c = static_cast<std::size_t>(claim - 1);
    visit(c, n * c / chunks, n * (c + 1) / chunks);
  };
  const int claims = static_cast<int>(chunks) + 1;
  if (runner != nullptr) {
    runner->run(claims, body, PartRunner::Order::AnyThread);
  } else {
    for (int claim = 0; claim < claims; ++claim) body(claim);
  }
}

// Calls visit(first, last) for every chunk [first, last) of [0, n), on runner's threads where runner is set.
template <class Visit>
void chunked_for(PartRunner* runner, std::size_t n, Visit&& visit) {
  for_each_chunk(runner, n, [&](std::size_t, std::size_t first, std::size_t last) { visit(first, last); });
}

// Σ over the chunks of visit(first, last, partial), each partial starting at `zero`, added in chunk order; `partials`
// is scratch (no allocation once its capacity settles). Each chunk sums into a partial on its own thread's stack and
// stores it once: the partials lie side by side, and a visit that adds to its partial at every index would make the
// threads fight over their shared cache lines.
template <class Partial, class Visit>
Partial chunked_sum(PartRunner* runner, std::size_t n, const Partial& zero, std::vector<Partial>& partials,
                    Visit&& visit) {
  partials.assign(static_cast<std::size_t>(chunk_count(n)), zero);
  for_each_chunk(runner, n, [&](std::size_t c, std::size_t first, std::size_t last) {
    Partial partial = zero;
    visit(first, last, partial);
    partials[c] = partial;
  });
  Partial total = partials[0];
  for (std::size_t c = 1; c < partials.size(); ++c) total += partials[c];
  return total;
}

}  // namespace sim
