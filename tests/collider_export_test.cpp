// Exported colliders: a static one written once, a keyframed one per frame (or as a point cache) where its keys put
// it at each frame's time, with no files of an earlier run left beside a new run's (frames, nor a collider that was
// static and is keyframed now, or the other way round), and nothing else removed.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "background_run.hpp"
#include "core/vec.hpp"
#include "sim/contact/collider_motion.hpp"
#include "test_helpers.hpp"

namespace {

using softbody::Vec3;

constexpr double kFps = 10.0;
const Vec3 kStart(0.0, 0.5, 3.0);  // the box's first key; it moves 1 m along x over the run

// A scene of `duration` s at 10 fps: a small body far from the colliders, and as collider 0 a box, keyframed from
// kStart to kStart + (1, 0, 0) over the run or static at kStart, then a static sphere.
std::string scene_text(double duration, bool moving) {
  const std::string box = moving ? R"("keys": [ { "time": 0, "position": [0, 0.5, 3] },
                                                { "time": )" +
                                       std::to_string(duration) + R"(, "position": [1, 0.5, 3] } ])"
                                 : R"("position": [0, 0.5, 3])";
  return R"({ "duration": )" + std::to_string(duration) + R"(, "fps": 10,
    "colliders": [ { "shape": "box", "size": [0.4, 0.2, 0.6], "rotation": [0, 30, 0], )" +
         box + R"( },
                   { "shape": "sphere", "radius": 0.3, "position": [-3, 0.3, 0] } ],
    "bodies": [ { "mesh": "icosphere:1", "scale": 0.2, "position": [0, 0.3, 0] } ] })";
}

std::filesystem::path write_scene(const std::filesystem::path& dir, const std::string& name, double duration,
                                  bool moving) {
  const std::filesystem::path path = dir / name;
  std::ofstream(path) << scene_text(duration, moving);
  return path;
}

void export_scene(const std::filesystem::path& scene, const std::filesystem::path& out, const std::string& flags) {
  const testing_support::CommandResult result =
      testing_support::run_softbody("export " + scene.string() + " -o " + out.string() + " " + flags);
  ASSERT_EQ(result.exit_status, 0) << result.output;
}

// The "v x y z" lines of an OBJ file.
std::vector<Vec3> obj_vertices(const std::filesystem::path& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in) << path;
  std::vector<Vec3> vertices;
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("v ", 0) != 0) continue;
    std::istringstream words(line.substr(2));
    Vec3 p;
    words >> p.x() >> p.y() >> p.z();
    vertices.push_back(p);
  }
  return vertices;
}

std::string file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// Where the box's keys put it at frame k, relative to its first key.
Vec3 offset_at_frame(double duration, int frame) {
  const sim::World world = testing_support::world_from_text(scene_text(duration, true));
  return sim::pose_at(world.model.colliders[0].motion, frame / kFps).position_m - kStart;
}

std::vector<std::string> collider_files(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("collider_", 0) == 0) names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  return names;
}

TEST(ColliderExport, KeyframedBoxIsWrittenPerFrameWhereItsKeysPutIt) {
  const std::filesystem::path dir = testing_support::scratch_dir("collider_export_moving");
  export_scene(write_scene(dir, "static.json", 0.3, false), dir / "static", "");
  export_scene(write_scene(dir, "moving.json", 0.3, true), dir / "moving", "");

  // Static: each collider once, no frames.
  EXPECT_EQ(collider_files(dir / "static"), (std::vector<std::string>{"collider_0.obj", "collider_1.obj"}));
  // Keyframed: the box per frame (0 .. 3), the static sphere once.
  EXPECT_EQ(collider_files(dir / "moving"),
            (std::vector<std::string>{"collider_0_0000.obj", "collider_0_0001.obj", "collider_0_0002.obj",
                                      "collider_0_0003.obj", "collider_1.obj"}));
  EXPECT_EQ(file_bytes(dir / "moving" / "collider_1.obj"), file_bytes(dir / "static" / "collider_1.obj"));

  const std::vector<Vec3> rest = obj_vertices(dir / "static" / "collider_0.obj");
  ASSERT_EQ(rest.size(), 8u * 3u);  // a box's faces, each corner with its face's normal
  for (int frame = 0; frame <= 3; ++frame) {
    const Vec3 offset = offset_at_frame(0.3, frame);
    EXPECT_NEAR(offset.x(), frame / 3.0, 1e-12);  // 1 m along x over the run
    const std::vector<Vec3> moved = obj_vertices(dir / "moving" / ("collider_0_000" + std::to_string(frame) + ".obj"));
    ASSERT_EQ(moved.size(), rest.size());
    for (std::size_t i = 0; i < rest.size(); ++i)
      EXPECT_LT((moved[i] - (rest[i] + offset)).norm(), 1e-12) << "frame " << frame << " vertex " << i;
  }
}

