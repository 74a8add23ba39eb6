// Hostile and careless scene files and --set values (tests/data/hostile/*.json): nesting that overflowed the
// stack, numbers that overflowed the frame count, the frame clock or the stability scan, names and patterns
// that wrote outside the output folder. Each is refused before any work: exit 2, one line naming the file,
// the key and the limit, and no output written.
#include <fstream>

#include <gtest/gtest.h>

#include "core/errors.hpp"
#include "frames/frame_clock.hpp"
#include "scene/json_text.hpp"
#include "scene/overrides.hpp"
#include "scene/scene_json.hpp"
#include "test_helpers.hpp"

namespace {

using testing_support::run_softbody;

struct HostileScene {
  const char* arguments;  // after "simulate"
  const char* message;
};

class HostileSceneFile : public ::testing::TestWithParam<HostileScene> {};

TEST_P(HostileSceneFile, ExitsTwoWithOneLineAndWritesNothing) {
  const std::string csv = "build/hostile_scene_should_not_exist.csv";
  const auto result = run_softbody(std::string("simulate ") + GetParam().arguments + " --csv " + csv);
  EXPECT_EQ(result.exit_status, 2) << result.output;
  EXPECT_EQ(result.output.rfind("error: ", 0), 0u) << result.output;
  EXPECT_EQ(std::count(result.output.begin(), result.output.end(), '\n'), 1) << result.output;
  EXPECT_NE(result.output.find(GetParam().message), std::string::npos) << result.output;
  EXPECT_FALSE(std::ifstream(csv).good()) << "no output file on bad input";
}

#define HOSTILE "tests/data/hostile/"
INSTANTIATE_TEST_SUITE_P(
    Scenes, HostileSceneFile,
    ::testing::Values(
        HostileScene{HOSTILE "deep_file.json", HOSTILE "deep_file.json: "
                                                       "0.0.0.0"},
        HostileScene{HOSTILE "deep_file.json", "nested deeper than 64 levels"},
        HostileScene{HOSTILE "deep_value.json", HOSTILE "deep_value.json: bodies.0.mass.0.0"},
        HostileScene{HOSTILE "number_1e400.json",
                     HOSTILE "number_1e400.json: bodies.0.mass: expected a finite number, got '1e400'"},
        HostileScene{
            HOSTILE "duration_1e300.json", HOSTILE
            "duration_1e300.json: duration: 1e+300 s at 30 fps makes 3e+301 frames, more than the limit of 100000000"},
        HostileScene{HOSTILE "duration_1e8.json", "more than the limit of 100000000"},
        HostileScene{HOSTILE "tiny_dt.json",
                     "solver.dt: 1e-300 s needs 3.33e+298 steps per frame at 30 fps, more than the limit of 1000000"},
        HostileScene{HOSTILE "scale_1e200.json",
                     HOSTILE "scale_1e200.json: bodies.0.scale: expected a finite number in [1e-6, 1e6]"},
        HostileScene{HOSTILE "scale_1e-200.json", "bodies.0.scale: expected a finite number in [1e-6, 1e6]"},
        HostileScene{HOSTILE "position_1e308.json",
                     "bodies.0.position.0: expected a finite number within +-1e6, got number 1e+308"},
        HostileScene{HOSTILE "name_dotdot.json",
                     HOSTILE "name_dotdot.json: name: expected a name without slashes, other than"},
        HostileScene{HOSTILE "mesh_dev_zero.json", "bodies.0.mesh: mesh file /dev/zero is a character device"},
        HostileScene{HOSTILE "mesh_directory.json", "bodies.0.mesh: mesh file " HOSTILE ". is a directory"},
        HostileScene{HOSTILE "huge_mesh_coordinates.json",
                     "bodies.0.mesh: mesh " HOSTILE "obj_huge_vertex.obj has a vertex with coordinate inf"},
        HostileScene{HOSTILE "pattern_string_conversion.json", "output.pattern: expected a file name ending in .png"},
        HostileScene{HOSTILE "pattern_no_conversion.json", "output.pattern: expected a file name ending in .png"},
        HostileScene{HOSTILE "tiny_mesh_limit.json", "12 triangles, more than the limit of 10"},
        HostileScene{"/dev/zero", "/dev/zero: cannot open the scene file (it is a character device"},
        HostileScene{HOSTILE, "cannot open the scene file (it is a directory"},
        HostileScene{"scenes/bounce.json --set bodies.99999999999999999999.mass=1",
                     "--set bodies.99999999999999999999.mass=1: bodies.99999999999999999999: index out of range (the "
                     "array has 1 elements)"},
        HostileScene{"scenes/bounce.json --set bodies.0.mass=1e400",
                     "bodies.0.mass: expected a number > 0, got string \"1e400\""},
        HostileScene{"scenes/bounce.json --set bodies.0.scale=1e-7",
                     "bodies.0.scale: expected a finite number in [1e-6, 1e6]"}),
    [](const auto& test) {
      std::string name = std::to_string(test.index) + "_" + test.param.arguments;
      if (name.rfind("tests/data/hostile/") != std::string::npos) name.erase(name.find("tests/data/hostile/"), 19);
      for (char& c : name) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
      return name.substr(0, 60);
    });

// The same with the file given to `info`, which ran the stability estimate's endless scan before.
TEST(HostileScene, InfoRefusesScalesBeyondTheLimit) {
  for (const char* file : {HOSTILE "scale_1e200.json", HOSTILE "scale_1e-200.json", HOSTILE "position_1e308.json"}) {
    const auto result = run_softbody(std::string("info ") + file);
    EXPECT_EQ(result.exit_status, 2) << file << ": " << result.output;
  }
}

TEST(HostileScene, OutputPatternsNeedExactlyOneIntegerConversion) {
  for (const char* file : {HOSTILE "pattern_string_conversion.json", HOSTILE "pattern_no_conversion.json"}) {
    const auto result = run_softbody(std::string("render ") + file + " -o build/hostile_pattern_should_not_exist");
    EXPECT_EQ(result.exit_status, 2) << file << ": " << result.output;
    EXPECT_NE(result.output.find("output.pattern: expected a file name ending in .png with one frame number"),
              std::string::npos)
        << result.output;
    EXPECT_FALSE(std::filesystem::exists("build/hostile_pattern_should_not_exist"));
  }
}

// Deeply nested values built in code (not parsed) are described without recursion.
TEST(HostileScene, DeepValuesAreDescribedWithoutRecursion) {
  nlohmann::json deep = nlohmann::json::array();
  nlohmann::json* inner = &deep;
  for (int i = 0; i < 100000; ++i) {
    inner->push_back(nlohmann::json::array());
    inner = &(*inner)[0];
  }
  EXPECT_EQ(scene::describe_json(deep), "array nested deeper than 8 levels");
  EXPECT_EQ(scene::describe_json(nlohmann::json::parse("[[1, 2], 3]")), "array [[1,2],3]");
}

// Found by fuzz_scene: a --set value is taken as bytes, and one that is not UTF-8 made the scene hash's
// dump throw nlohmann's type_error (exit 1 with its raw text) instead of the key's message.
TEST(HostileScene, SetValuesThatAreNotUtf8GetTheKeysMessage) {
  nlohmann::json document = scene::parse_scene_text(R"({ "bodies": [ {} ] })", "s.json");
  scene::apply_override(document, "floor.contact=fric\xfftion");
  try {
    scene::scene_from_json(document, "s.json");
    FAIL() << "accepted";
  } catch (const softbody::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("s.json: floor.contact: expected one of \"paper\" \"friction\""),
              std::string::npos)
        << e.what();
  }
  scene::apply_override(document, "name=caf\xff");  // a valid value whose bytes are not UTF-8: dumped, replaced
  scene::apply_override(document, "floor.contact=paper");
  EXPECT_NO_THROW(scene::scene_from_json(document, "s.json"));
}

