// Hostile and careless scene files and --set values (tests/data/hostile/*.json): nesting that overflowed the
// stack, numbers that overflowed the frame count, the frame clock or the stability scan, names and patterns
// that wrote outside the output folder, keys given twice, control characters and lengths in names, derived
// quantities that overflow, and scenes whose bodies together exceed the memory. Each is refused before any work: exit
// 2, one line naming the file, the key and the limit, and no output written.
#include <fstream>

#include <gtest/gtest.h>

#include "core/errors.hpp"
#include "frames/frame_clock.hpp"
#include "mesh/generators.hpp"
#include "scene/json_text.hpp"
#include "scene/overrides.hpp"
#include "scene/scene_json.hpp"
#include "setup/scene_totals.hpp"
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
                     "bodies.0.scale: expected a finite number in [1e-6, 1e6]"},
        // The ball (radius 1 m, its centre at y = 3 m) under a floor raised to 5 m: it collapsed within 8 steps.
        HostileScene{"scenes/bounce.json --set floor.height=5",
                     "scenes/bounce.json: bodies.0.position: the body starts under the floor: its centre at y = 3 m, "
                     "its top at 4 m, the floor at 5 m (floor.height): expected a position whose body is above the "
                     "floor"},
        // A key given twice: in a file, and in a --set value.
        HostileScene{HOSTILE "duplicate_key.json",
                     HOSTILE "duplicate_key.json: bodies.0.mass: expected each key once in an object, got it twice: "
                             "number 1.0, then number 1000000000.0"},
        HostileScene{"scenes/bounce.json --set 'floor={\"height\": 0, \"height\": 1}'",
                     "--set floor={\"height\": 0, \"height\": 1}: height: expected each key once in an object, got it "
                     "twice: number 0, then number 1"},
        // Control characters and lengths in what names files.
        HostileScene{"scenes/bounce.json --set 'bodies.0.mesh=\"cube.obj\\u0000junk\"'",
                     "bodies.0.mesh: expected a name without control characters (NUL, line breaks, ...): it names a "
                     "file, got string \"cube.obj\\u0000junk\""},
        HostileScene{HOSTILE "name_nul.json",
                     HOSTILE "name_nul.json: name: expected a name without control characters"},
        HostileScene{HOSTILE "output_dir_newline.json", "output.dir: expected a name without control characters"},
        HostileScene{"scenes/bounce.json --set 'output.pattern=\"frame_%04d\\n.png\"'",
                     "output.pattern: expected a name without control characters"},
        HostileScene{HOSTILE "name_300_bytes.json",
                     HOSTILE "name_300_bytes.json: name: expected at most 255 bytes (what a file name may hold), got "
                             "string \"aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa... (300 bytes)"},
        HostileScene{
            "scenes/bounce.json --set output.dir=out/$(printf 'a%.0s' $(seq 256))/b",
            "output.dir: expected each part between slashes at most 255 bytes (what a file name may hold), got "
            "one of 256 bytes"},
        // Numbers within their ranges whose derived quantities overflow: refused before any step.
        HostileScene{HOSTILE "mass_subnormal.json",
                     "bodies.0.mass: expected a finite number > 0 and 0 or at least 2.2e-308 in magnitude (not "
                     "subnormal)"},
        HostileScene{"scenes/bounce.json --set bodies.0.mass=1e-320", "bodies.0.mass: expected a finite number > 0"},
        HostileScene{HOSTILE "mass_1e-300.json", HOSTILE
                     "mass_1e-300.json: bodies.0.stiffness: k/m = 5.02e+304 1/s² (k = 1e+03 N/m, the lightest "
                     "vertex 1.99e-302 kg), beyond the limit of 1e200 1/s²: expected a smaller bodies.0.stiffness "
                     "or a larger bodies.0.mass"},
        HostileScene{HOSTILE "frequency_1e300.json",
                     HOSTILE "frequency_1e300.json: bodies.0.stiffness.frequency: the springs' k = inf N/m, not "
                             "finite"},
        HostileScene{HOSTILE "smooth_time_constant_1e-300.json",
                     HOSTILE "smooth_time_constant_1e-300.json: floor.time_constant: the smooth contact's ω² = 1/τ² = "
                             "inf 1/s², beyond the limit of 1e200 1/s²"},
        // Many bodies that each fit the per-file limits: the scene's totals.
        HostileScene{HOSTILE "many_icospheres.json",
                     HOSTILE "many_icospheres.json: limits.max_total_vertices: the scene's bodies hold 49152600 "
                             "vertices (meshes and simulation proxies), more than the limit of"},
        HostileScene{"scenes/bounce.json --set limits.max_total_triangles=100",
                     "limits.max_total_triangles: the scene's bodies hold 1280 triangles"},
        // Collider meshes count too: a generator's before it is built, a file's as it is read.
        HostileScene{"scenes/stairs.json --set colliders.0.mesh=torus:512,256 --set limits.max_total_vertices=100000",
                     "stairs.json: limits.max_total_vertices: the scene's bodies and collider meshes hold 131714 "
                     "vertices (bodies 642, collider meshes 131072, the largest colliders.0.mesh with 131072), more "
                     "than the limit of 100000: expected fewer or smaller bodies or collider meshes, or a larger "
                     "limits.max_total_vertices"},
        HostileScene{"scenes/stairs.json --set limits.max_total_vertices=650",
                     "limits.max_total_vertices: the scene's bodies and collider meshes hold 674 vertices (bodies 642, "
                     "collider meshes 32, the largest colliders.0.mesh with 32)"}),
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

