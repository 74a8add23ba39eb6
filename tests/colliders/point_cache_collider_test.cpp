// Mesh colliders moved by a point cache ("cache": a PC2 file): a keyframed mesh collider written by `softbody export
// --format pc2` and read back as a cache moves a body as the keys did; a body on a cached platform sliding sideways
// ends moving with it (friction, every integrator); a ball thrown at 5 m/s onto a cached 1 cm board that moves slowly
// never ends a step behind it nor, with the impulse contacts, inside it; a refitted pose answers as a mesh built
// from its vertices; and a cache that does not fit its mesh is refused with its file named.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/errors.hpp"
#include "frames/frame_clock.hpp"
#include "output/point_cache.hpp"
#include "setup/build_world.hpp"
#include "sim/contact/collider_mesh.hpp"
#include "sim/step/diagnostics.hpp"
#include "sim/step/step_plan.hpp"
#include "sim/step/world.hpp"
#include "test_helpers.hpp"

namespace {

using softbody::Vec3;
namespace fs = std::filesystem;

void write_file(const fs::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out << bytes;
}

// A box of half sizes h centred on the origin: 8 corners (corner i at ±h by its bits x 1, y 2, z 4), 6 quads wound
// counter-clockwise seen from outside.
std::vector<Vec3> box_corners(const Vec3& h) {
  std::vector<Vec3> corners;
  for (int i = 0; i < 8; ++i)
    corners.emplace_back((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(), (i & 4) ? h.z() : -h.z());
  return corners;
}

std::string box_obj(const Vec3& h) {
  std::string text = "# a box\n";
  char line[96];
  for (const Vec3& p : box_corners(h)) {
    std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", p.x(), p.y(), p.z());
    text += line;
  }
  // Face of axis k, side s: corners (−u −v), (+u −v), (+u +v), (−u +v) with u, v the next axes (u × v = e_k), the
  // order reversed on the negative side.
  for (int k = 0; k < 3; ++k) {
    for (int side : {0, 1}) {
      const int bk = 1 << k, bu = 1 << ((k + 1) % 3), bv = 1 << ((k + 2) % 3);
      const int base = side ? bk : 0;
      int quad[4] = {base, base + bu, base + bu + bv, base + bv};
      if (!side) std::swap(quad[1], quad[3]);
      std::snprintf(line, sizeof line, "f %d %d %d %d\n", quad[0] + 1, quad[1] + 1, quad[2] + 1, quad[3] + 1);
      text += line;
    }
  }
  return text;
}

// A PC2 cache of the box's corners translated by velocity × time, one sample per frame at `fps` from frame 0.
std::string translated_box_pc2(const Vec3& h, const Vec3& velocity, int fps, int frames) {
  output::PointSamples samples;
  samples.points = 8;
  for (int f = 0; f < frames; ++f) {
    const double t = static_cast<double>(f) / fps;
    for (const Vec3& p : box_corners(h)) {
      for (int axis = 0; axis < 3; ++axis) samples.xyz.push_back(static_cast<float>(p[axis] + t * velocity[axis]));
    }
    samples.times_s.push_back(static_cast<float>(t));
  }
  return output::encode_pc2(samples, 0.0f, 1.0f);
}

std::string step_keys(const sim::IntegratorInfo& integrator) {
  return std::string(R"("integrator": ")") + std::string(integrator.name) + R"(", )" +
         (integrator.frame_substeps ? R"("substeps": "auto")" : R"("dt": "auto")");
}

// A firm cube dropped 1 cm onto a 2 m platform (top at y = 0.05) whose motion is `motion` (keys or a cache).
std::string cube_on_platform(const std::string& platform, const std::string& contact, const std::string& step) {
  return R"({ "duration": 1.5, "fps": 30, "solver": { )" + step + R"( },
      "colliders": [ { )" +
         platform + R"(, "contact": ")" + contact + R"(", "restitution": 0, "friction": 0.8 } ],
      "bodies": [ { "mesh": "cube:2", "scale": 0.2, "position": [0, 0.16, 0], "mass": 1, "stiffness": 2000,
                    "damping": 2, "pressure": 0 } ] })";
}

constexpr double kPlatformSpeed_m_per_s = 0.5;
const Vec3 kPlatformHalf(1.0, 0.05, 1.0);

// Body 0's centre of mass at every frame of a scene, and its velocity at the end.
struct CentrePath {
  std::vector<Vec3> centres;
  Vec3 end_velocity = Vec3::Zero();
};
CentrePath centre_path(const std::string& text) {
  CentrePath path;
  const sim::World end = testing_support::run_scene_frames(
      text, [&](double, const sim::World& w) { path.centres.push_back(sim::diagnose(w.model, w.state, 0).com_m); });
  path.end_velocity = sim::diagnose(end.model, end.state, 0).com_velocity_m_per_s;
  return path;
}

// The largest distance between two paths' centres at the same frame [m].
double farthest_apart(const CentrePath& a, const CentrePath& b) {
  double apart = 0.0;
  for (std::size_t f = 0; f < a.centres.size() && f < b.centres.size(); ++f)
    apart = std::max(apart, (a.centres[f] - b.centres[f]).norm());
  return apart;
}

// The cube on a keyframed mesh platform (dir/platform.obj) sliding 1.5 m along x in 3 s, also written as
// dir/keyed.json: its text.
std::string keyed_platform_scene(const fs::path& dir) {
  write_file(dir / "platform.obj", box_obj(kPlatformHalf));
  const std::string keyed =
      cube_on_platform(R"("shape": "mesh", "mesh": ")" + (dir / "platform.obj").string() +
                           R"(", "keys": [ {"time": 0, "position": [0, 0, 0]}, {"time": 3, "position": [1.5, 0, 0]} ])",
                       "friction", step_keys(sim::kIntegrators[0]));
  write_file(dir / "keyed.json", keyed);
  return keyed;
}