TEST(HostileScene, DepthLimitLeavesRoomForRealScenes) {
  const std::string ok = std::string(scene::kMaxJsonDepth, '[') + std::string(scene::kMaxJsonDepth, ']');
  EXPECT_NO_THROW(scene::parse_json_limited(ok, "t", false));
  EXPECT_THROW(scene::parse_json_limited("[" + ok + "]", "t", false), softbody::InputError);
}

TEST(HostileScene, FrameClockRefusesWhatAnIntCannotCount) {
  EXPECT_EQ(frames::plan_frames(1.0, 30, 1e-3).frame_count, 30);
  EXPECT_THROW(frames::plan_frames(1e300, 30, 1e-3), softbody::InputError);
  EXPECT_THROW(frames::plan_frames(1e8, 30, 1e-3), softbody::InputError);  // 3e9 frames: beyond an int
  EXPECT_EQ(frames::plan_frames(frames::kMaxFrames / 30.0, 30, 1e-3).frame_count, frames::kMaxFrames);
  EXPECT_EQ(frames::plan_frames(1.0, 30, 1.0 / 30 / frames::kMaxStepsPerFrame).steps_per_frame,
            frames::kMaxStepsPerFrame);
  EXPECT_THROW(frames::plan_frames(1.0, 30, 0.5 / 30 / frames::kMaxStepsPerFrame), softbody::InputError);
}

}  // namespace
