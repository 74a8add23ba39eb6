// vbd on threads: how a colour's vertices are split (ThreadShares: patches of the surface, every thread's share of
// every colour) and what the split must not change (the safeguard on a colour's joint move is in vbd_test.cpp, the same
// bits on one and two threads in determinism_test.cpp).
#include <algorithm>
#include <cstdio>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "sim/integrators/vertex_blocks.hpp"
#include "support.hpp"

namespace {

// A 2562-vertex ball (icosphere:4).
sim::World ball() {
  return integrator_tests::make_world(R"({ "bodies": [ { "mesh": "icosphere:4", "stiffness": 100.0 } ] })",
                                      sim::IntegratorKind::Vbd);
}

TEST(VbdThreads, EveryColourIsSplitIntoEachThreadsPatches) {
  const sim::World world = ball();
  const sim::VertexBlocks blocks = sim::vertex_blocks(world.model.bodies.at(0));
  const sim::VertexColouring& colouring = blocks.colouring;
  const std::vector<int> patch = sim::surface_patches(blocks);
  std::set<int> patches(patch.begin(), patch.end());
  EXPECT_EQ(patches.size(), static_cast<std::size_t>(sim::kSurfacePatches));
  EXPECT_EQ(*patches.begin(), 0);
  EXPECT_TRUE(sim::thread_shares(blocks, 1).slots.empty());  // one thread walks each colour in order
  for (const int threads : {2, 3}) {
    const sim::ThreadShares shares = sim::thread_shares(blocks, threads);
    for (int c = 0; c < colouring.colours(); ++c) {
      const int first = colouring.colour_start[static_cast<std::size_t>(c)];
      const int size = colouring.colour_start[static_cast<std::size_t>(c) + 1] - first;
      const int* starts = &shares.part_start[static_cast<std::size_t>(c * (threads + 1))];
      ASSERT_EQ(starts[0], 0);
      ASSERT_EQ(starts[threads], size);
      std::vector<int> seen;
      for (int t = 0; t < threads; ++t) {
        for (int k = starts[t]; k < starts[t + 1]; ++k) {
          const int slot = shares.slots[static_cast<std::size_t>(first + k)];
          if (k > starts[t]) {  // a thread walks its slots forward
            EXPECT_GT(slot, shares.slots[static_cast<std::size_t>(first + k - 1)]);
          }
          const int vertex = colouring.vertices[static_cast<std::size_t>(first + slot)];
          EXPECT_EQ(patch[static_cast<std::size_t>(vertex)] % threads, t);
          seen.push_back(slot);
        }
      }
      std::sort(seen.begin(), seen.end());
      for (int slot = 0; slot < size; ++slot) ASSERT_EQ(seen[static_cast<std::size_t>(slot)], slot);  // each once
      EXPECT_EQ(shares.splits(c), size >= sim::kLeastVerticesPerThread * threads) << "colour " << c;
    }
  }
  EXPECT_FALSE(sim::thread_shares(blocks, 1).splits(0));
}

// The point of patches: a thread's vertices have most neighbours of its own, so little of what one thread writes is
// read by the other (a split by index, the colour's first and second halves, shares about half of all edges).
TEST(VbdThreads, PatchesKeepMostEdgesWithinOneThread) {
  const sim::World world = ball();
  const sim::Body& body = world.model.bodies.at(0);
  const std::vector<int> patch = sim::surface_patches(sim::vertex_blocks(body));
  std::size_t crossing = 0;
  for (const auto& [i, j] : body.constraints.ends) {
    crossing += patch[static_cast<std::size_t>(i)] % 2 != patch[static_cast<std::size_t>(j)] % 2;
  }
  const double share = static_cast<double>(crossing) / static_cast<double>(body.constraints.size());
  std::printf("%zu of %zu constraints cross between the two threads' patches (%.1f %%)\n", crossing,
              body.constraints.size(), 100.0 * share);
  EXPECT_LT(share, 0.25);
  for (int p = 0; p < sim::kSurfacePatches; ++p) {  // every patch a fair share: within 4x of the mean
    const auto size = std::count(patch.begin(), patch.end(), p);
    EXPECT_GT(size * sim::kSurfacePatches * 4, body.vertex_count) << "patch " << p;
    EXPECT_LT(size * sim::kSurfacePatches, body.vertex_count * 4) << "patch " << p;
  }
}

}  // namespace