// Keyframed linear keys that fall on frames (0 and 3 s at 30 fps), read back from the export's cache: linear
// interpolation of the frames' samples gives the keys' positions again (to float precision), so the body moves as
// it did on the keyframed platform.
TEST(PointCacheCollider, ExportedCacheOfAKeyframedMeshMovesABodyAsTheKeysDid) {
  const fs::path dir = testing_support::scratch_dir("point_cache_round_trip");
  const std::string keyed = keyed_platform_scene(dir);
  const testing_support::CommandResult exported = testing_support::run_softbody(
      "export " + (dir / "keyed.json").string() + " --format pc2 -o " + (dir / "out").string());
  ASSERT_EQ(exported.exit_status, 0) << exported.output;
  const std::string cached = cube_on_platform(R"("shape": "mesh", "mesh": ")" + (dir / "out/collider_0.obj").string() +
                                                  R"(", "cache": ")" + (dir / "out/collider_0.pc2").string() + "\"",
                                              "friction", step_keys(sim::kIntegrators[0]));
  const CentrePath keyed_path = centre_path(keyed), cached_path = centre_path(cached);
  ASSERT_EQ(keyed_path.centres.size(), cached_path.centres.size());
  const double apart = farthest_apart(keyed_path, cached_path);
  std::printf("the body's centre on the cached platform and on the keyframed one: at most %.3g m apart\n", apart);
  // The cache holds float positions (about 1e-7 m here); the contact passes on such differences without growing them.
  EXPECT_LT(apart, 1e-5);
  EXPECT_NEAR(cached_path.end_velocity.x(), kPlatformSpeed_m_per_s, 0.02);
}

// The same through a numbered OBJ sequence: `softbody export` writes the keyframed collider as collider_0_%04d.obj,
// one file per frame, and "cache": "out/collider_0_%04d.obj" reads them back, frame k at k / fps.
TEST(PointCacheCollider, ExportedMeshSequenceOfAKeyframedMeshMovesABodyAsTheKeysDid) {
  const fs::path dir = testing_support::scratch_dir("point_cache_sequence");
  const std::string keyed = keyed_platform_scene(dir);
  const testing_support::CommandResult exported =
      testing_support::run_softbody("export " + (dir / "keyed.json").string() + " -o " + (dir / "out").string());
  ASSERT_EQ(exported.exit_status, 0) << exported.output;
  const std::string cached =
      cube_on_platform(R"("shape": "mesh", "mesh": ")" + (dir / "out/collider_0_0000.obj").string() +
                           R"(", "cache": ")" + (dir / "out/collider_0_%04d.obj").string() + "\"",
                       "friction", step_keys(sim::kIntegrators[0]));
  const CentrePath keyed_path = centre_path(keyed), cached_path = centre_path(cached);
  ASSERT_EQ(keyed_path.centres.size(), cached_path.centres.size());
  const double apart = farthest_apart(keyed_path, cached_path);
  std::printf("the body's centre on the sequence's platform and on the keyframed one: at most %.3g m apart\n", apart);
  EXPECT_LT(apart, 1e-5);
}

