// vbd on threads: how a colour's vertices are split (ThreadShares: one patch of the surface per thread, every
// thread's share of every colour) and what the split must not change (the safeguard on a colour's joint move is in
// vbd_test.cpp, the same bits on one and two threads in determinism_test.cpp), that the chunks a thread takes from
// another's part change no bit, and that a pass's chunks beside a serial task each run once.
#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstring>
#include <optional>
#include <set>
#include <span>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "sim/contact/smooth_contact.hpp"
#include "sim/forces/forces.hpp"
#include "sim/integrators/lane_groups.hpp"
#include "sim/integrators/vertex_blocks.hpp"
#include "sim/integrators/vertex_move_lanes.hpp"
#include "sim/integrators/vertex_moves.hpp"
#include "sim/step/chunk_claims.hpp"
#include "sim/step/chunked_sum.hpp"
#include "sim/step/part_runner.hpp"
#include "support.hpp"

namespace {

// A 2562-vertex ball (icosphere:4).
sim::World ball() {
  return integrator_tests::make_world(R"({ "bodies": [ { "mesh": "icosphere:4", "stiffness": 100.0 } ] })",
                                      sim::IntegratorKind::Vbd);
}

TEST(VbdThreads, EveryColourIsSplitIntoEachThreadsPatch) {
  const sim::World world = ball();
  const sim::VertexBlocks blocks = sim::vertex_blocks(world.model.bodies.at(0));
  const sim::VertexColouring& colouring = blocks.colouring;
  EXPECT_TRUE(sim::thread_shares(blocks, 1).slots.empty());  // one thread walks each colour in order
  for (const int threads : {2, 3}) {
    const std::vector<int> patch = sim::surface_patches(blocks, threads);
    std::set<int> expected;
    for (int t = 0; t < threads; ++t) expected.insert(t);
    EXPECT_EQ(std::set<int>(patch.begin(), patch.end()), expected);  // every vertex in one of the threads' patches
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
          EXPECT_EQ(patch[static_cast<std::size_t>(vertex)], t);
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

// The point of one patch per thread: a thread's vertices have nearly all their neighbours of its own, so little of
// what one thread writes is read by the other. Two patches grown from farthest seeds are the ball's two halves: the
// border between them crosses about a circumference's worth of edges (a split by index, the colour's first and second
// halves, shares about half of all edges; 64 patches dealt out alternately, the split before this one, 9.9 %).
TEST(VbdThreads, PatchesKeepNearlyEveryEdgeWithinOneThread) {
  const sim::World world = ball();
  const sim::Body& body = world.model.bodies.at(0);
  for (const int threads : {2, 3}) {
    const std::vector<int> patch = sim::surface_patches(sim::vertex_blocks(body), threads);
    std::size_t crossing = 0;
    for (const auto& [i, j] : body.constraints.ends) {
      crossing += patch[static_cast<std::size_t>(i)] != patch[static_cast<std::size_t>(j)];
    }
    const double share = static_cast<double>(crossing) / static_cast<double>(body.constraints.size());
    std::printf("%d patches: %zu of %zu constraints cross between them (%.1f %%)\n", threads, crossing,
                body.constraints.size(), 100.0 * share);
    EXPECT_LT(share, 0.05);              // 2.1 % for two patches, 3.7 % for three
    for (int p = 0; p < threads; ++p) {  // every patch a fair share: within 1.5x of the mean
      const auto size = std::count(patch.begin(), patch.end(), p);
      EXPECT_GT(size * threads * 3, body.vertex_count * 2) << "patch " << p;
      EXPECT_LT(size * threads * 2, body.vertex_count * 3) << "patch " << p;
    }
  }
}

}  // namespace

namespace {

using softbody::Vec3;

// Two threads claim one part's chunks from its two ends, as move_colour_at_once's threads do: every chunk is taken
// exactly once, the owner's in rising order from the front, the thief's in falling order from the back.
TEST(VbdThreads, ChunkClaimsTakeEachChunkOnce) {
  constexpr int kChunks = 200000;
  for (int round = 0; round < 5; ++round) {
    sim::ChunkClaims claims;
    claims.reset(kChunks);
    std::vector<int> owner, thief;
    std::thread stealing([&] {
      for (int c; (c = claims.take(false)) >= 0;) thief.push_back(c);
    });
    for (int c; (c = claims.take(true)) >= 0;) owner.push_back(c);
    stealing.join();
    ASSERT_EQ(owner.size() + thief.size(), static_cast<std::size_t>(kChunks));
    for (std::size_t k = 0; k < owner.size(); ++k) ASSERT_EQ(owner[k], static_cast<int>(k));
    for (std::size_t k = 0; k < thief.size(); ++k) ASSERT_EQ(thief[k], kChunks - 1 - static_cast<int>(k));
    EXPECT_EQ(claims.take(true), -1);
    EXPECT_EQ(claims.take(false), -1);
  }
}

// A serial task beside a pass's chunks (the coarse level's factorisation beside its constraints' forces): without a
// runner and on one to three threads, the task runs once and every chunk once, the chunks covering the range in order.
TEST(VbdThreads, ChunksBesideASerialTaskRunEachOnce) {
  constexpr std::size_t kRange = 100000;
  sim::PartRunner one(1), two(2), three(3);
  for (sim::PartRunner* runner : {static_cast<sim::PartRunner*>(nullptr), &one, &two, &three}) {
    for (int round = 0; round < 20; ++round) {
      std::atomic<int> sides{0};
      const auto chunks = static_cast<std::size_t>(sim::chunk_count(kRange));
      std::vector<std::atomic<int>> visits(chunks);
      std::vector<std::size_t> firsts(chunks), lasts(chunks);
      sim::for_each_chunk_beside(
          runner, kRange, [&] { sides.fetch_add(1); },
          [&](std::size_t c, std::size_t first, std::size_t last) {
            visits[c].fetch_add(1);
            firsts[c] = first;
            lasts[c] = last;
          });
      ASSERT_EQ(sides.load(), 1);
      for (std::size_t c = 0; c < chunks; ++c) {
        ASSERT_EQ(visits[c].load(), 1) << "chunk " << c;
        ASSERT_EQ(firsts[c], c == 0 ? 0 : lasts[c - 1]);
      }
      ASSERT_EQ(lasts.back(), kRange);
    }
  }
}

// A colour moved at once is the same bits however its vertices are split and handed out: in order on one thread, and
// split for two and three threads, on one thread (part 0 then takes all the others' chunks, from their backs) and on
// two. The pressurised ball is stretched (a membrane at its rest length has no stiffness across itself, so no step
// would be sure) and every fifth vertex's target is far: once stretched by 2 % with the others' targets at x (most
// steps sure, taken in the lanes), once by 1 % with the others' targets near (line searches at the far ones). Each
// colour is tried, every split one with several chunks per part.
TEST(VbdThreads, AColourMovedAtOnceIsTheSameBitsWhoeverMovesIt) {
  struct Setup {
    double stretch, near_m;
  };
  for (const Setup setup : {Setup{1.02, 0.0}, Setup{1.01, 1e-5}}) {
    sim::Solver solver;
    solver.integrator = sim::IntegratorKind::Vbd;
    sim::World world = integrator_tests::make_world(R"({
      "floor": { "height": 0.0, "contact": "smooth", "restitution": 0.5, "friction": 0.5, "smoothing": 0.01 },
      "bodies": [ { "mesh": "icosphere:4", "position": [0, 1.5, 0], "velocity": [1.5, -0.3, 0.5],
                    "mass": 1.0, "stiffness": 500.0, "damping": 0.5, "pressure": 100.0 } ]
    })",
                                                    solver);
    const sim::Body& body = world.model.bodies[0];
    const sim::VertexBlocks blocks = sim::vertex_blocks(body);
    std::vector<Vec3> target, base;
    const double h_hat = 2.0 / 3.0 / 60.0;
    Vec3 centre = Vec3::Zero();
    for (const Vec3& p : world.state.x) centre += p / static_cast<double>(world.state.x.size());
    for (std::size_t i = 0; i < world.state.x.size(); ++i) {
      world.state.x[i] = centre + setup.stretch * (world.state.x[i] - centre);
      base.push_back(world.state.x[i] - 0.6 * h_hat * world.state.v[i]);
      target.push_back(world.state.x[i] + (i % 5 == 0 ? 0.3 : setup.near_m) * integrator_tests::wiggle(i, 0.3));
    }
    const std::optional<sim::SmoothFloor> floor = sim::resolve_smooth_floor(*world.model.floor);
    sim::BodySolve s{blocks, world.model.mass_kg,   target,       base,    h_hat,
                     0.0,    1.0 / (h_hat * h_hat), std::nullopt, &*floor, {}};
    s.gas = sim::GasLaw{body.params.pressure_J, sim::guarded_volume(0.0, body.rest.volume_m3)};
    const double start_volume = sim::enclosed_volume(body.topology.faces, world.state.x);
    const auto move = [&](int c, int split_threads, sim::PartRunner& runner, std::vector<Vec3>& x, double& volume,
                          sim::MoveCounts& counts) {
      const sim::ThreadShares shares = sim::thread_shares(blocks, split_threads);
      const sim::LaneGroups groups = sim::lane_groups(blocks, shares, sim::lane_width());
      const auto first = static_cast<std::size_t>(blocks.colouring.colour_start[static_cast<std::size_t>(c)]);
      const auto last = static_cast<std::size_t>(blocks.colouring.colour_start[static_cast<std::size_t>(c) + 1]);
      sim::ColourParts parts;
      parts.groups = &groups;
      parts.colour = c;
      if (shares.splits(c)) {
        parts.slots = std::span<const int>(shares.slots.data() + first, last - first);
        parts.bounds =
            std::span<const int>(shares.part_start.data() + static_cast<std::size_t>(c * (split_threads + 1)),
                                 static_cast<std::size_t>(split_threads + 1));
      }
      sim::ColourScratch scratch;
      x = world.state.x;
      volume = start_volume;
      return sim::move_colour_at_once(s, std::span<const int>(blocks.colouring.vertices.data() + first, last - first),
                                      x, volume, runner, parts, scratch, counts);
    };
    sim::PartRunner one(1), two(2);
    int split_colours = 0;
    sim::MoveCounts all;
    for (int c = 0; c < blocks.colouring.colours(); ++c) {
      std::vector<Vec3> expected_x;
      double expected_volume = 0.0;
      sim::MoveCounts expected;
      const bool moved = move(c, 1, one, expected_x, expected_volume, expected);
      all += expected;
      EXPECT_TRUE(moved) << "colour " << c << ": a refused move compares the start with itself";
      for (const int split : {2, 3}) {
        if (!sim::thread_shares(blocks, split).splits(c)) continue;
        split_colours += split == 2;
        for (sim::PartRunner* runner : {&one, &two}) {
          std::vector<Vec3> x;
          double volume = 0.0;
          sim::MoveCounts counts;
          EXPECT_EQ(move(c, split, *runner, x, volume, counts), moved);
          EXPECT_EQ(std::memcmp(x.data(), expected_x.data(), x.size() * sizeof(Vec3)), 0)
              << "colour " << c << " split for " << split << " threads, on " << runner->threads();
          EXPECT_EQ(std::memcmp(&volume, &expected_volume, sizeof(double)), 0) << "colour " << c;
          EXPECT_EQ(counts.vertex_solves, expected.vertex_solves);
          EXPECT_EQ(counts.sure_steps, expected.sure_steps);
          EXPECT_EQ(counts.lane_moves, expected.lane_moves) << "colour " << c << " split for " << split;
          EXPECT_EQ(counts.halvings, expected.halvings);
        }
      }
    }
    std::printf(
        "stretched %.2f: %d colours split for two threads; %lld vertices solved, %lld in lanes, %lld sure, "
        "%lld halvings\n",
        setup.stretch, split_colours, all.vertex_solves, all.lane_moves, all.sure_steps, all.halvings);
    EXPECT_GE(split_colours, 3);
    if (setup.near_m == 0.0) {
      EXPECT_GT(all.lane_moves, all.vertex_solves / 4);  // the lanes serve (their groups follow the chunks)
    } else {
      EXPECT_GT(all.halvings, all.vertex_solves / 20);  // and the line searches
    }
  }
}

}  // namespace