// A 10 MB name or --set value is echoed in a message cut to about 100 bytes, with its length.
TEST(HostileScene, LongValuesAreCutInMessages) {
  const std::string long_key(100000, 'k');  // an argument may hold at most 128 KiB
  const auto result = run_softbody("simulate scenes/bounce.json --set bodies.0." + long_key +
                                   "=1 --csv build/hostile_long_should_not_exist.csv");
  EXPECT_EQ(result.exit_status, 2) << result.output.substr(0, 400);
  EXPECT_LT(result.output.size(), 400u) << result.output.substr(0, 400);
  EXPECT_NE(result.output.find("... (100009 bytes): unknown key"), std::string::npos) << result.output.substr(0, 400);
  EXPECT_EQ(scene::message_text("a\nb\x01"), "a\\nb\\x01");
  EXPECT_EQ(scene::message_text(std::string(20, 'x'), 10), "xxxxxxx... (20 bytes)");
  EXPECT_EQ(scene::describe_json(nlohmann::json(std::string(10 << 20, 'a'))),
            "string \"aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa... (10485760 bytes)");
}

// The scene's totals count a generator's size without building it.
TEST(HostileScene, GeneratorSizesMatchTheGenerators) {
  for (const char* spec : {"icosphere:0", "icosphere:3", "cube:1", "cube:7", "torus:12,5", "capsule:4", "capsule:13"}) {
    const mesh::TriMesh built = mesh::generate(spec);
    const setup::MeshSize size = setup::generator_size(spec);
    EXPECT_EQ(size.vertices, static_cast<long long>(built.vertices.size())) << spec;
    EXPECT_EQ(size.triangles, static_cast<long long>(built.triangles.size())) << spec;
  }
  EXPECT_EQ(setup::generator_size("icosphere:7").vertices, 163842);
}

// A duplicate key is refused wherever it is, and the parse error names where.
TEST(HostileScene, DuplicateKeysAreRefusedAtAnyDepth) {
  EXPECT_NO_THROW(scene::parse_json_limited(R"({"a": {"b": 1}, "c": [{"b": 2}, {"b": 3}]})", "t", false));
  try {
    scene::parse_json_limited(R"({"a": [{"b": {"x": 1}}, {"b": [1], "b": {"y": 2}}]})", "t", false);
    FAIL() << "accepted";
  } catch (const softbody::InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "t: a.1.b: expected each key once in an object, got it twice: an array, then an "
              "object");
  }
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