// The platform's cache written directly (8 corners sliding along +x at 0.5 m/s), every integrator at its automatic
// step, friction and smooth contacts: the body's mean velocity over the last half second is the platform's.
TEST(PointCacheCollider, CachedPlatformCarriesABodyWithIt) {
  const fs::path dir = testing_support::scratch_dir("point_cache_platform");
  write_file(dir / "platform.obj", box_obj(kPlatformHalf));
  write_file(dir / "platform.pc2", translated_box_pc2(kPlatformHalf, Vec3(kPlatformSpeed_m_per_s, 0, 0), 30, 61));
  const std::string platform = R"("shape": "mesh", "mesh": ")" + (dir / "platform.obj").string() + R"(", "cache": ")" +
                               (dir / "platform.pc2").string() + "\"";
  for (const char* contact : {"friction", "smooth"}) {
    for (const sim::IntegratorInfo& integrator : sim::kIntegrators) {
      std::string step = step_keys(integrator);
      // xpbd's explicit regularised friction jitters at its automatic substeps (as on a keyframed platform).
      if (integrator.kind == sim::IntegratorKind::Xpbd && std::string(contact) == "smooth")
        step = R"("integrator": "xpbd", "substeps": 40)";
      Vec3 com_at_1s = Vec3::Zero();
      const sim::World world = testing_support::run_scene_frames(
          cube_on_platform(platform, contact, step), [&](double t, const sim::World& w) {
            if (std::abs(t - 1.0) < 1e-9) com_at_1s = sim::diagnose(w.model, w.state, 0).com_m;
          });
      const Vec3 v = (sim::diagnose(world.model, world.state, 0).com_m - com_at_1s) / 0.5;
      std::printf("%-8s %-10s mean velocity from 1 to 1.5 s: (%.4f, %.4f, %.4f) m/s, platform's %.2f\n", contact,
                  std::string(integrator.name).c_str(), v.x(), v.y(), v.z(), kPlatformSpeed_m_per_s);
      EXPECT_NEAR(v.x(), kPlatformSpeed_m_per_s, 0.02 * kPlatformSpeed_m_per_s) << contact << ", " << integrator.name;
      EXPECT_LT(std::abs(v.y()) + std::abs(v.z()), 0.01) << contact << ", " << integrator.name;
    }
  }
}

constexpr double kHalfThickness_m = 0.005;   // the board: 1 cm thick, its top at y = +5 mm
constexpr double kBoardSpeed_m_per_s = 0.2;  // along +x

// The lowest any vertex over the board got below its top after any step [m], the board sliding along +x.
double deepest_below_board_top(const std::string& text, bool continuous) {
  double deepest = 0.0;
  testing_support::run_scene_steps(
      text,
      [&](const sim::World& world) {
        const double centre = kBoardSpeed_m_per_s * world.state.time_s;
        for (const Vec3& x : world.state.x) {
          if (std::max(std::abs(x.x() - centre), std::abs(x.z())) < 0.3)
            deepest = std::max(deepest, kHalfThickness_m - x.y());
        }
      },
      [&](sim::World& world) { world.model.colliders.at(0).continuous = continuous; });
  return deepest;
}

// A ball at 5 m/s onto a cached 1 cm board sliding at 0.2 m/s: the continuous check against a cached mesh carries a
// step's start with the nearest surface point's motion, then crosses the segment with the pose at the step's end.
// Not through the board in any model and integrator; with the impulse contacts no vertex inside at all (1 µm of
// round-off); with the smooth one less than the board's thickness (its spring lets a vertex sink about v τ, and
// without the continuous check the same runs go through, so the test can fail).
TEST(PointCacheCollider, NoVertexEndsAStepBehindOrInsideACachedBoard) {
  const fs::path dir = testing_support::scratch_dir("point_cache_board");
  const Vec3 half(0.3, kHalfThickness_m, 0.3);
  write_file(dir / "board.obj", box_obj(half));
  write_file(dir / "board.pc2", translated_box_pc2(half, Vec3(kBoardSpeed_m_per_s, 0, 0), 100, 12));
  int smooth_discrete_passes = 0;
  for (const char* contact : {"paper", "friction", "smooth"}) {
    for (const sim::IntegratorInfo& integrator : sim::kIntegrators) {
      const std::string step = integrator.frame_substeps ? R"("substeps": "auto")" : R"("dt": "auto")";
      const std::string text = R"({ "duration": 0.1, "fps": 100, "solver": { "integrator": ")" +
                               std::string(integrator.name) + R"(", )" + step +
                               R"( }, "colliders": [ { "shape": "mesh", "mesh": ")" + (dir / "board.obj").string() +
                               R"(", "cache": ")" + (dir / "board.pc2").string() + R"(", "contact": ")" + contact +
                               R"(", "restitution": 0.3, "friction": 0.3 } ],
          "bodies": [ { "mesh": "icosphere:2", "scale": 0.05, "position": [0, 0.06, 0], "velocity": [0, -5, 0],
                        "mass": 0.2, "stiffness": 300, "damping": {"ratio": 0.3}, "pressure": {"inflation": 0.05} } ] })";
      const double deepest = deepest_below_board_top(text, true);
      const double discrete = std::string(contact) == "smooth" ? deepest_below_board_top(text, false) : 0.0;
      smooth_discrete_passes += discrete > 2.0 * kHalfThickness_m;
      std::printf("%-8s %-10s deepest below the cached board's top: %.3f mm (smooth, discrete only: %.1f mm)\n",
                  contact, std::string(integrator.name).c_str(), 1e3 * deepest, 1e3 * discrete);
      EXPECT_LT(deepest, std::string(contact) == "smooth" ? 2.0 * kHalfThickness_m : 1e-6)
          << contact << ", " << integrator.name;
    }
  }
  EXPECT_GT(smooth_discrete_passes, 0);  // without the continuous check the smooth contact lets vertices through
}

