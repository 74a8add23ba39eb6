// Scene files: defaults, comments, --set overrides and one clear message per kind of bad input.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/errors.hpp"
#include "scene/overrides.hpp"
#include "scene/scene_json.hpp"
#include "test_helpers.hpp"

namespace {

using testing_support::scene_from_text;

std::string error_of(const std::string& text, const std::vector<std::string>& overrides = {}) {
  try {
    nlohmann::json document = scene::parse_scene_text(text, "s.json");
    for (const std::string& o : overrides) scene::apply_override(document, o);
    scene::scene_from_json(document, "s.json");
  } catch (const softbody::InputError& e) {
    return e.what();
  }
  return "(no error)";
}

constexpr const char* kMinimal = R"({ "bodies": [ { "mesh": "icosphere:1" } ] })";

TEST(Scene, DefaultsAndComments) {
  const scene::Scene s = scene_from_text(R"(
    // a comment
    { "name": "x", /* block */ "bodies": [ { "mesh": "icosphere:2", "mass": 2 } ] })");
  EXPECT_EQ(s.name, "x");
  EXPECT_EQ(s.fps, 30);
  EXPECT_FALSE(s.floor.has_value());
  EXPECT_EQ(s.bodies.at(0).mass_kg, 2.0);
  EXPECT_EQ(s.output.dir, std::filesystem::path("out/x"));
}

TEST(Scene, OverridesSetNestedKeys) {
  nlohmann::json document = scene::parse_scene_text(kMinimal, "s.json");
  scene::apply_override(document, "bodies.0.stiffness=800");
  scene::apply_override(document, "solver.dt=5e-5");
  scene::apply_override(document, "solver.integrator=euler");
  scene::apply_override(document, "floor.contact=paper");
  scene::apply_override(document, "bodies.0.position=[1,2,3]");
  const scene::Scene s = scene::scene_from_json(document, "s.json");
  EXPECT_EQ(s.bodies[0].stiffness_N_per_m, 800.0);
  EXPECT_EQ(s.solver.dt_s, 5e-5);
  ASSERT_TRUE(s.floor.has_value());
  EXPECT_EQ(s.bodies[0].position_m, softbody::Vec3(1, 2, 3));
}

TEST(Scene, BadOverridesNameTheAssignment) {
  EXPECT_NE(error_of(kMinimal, {"bodies.3.mass=1"}).find("--set bodies.3.mass=1: bodies.3: index out of range"),
            std::string::npos);
  EXPECT_NE(error_of(kMinimal, {"nonsense"}).find("expected PATH=VALUE"), std::string::npos);
  EXPECT_NE(error_of(kMinimal, {"bodies.0.mass=nan"})
                .find("s.json: bodies.0.mass: expected a number > 0, got string \"nan\""),
            std::string::npos);
}

struct BadInput {
  const char* text;
  const char* message;
};

class SceneErrors : public ::testing::TestWithParam<BadInput> {};

TEST_P(SceneErrors, NameFileKeyAndExpectation) {
  const std::string error = error_of(GetParam().text);
  EXPECT_NE(error.find(GetParam().message), std::string::npos) << "got: " << error;
}

INSTANTIATE_TEST_SUITE_P(
    Scene, SceneErrors,
    ::testing::Values(
        BadInput{R"({ "bodies": [ { "mesh": "icosphere:1", "stifness": 3 } ] })",
                 "s.json: bodies.0.stifness: unknown key"},
        BadInput{R"({ "fsp": 30, "bodies": [ { } ] })", "s.json: fsp: unknown key"},
        BadInput{R"({ "bodies": [ { "mass": -1 } ] })",
                 "s.json: bodies.0.mass: expected a finite number > 0, got number -1"},
        BadInput{R"({ "bodies": [ { "mass": "heavy" } ] })",
                 "s.json: bodies.0.mass: expected a number > 0, got string \"heavy\""},
        BadInput{R"({ "solver": { "dt": 0 }, "bodies": [ { } ] })", "s.json: solver.dt: expected a finite number > 0"},
        BadInput{R"({ "solver": { "dt": -1e-4 }, "bodies": [ { } ] })",
                 "s.json: solver.dt: expected a finite number > 0"},
        BadInput{R"({ "solver": { "integrator": "leapfrog" }, "bodies": [ { } ] })",
                 "s.json: solver.integrator: expected one of \"euler\""},
        BadInput{R"({ "solver": { "threads": -1 }, "bodies": [ { } ] })",
                 "s.json: solver.threads: expected an integer in 0..256"},
        BadInput{R"({ "fps": 0, "bodies": [ { } ] })", "s.json: fps: expected an integer in 1..1000, got number 0"},
        BadInput{R"({ "fps": 29.97, "bodies": [ { } ] })", "s.json: fps: expected an integer in 1..1000"},
        BadInput{R"({ "duration": -3, "bodies": [ { } ] })", "s.json: duration: expected a finite number > 0"},
        BadInput{R"({ "bodies": [ ] })", "s.json: bodies: expected an array of at least one body"},
        BadInput{R"({ })", "s.json: bodies: expected an array of at least one body"},
        BadInput{R"({ "bodies": [ { "position": [1, 2] } ] })",
                 "s.json: bodies.0.position: expected an array of 3 numbers"},
        BadInput{R"({ "bodies": [ { "pressure": -5 } ] })", "s.json: bodies.0.pressure: expected a finite number >= 0"},
        BadInput{R"({ "bodies": [ { "mesh": "icosphere:12" } ] })",
                 "s.json: bodies.0.mesh: expected icosphere:L with L an integer in 0..7"},
        BadInput{R"({ "bodies": [ { "mesh": "missing.obj" } ] })",
                 "s.json: bodies.0.mesh: mesh file missing.obj does not exist"},
        BadInput{R"({ "floor": { "contact": "sticky" }, "bodies": [ { } ] })",
                 "s.json: floor.contact: expected one of \"paper\" \"friction\""},
        BadInput{R"({ "render": { "width": 641 }, "bodies": [ { } ] })",
                 "s.json: render.width: expected an even number of pixels"},
        BadInput{R"({ "bodies": [ { "color": [1, 2, 0] } ] })",
                 "s.json: bodies.0.color.1: expected a finite number in [0, 1]"},
        BadInput{R"([1, 2])", "s.json: (top level): expected an object"},
        BadInput{R"({ "solver": { "substeps": 0 }, "bodies": [ { } ] })",
                 "s.json: solver.substeps: expected an integer in 1..1000000, got number 0"},
        BadInput{R"({ "solver": { "substeps": "many" }, "bodies": [ { } ] })",
                 "s.json: solver.substeps: expected a whole number >= 1 or \"auto\", got string \"many\""},
        BadInput{
            R"({ "solver": { "iterations": "many" }, "bodies": [ { } ] })",
            "s.json: solver.iterations: expected a whole number >= 1, \"converge\" or \"auto\", got string \"many\""},
        BadInput{R"({ "solver": { "iterations": 0 }, "bodies": [ { } ] })",
                 "s.json: solver.iterations: expected an integer in 1..10000, got number 0"},
        BadInput{R"({ "solver": { "coarse_space": "many" }, "bodies": [ { } ] })",
                 "s.json: solver.coarse_space: expected a whole number 0..512 or \"auto\", got string \"many\""},
        BadInput{R"({ "solver": { "coarse_space": 513 }, "bodies": [ { } ] })",
                 "s.json: solver.coarse_space: expected an integer in 0..512, got number 513"}),
    [](const auto& param) { return "case" + std::to_string(param.index); });

TEST(Scene, InvalidJsonNamesTheFile) {
  EXPECT_NE(error_of("{ \"bodies\": [ ").find("s.json: not valid JSON"), std::string::npos);
}

}  // namespace

