// The state cache: a State survives the codec and the file bit for bit, a bad or foreign file is refused
// with its name, and frame ranges parse as the farm scripts write them.
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "core/errors.hpp"
#include "frames/frame_selection.hpp"
#include "output/state_cache.hpp"
#include "sim/model/state_codec.hpp"
#include "sim/step/world.hpp"
#include "test_helpers.hpp"

namespace {

using softbody::Vec3;

// A ball on the paper floor after a few hundred steps: its state carries an acceleration (Verlet), xpbd's edge
// tensions, vbd's BDF2 history, the floor's reversed vertices and the guard's budget.
sim::World landed_ball(const std::string& integrator) {
  sim::World world = testing_support::world_from_text(R"({ "solver": { "integrator": ")" + integrator + R"(" },
    "floor": { "contact": "paper" },
    "bodies": [ { "mesh": "icosphere:2", "position": [0, 1.02, 0], "velocity": [0.5, -1, 0] } ] })");
  testing_support::run_steps(world, 300, 1e-4);
  return world;
}

bool same_bits(const sim::State& a, const sim::State& b) {
  return a.x == b.x && a.v == b.v && a.time_s == b.time_s && a.steps == b.steps &&
         a.retry_substeps == b.retry_substeps && a.next_dt_s == b.next_dt_s && a.last_dt_s == b.last_dt_s &&
         a.carry.acceleration == b.carry.acceleration && a.carry.edge_tension_N == b.carry.edge_tension_N &&
         a.carry.previous_x == b.carry.previous_x && a.carry.previous_v == b.carry.previous_v &&
         a.carry.previous_dt_s == b.carry.previous_dt_s && a.carry.older_x == b.carry.older_x &&
         a.carry.older_v == b.carry.older_v && a.carry.older_dt_s == b.carry.older_dt_s &&
         a.carry.previous_error == b.carry.previous_error && a.carry.rejected_last == b.carry.rejected_last &&
         a.coasting == b.coasting && a.guard.budget_J == b.guard.budget_J &&
         a.guard.steps_since_full_check == b.guard.steps_since_full_check;
}

TEST(StateCodec, RoundTripKeepsEveryFieldAndTheNextStepsBits) {
  for (const char* integrator : {"verlet", "symplectic", "rk45", "xpbd", "vbd"}) {
    sim::World world = landed_ball(integrator);
    const sim::State decoded = sim::decode_state(sim::encode_state(world.state), world.model);
    EXPECT_TRUE(same_bits(decoded, world.state)) << integrator;
    sim::World resumed = landed_ball(integrator);
    resumed.state = decoded;
    testing_support::run_steps(world, 200, 1e-4);
    testing_support::run_steps(resumed, 200, 1e-4);
    EXPECT_TRUE(same_bits(resumed.state, world.state)) << integrator << ": the decoded state steps differently";
  }
}

TEST(StateCodec, RefusesAStateOfAnotherModel) {
  const sim::World ball = landed_ball("verlet");
  const sim::World other = testing_support::world_from_text(R"({ "bodies": [ { "mesh": "icosphere:1" } ] })");
  EXPECT_THROW(sim::decode_state(sim::encode_state(ball.state), other.model), softbody::InputError);
  const std::string bytes = sim::encode_state(ball.state);
  EXPECT_THROW(sim::decode_state(bytes.substr(0, bytes.size() - 3), ball.model), softbody::InputError);
}

// The refusal's message, or "" when the read succeeds.
std::string refusal(const std::filesystem::path& dir, int frame, std::uint64_t hash, const sim::Model& model) {
  try {
    output::read_cached_state(dir, frame, hash, model);
  } catch (const softbody::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(StateCache, FilesReadBackAndBadOnesAreRefusedByName) {
  const std::filesystem::path dir = testing_support::scratch_dir("state_cache");
  const sim::World world = landed_ball("verlet");
  constexpr std::uint64_t kHash = 0x1234abcd;
  output::write_cached_state(dir, 7, kHash, world.model, world.state);
  EXPECT_TRUE(same_bits(output::read_cached_state(dir, 7, kHash, world.model), world.state));

  const std::string file = output::cached_state_path(dir, 7).string();
  EXPECT_NE(refusal(dir, 7, kHash + 1, world.model).find(file + ": made from another scene"), std::string::npos);
  EXPECT_NE(refusal(dir, 8, kHash, world.model).find("missing"), std::string::npos);

  std::string bytes;
  {
    std::ifstream in(file, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  auto rewrite = [&](const std::string& content) { std::ofstream(file, std::ios::binary) << content; };
  rewrite(bytes.substr(0, bytes.size() / 2));
  EXPECT_NE(refusal(dir, 7, kHash, world.model).find("truncated"), std::string::npos);
  rewrite(bytes.substr(0, 40));
  EXPECT_NE(refusal(dir, 7, kHash, world.model).find("truncated"), std::string::npos);
  std::string flipped = bytes;
  flipped[bytes.size() - 100] ^= 0x10;  // one bit of one coordinate
  rewrite(flipped);
  EXPECT_NE(refusal(dir, 7, kHash, world.model).find("corrupt state"), std::string::npos);
  flipped = bytes;
  flipped[20] ^= 0x01;  // the header's codec version
  rewrite(flipped);
  EXPECT_NE(refusal(dir, 7, kHash, world.model).find(file), std::string::npos);
  rewrite(std::string(200, 'x'));  // long enough for a header, but none
  EXPECT_NE(refusal(dir, 7, kHash, world.model).find("not a softbody state file"), std::string::npos);
}

TEST(StateCache, ManifestNamesTheSceneAndTheSpacing) {
  const std::filesystem::path dir = testing_support::scratch_dir("state_manifest");
  output::write_manifest(dir, {42, 10, 95, 30, true});
  const output::CacheManifest manifest = output::read_manifest(dir, 42);
  EXPECT_EQ(manifest.every, 10);
  EXPECT_EQ(output::cached_frame_at_or_before(manifest, 37), 30);
  EXPECT_EQ(output::cached_frame_at_or_before(manifest, 95), 95) << "the last frame is always cached";
  EXPECT_EQ(output::cached_frame_at_or_before(manifest, 94), 90);
  EXPECT_THROW(output::read_manifest(dir, 43), softbody::InputError);
  EXPECT_THROW(output::read_manifest(dir / "nothing", 42), softbody::InputError);
}

TEST(FrameSelection, ParsesRangesListsAndOpenEnds) {
  const frames::FrameSelection list = frames::FrameSelection::parse("0-2,5,8-", 9);
  for (int f : {0, 1, 2, 5, 8, 9}) EXPECT_TRUE(list.contains(f)) << f;
  for (int f : {3, 4, 6, 7, 10}) EXPECT_FALSE(list.contains(f)) << f;
  EXPECT_EQ(list.count(), 6);
  EXPECT_EQ(list.first(), 0);
  EXPECT_EQ(list.last(), 9);
  EXPECT_FALSE(list.everything());
  const frames::FrameSelection head = frames::FrameSelection::parse("-3", 9);
  EXPECT_EQ(head.count(), 4);
  EXPECT_TRUE(frames::FrameSelection::parse("0-9", 9).everything());
  for (const char* bad : {"", "-", "3-1", "10", "a-b", "1,,2", "1-2-3", "1 - 2", "99999999999"}) {
    EXPECT_THROW(frames::FrameSelection::parse(bad, 9), softbody::InputError) << bad;
  }
}

}  // namespace