// A pose is the rest mesh refitted: its signed distance, normal and nearest point are those of a mesh built afresh
// from the same vertices (the tree's boxes and the pseudo-normals follow the vertices).
TEST(PointCacheCollider, RefittedPoseAnswersAsAMeshBuiltFromItsVertices) {
  const std::vector<Vec3> rest = box_corners(Vec3(0.5, 0.2, 0.3));
  std::vector<softbody::Triangle> triangles;
  for (int k = 0; k < 3; ++k) {
    for (int side : {0, 1}) {
      const int bk = 1 << k, bu = 1 << ((k + 1) % 3), bv = 1 << ((k + 2) % 3), base = side ? bk : 0;
      int quad[4] = {base, base + bu, base + bu + bv, base + bv};
      if (!side) std::swap(quad[1], quad[3]);
      triangles.push_back({quad[0], quad[1], quad[2]});
      triangles.push_back({quad[0], quad[2], quad[3]});
    }
  }
  std::vector<Vec3> moved = rest;  // sheared and stretched: every box and normal changes
  for (Vec3& p : moved) p = Vec3(1.3 * p.x() + 0.4 * p.y(), p.y() - 0.2 * p.z(), 0.8 * p.z()) + Vec3(0.1, -0.2, 0.3);
  const auto built = sim::make_collider_mesh(rest, triangles, 0.01);
  const auto refitted = sim::refit_collider_mesh(*built, moved, std::vector<Vec3>(moved.size()));
  const auto fresh = sim::make_collider_mesh(moved, triangles, 0.01);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  for (int i = 0; i < 5000; ++i) {
    const Vec3 q(coordinate(random), coordinate(random), coordinate(random));
    const sim::SurfacePoint a = sim::mesh_nearest_local(*refitted, q), b = sim::mesh_nearest_local(*fresh, q);
    ASSERT_NEAR(a.distance_m, b.distance_m, 1e-12) << i;
    ASSERT_LT((a.closest_m - b.closest_m).norm(), 1e-12) << i;
    ASSERT_EQ(sim::mesh_inside_local(*refitted, q), sim::mesh_inside_local(*fresh, q)) << i;
  }
}

// The refusals name the file and what is wrong.
class PointCacheRefusal : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = testing_support::scratch_dir("point_cache_refusal");
    write_file(dir_ / "box.obj", box_obj(Vec3(0.5, 0.5, 0.5)));
    good_ = translated_box_pc2(Vec3(0.5, 0.5, 0.5), Vec3(1, 0, 0), 30, 4);
  }
  // The refusal of a scene whose cube collider is cached by `bytes`, and `extra` keys.
  std::string refusal(const std::string& bytes, const std::string& extra = "") {
    write_file(dir_ / "cache.pc2", bytes);
    const std::string text = R"({ "colliders": [ { "shape": "mesh", "mesh": ")" + (dir_ / "box.obj").string() +
                             R"(", "cache": ")" + (dir_ / "cache.pc2").string() + "\"" + extra +
                             R"( } ], "bodies": [ { "mesh": "icosphere:1", "position": [0, 2, 0] } ] })";
    try {
      testing_support::world_from_text(text);
    } catch (const softbody::InputError& e) {
      return e.what();
    }
    return "";
  }
  fs::path dir_;
  std::string good_;
};

TEST_F(PointCacheRefusal, ReadsAGoodCache) { EXPECT_EQ(refusal(good_), ""); }