namespace {

// vbd's sweeps: a number, "converge" (the sweeps stop by themselves) or "auto" (vbd holds its error); the default 4.
TEST(Scene, IterationsTakeANumberConvergeOrAuto) {
  const scene::Scene plain = scene_from_text(R"({ "bodies": [ { } ] })");
  EXPECT_EQ(plain.solver.iterations, 4);
  EXPECT_EQ(plain.solver.sweep_control, sim::SweepControl::Count);
  const scene::Scene seven = scene_from_text(R"({ "solver": { "iterations": 7 }, "bodies": [ { } ] })");
  EXPECT_EQ(seven.solver.iterations, 7);
  EXPECT_EQ(seven.solver.sweep_control, sim::SweepControl::Count);
  EXPECT_EQ(scene_from_text(R"({ "solver": { "iterations": "converge" }, "bodies": [ { } ] })").solver.sweep_control,
            sim::SweepControl::Converge);
  EXPECT_EQ(scene_from_text(R"({ "solver": { "iterations": "auto" }, "bodies": [ { } ] })").solver.sweep_control,
            sim::SweepControl::Auto);
}

// vbd's impact steps: solver.impact_phase where given, else 0.5, and 0.25 with "iterations": "auto" (whose tolerance
// the default 0.5 misses through an impact at icosphere:4).
TEST(Scene, ImpactPhaseDefaultsByTheSweepControl) {
  const auto phase_of = [](const char* solver) {
    return sim::vbd_impact_phase(
        scene_from_text(std::string(R"({ "solver": )") + solver + R"(, "bodies": [ { } ] })").solver);
  };
  EXPECT_EQ(phase_of("{}"), sim::kVbdImpactPhase);
  EXPECT_EQ(phase_of(R"({ "iterations": "converge" })"), sim::kVbdImpactPhase);
  EXPECT_EQ(phase_of(R"({ "iterations": "auto" })"), sim::kVbdAutoImpactPhase);
  EXPECT_EQ(phase_of(R"({ "iterations": "auto", "impact_phase": 0.5 })"), 0.5);
  EXPECT_EQ(phase_of(R"({ "impact_phase": 0.125 })"), 0.125);
}

// The smooth contact's keys are read and checked.
TEST(Scene, SmoothContactKeys) {
  const scene::Scene s = scene_from_text(R"({ "floor": { "contact": "smooth", "time_constant": 0.001, "slip_speed": 0.2,
      "smoothing": 0.003, "damping_ratio": 0.4 }, "collisions": { "contact": "smooth" },
      "bodies": [ { "mesh": "icosphere:1" } ] })");
  EXPECT_EQ(s.floor->contact, sim::FloorContact::Smooth);
  EXPECT_EQ(s.floor->smooth.time_constant_s, 0.001);
  EXPECT_EQ(s.floor->smooth.slip_speed_m_per_s, 0.2);
  EXPECT_EQ(s.floor->smooth.smoothing_m, 0.003);
  EXPECT_EQ(s.floor->smooth.damping_ratio, 0.4);
  EXPECT_EQ(s.collisions.contact, sim::BodyContactModel::Smooth);
  EXPECT_NE(
      error_of(R"({ "floor": { "contact": "smooth", "time_constant": 0 }, "bodies": [ { "mesh": "icosphere:1" } ] })")
          .find("floor.time_constant: expected a finite number > 0"),
      std::string::npos);
}

// The removed newton integrator is refused with its replacement named.
TEST(Scene, RemovedNewtonIntegratorNamesItsReplacement) {
  const std::string error =
      error_of(R"({ "solver": { "integrator": "newton" }, "bodies": [ { "mesh": "icosphere:1" } ] })");
  EXPECT_NE(error.find("solver.integrator: \"newton\" was removed: use \"vbd\""), std::string::npos) << error;
}

// So is the removed implicit integrator, with the key that lets vbd choose its steps.
TEST(Scene, RemovedImplicitIntegratorNamesItsReplacement) {
  const std::string error =
      error_of(R"({ "solver": { "integrator": "implicit", "dt": 0.01 }, "bodies": [ { "mesh": "icosphere:1" } ] })");
  EXPECT_NE(error.find("solver.integrator: \"implicit\" was removed: use \"vbd\""), std::string::npos) << error;
  EXPECT_NE(error.find("solver.substeps"), std::string::npos) << error;
}

}  // namespace