TEST(ColliderExport, NewRunLeavesNoStaleColliderFrames) {
  const std::filesystem::path dir = testing_support::scratch_dir("collider_export_rerun");
  export_scene(write_scene(dir, "long.json", 0.3, true), dir / "out", "--format ply");
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "collider_0_0003.ply"));
  export_scene(write_scene(dir, "short.json", 0.1, true), dir / "out", "--format ply");
  EXPECT_EQ(collider_files(dir / "out"),
            (std::vector<std::string>{"collider_0_0000.ply", "collider_0_0001.ply", "collider_1.ply"}));
}

// A collider that was static in the earlier export into the same folder and is keyframed now (and back): the new run
// leaves no file of its earlier kind.
TEST(ColliderExport, StaticThenKeyframedLeavesNoFileOfTheEarlierKind) {
  const std::filesystem::path dir = testing_support::scratch_dir("collider_export_kind");
  const std::filesystem::path still = write_scene(dir, "static.json", 0.2, false);
  const std::filesystem::path moving = write_scene(dir, "moving.json", 0.2, true);
  export_scene(still, dir / "out", "");
  export_scene(moving, dir / "out", "");
  EXPECT_EQ(collider_files(dir / "out"), (std::vector<std::string>{"collider_0_0000.obj", "collider_0_0001.obj",
                                                                   "collider_0_0002.obj", "collider_1.obj"}));
  export_scene(still, dir / "out", "");
  EXPECT_EQ(collider_files(dir / "out"), (std::vector<std::string>{"collider_0.obj", "collider_1.obj"}));

  // Point caches: the keyframed box's cache goes when the box is static (an import would move it by the cache).
  export_scene(moving, dir / "cache", "--format pc2");
  EXPECT_EQ(collider_files(dir / "cache"),
            (std::vector<std::string>{"collider_0.obj", "collider_0.pc2", "collider_1.obj"}));
  export_scene(still, dir / "cache", "--format mdd");
  EXPECT_EQ(collider_files(dir / "cache"), (std::vector<std::string>{"collider_0.obj", "collider_1.obj"}));
}

// Only the files a run names so are removed: not a near name, not a folder, not one of the run's inputs (a body mesh
// kept in the output folder under a collider's name).
TEST(ColliderExport, ANewRunRemovesOnlyItsOwnNames) {
  const std::filesystem::path dir = testing_support::scratch_dir("collider_export_names");
  const std::filesystem::path out = dir / "out";
  std::filesystem::create_directories(out / "collider_5.obj");  // a folder
  std::filesystem::copy_file(testing_support::data_path("cube_quads.obj"), out / "collider_7.obj");
  const std::vector<std::string> kept = {"collider_01.obj", "collider_2.obj.bak", "collider_x.obj",
                                         "collider_3.stl",  "collider_-1.obj",    "Collider_4.obj"};
  for (const std::string& name : kept) std::ofstream(out / name) << "# not softbody's\n";
  std::ofstream(out / "collider_9.obj") << "# an earlier run's\n";
  std::ofstream(dir / "scene.json") << R"({ "duration": 0.1, "fps": 10,
    "colliders": [ { "shape": "sphere", "radius": 0.3, "position": [-3, 0.3, 0] } ],
    "bodies": [ { "mesh": "out/collider_7.obj", "scale": 0.2, "position": [0, 0.3, 0] } ] })";
  const testing_support::CommandResult result =
      testing_support::run_softbody("export " + (dir / "scene.json").string() + " -o " + out.string());
  ASSERT_EQ(result.exit_status, 0) << result.output;
  EXPECT_NE(result.output.find("removed an earlier run's outputs before writing: 1 collider files"), std::string::npos)
      << result.output;
  EXPECT_FALSE(std::filesystem::exists(out / "collider_9.obj"));
  EXPECT_TRUE(std::filesystem::is_directory(out / "collider_5.obj"));
  EXPECT_EQ(file_bytes(out / "collider_7.obj"), file_bytes(testing_support::data_path("cube_quads.obj")));
  for (const std::string& name : kept) EXPECT_TRUE(std::filesystem::exists(out / name)) << name;
}