TEST_F(PointCacheRefusal, BadHeader) {
  std::string bytes = good_;
  bytes[0] = 'X';
  const std::string message = refusal(bytes);
  EXPECT_NE(message.find("cache.pc2"), std::string::npos) << message;
  EXPECT_NE(message.find("bad header"), std::string::npos) << message;
}

TEST_F(PointCacheRefusal, HeaderThatDisagreesWithItsSize) {
  const std::string message =
      refusal(translated_box_pc2(Vec3(0.5, 0.5, 0.5), Vec3::Zero(), 30, 2).replace(16, 1, "\x07"));
  EXPECT_NE(message.find("cache.pc2"), std::string::npos) << message;
  EXPECT_NE(message.find("24 bytes after its last sample"), std::string::npos) << message;
}

TEST_F(PointCacheRefusal, PointsThatDoNotMatchTheMesh) {
  output::PointSamples samples;
  samples.points = 7;
  samples.xyz.assign(7 * 3, 0.0f);
  samples.times_s = {0.0f};
  const std::string message = refusal(output::encode_pc2(samples, 0.0f, 1.0f));
  EXPECT_NE(message.find("cache.pc2"), std::string::npos) << message;
  EXPECT_NE(message.find("holds 7 points per sample"), std::string::npos) << message;
  EXPECT_NE(message.find("box.obj has 8 vertices"), std::string::npos) << message;
}

TEST_F(PointCacheRefusal, Truncated) {
  const std::string message = refusal(good_.substr(0, good_.size() - 5));
  EXPECT_NE(message.find("cache.pc2"), std::string::npos) << message;
  EXPECT_NE(message.find("truncated"), std::string::npos) << message;
}

TEST_F(PointCacheRefusal, NotFinite) {
  std::string bytes = good_;
  const float nan = std::nanf("");
  std::memcpy(&bytes[32 + 12 * 5 + 4], &nan, 4);
  const std::string message = refusal(bytes);
  EXPECT_NE(message.find("cache.pc2"), std::string::npos) << message;
  EXPECT_NE(message.find("not finite"), std::string::npos) << message;
}

// A numbered sequence whose files differ from the first, or that names no file.
TEST_F(PointCacheRefusal, SequenceFilesThatDifferFromTheFirst) {
  const fs::path seq = dir_ / "seq";
  fs::create_directories(seq);
  write_file(seq / "box_0000.obj", box_obj(Vec3(0.5, 0.5, 0.5)));
  write_file(seq / "box_0001.obj", box_obj(Vec3(0.6, 0.5, 0.5)));
  write_file(seq / "box_0002.obj", box_obj(Vec3(0.6, 0.5, 0.5)) + "v 0 0 0\n");
  const std::string text = R"({ "colliders": [ { "shape": "mesh", "mesh": ")" + (dir_ / "box.obj").string() +
                           R"(", "cache": ")" + (seq / "box_%04d.obj").string() +
                           R"(" } ], "bodies": [ { "mesh": "icosphere:1", "position": [0, 2, 0] } ] })";
  std::string message;
  try {
    testing_support::world_from_text(text);
  } catch (const softbody::InputError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("colliders.0.cache"), std::string::npos) << message;
  EXPECT_NE(message.find("box_0002.obj: has 9 vertices"), std::string::npos) << message;
  fs::remove(seq / "box_0002.obj");
  EXPECT_NO_THROW(testing_support::world_from_text(text));
  const std::string none = testing_support::scene_refusal(
      R"({ "colliders": [ { "shape": "mesh", "mesh": "cube:1", "cache": "data/%d_%d.obj" } ], "bodies": [ { "mesh": "icosphere:1" } ] })");
  EXPECT_NE(none.find("one frame number conversion"), std::string::npos) << none;
}

TEST_F(PointCacheRefusal, WithKeysOrOnAnotherShape) {
  const std::string with_keys = refusal(good_, R"(, "keys": [ {"time": 0} ])");
  EXPECT_NE(with_keys.find("colliders.0.cache"), std::string::npos) << with_keys;
  EXPECT_NE(with_keys.find("not both"), std::string::npos) << with_keys;
  const std::string on_box = testing_support::scene_refusal(
      R"({ "colliders": [ { "shape": "box", "size": [1, 1, 1], "cache": "x.pc2" } ], "bodies": [ { "mesh": "icosphere:1" } ] })");
  EXPECT_NE(on_box.find("colliders.0.cache"), std::string::npos) << on_box;
  EXPECT_NE(on_box.find("a box takes no \"cache\""), std::string::npos) << on_box;
}

}  // namespace