// export --resume vouches for a frame only when the manifest vouches for its collider files too: a collider frame
// removed after SIGINT is made again, and the files end as an uninterrupted run's.
TEST(ColliderExport, ResumeRemakesAMissingColliderFrame) {
  const std::filesystem::path dir = testing_support::scratch_dir("collider_export_resume");
  const std::filesystem::path scene = write_scene(dir, "moving.json", 1.0, true), out = dir / "out";
  export_scene(scene, dir / "reference", "--set solver.dt=2e-6");
  {
    testing_support::BackgroundRun run(
        {"export", scene.string(), "--set", "solver.dt=2e-6", "-o", out.string(), "--resume"}, dir);
    ASSERT_TRUE(
        run.wait_until([&] { return std::filesystem::exists(out / "collider_0_0004.obj"); }, std::chrono::seconds(60)))
        << run.errors();
    run.signal(SIGINT);
    ASSERT_EQ(run.wait_for_exit(std::chrono::seconds(60)), std::optional<int>(130)) << run.errors();
  }
  ASSERT_FALSE(std::filesystem::exists(out / "collider_0_0010.obj"));  // the run was interrupted
  std::filesystem::remove(out / "collider_0_0002.obj");
  const testing_support::CommandResult resumed = testing_support::run_softbody(
      "export " + scene.string() + " --set solver.dt=2e-6 -o " + out.string() + " --resume");
  ASSERT_EQ(resumed.exit_status, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("frames 0..1 are complete"), std::string::npos) << resumed.output;
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "reference")) {
    EXPECT_EQ(file_bytes(out / entry.path().filename()), file_bytes(entry.path())) << entry.path().filename();
    ++files;
  }
  EXPECT_EQ(files, 11 + 11 + 1);  // the body frames, the box's frames, the sphere
}

// Little-endian 32-bit values of a PC2 file.
template <typename T>
T read_le(const std::string& bytes, std::size_t offset) {
  T value;
  std::memcpy(&value, bytes.data() + offset, sizeof(T));
  return value;
}

TEST(ColliderExport, KeyframedBoxGetsAPointCache) {
  const std::filesystem::path dir = testing_support::scratch_dir("collider_export_pc2");
  export_scene(write_scene(dir, "static.json", 0.3, false), dir / "static", "");
  export_scene(write_scene(dir, "moving.json", 0.3, true), dir / "cache", "--format pc2");
  EXPECT_EQ(collider_files(dir / "cache"),
            (std::vector<std::string>{"collider_0.obj", "collider_0.pc2", "collider_1.obj"}));

  const std::vector<Vec3> rest = obj_vertices(dir / "static" / "collider_0.obj");
  const std::vector<Vec3> first = obj_vertices(dir / "cache" / "collider_0.obj");  // the box at frame 0
  ASSERT_EQ(first.size(), rest.size());
  for (std::size_t i = 0; i < rest.size(); ++i) EXPECT_LT((first[i] - rest[i]).norm(), 1e-12);

  const std::string pc2 = file_bytes(dir / "cache" / "collider_0.pc2");
  ASSERT_GE(pc2.size(), 32u);
  EXPECT_EQ(std::string(pc2.data(), 12), std::string("POINTCACHE2", 12));
  const int points = read_le<std::int32_t>(pc2, 16), samples = read_le<std::int32_t>(pc2, 28);
  EXPECT_EQ(points, static_cast<int>(rest.size()));
  EXPECT_EQ(read_le<float>(pc2, 20), 0.0f);  // start frame
  ASSERT_EQ(samples, 4);                     // frames 0 .. 3
  ASSERT_EQ(pc2.size(), 32u + 12u * static_cast<std::size_t>(points * samples));
  for (int frame = 0; frame < samples; ++frame) {
    const Vec3 offset = offset_at_frame(0.3, frame);
    for (int i = 0; i < points; ++i) {
      const std::size_t at = 32u + 12u * static_cast<std::size_t>(frame * points + i);
      const Vec3 cached(read_le<float>(pc2, at), read_le<float>(pc2, at + 4), read_le<float>(pc2, at + 8));
      EXPECT_LT((cached - (rest[static_cast<std::size_t>(i)] + offset)).norm(), 1e-6)
          << "frame " << frame << " vertex " << i;
    }
  }
}

}  // namespace
