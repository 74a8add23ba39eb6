// The command line: exit statuses and one clear line per bad input, CSV contract.
#include <fstream>
#include <iterator>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "output/csv_sink.hpp"
#include "test_helpers.hpp"

namespace {

using testing_support::run_softbody;

TEST(Cli, HelpExplainsCommandsAndExitStatuses) {
  const auto top = run_softbody("--help");
  EXPECT_EQ(top.exit_status, 0);
  EXPECT_NE(top.output.find("simulate"), std::string::npos);
  EXPECT_NE(top.output.find("3 the simulation diverged"), std::string::npos);
  const auto simulate = run_softbody("simulate --help");
  EXPECT_EQ(simulate.exit_status, 0);
  EXPECT_NE(simulate.output.find("--csv"), std::string::npos);
  EXPECT_NE(simulate.output.find("--set"), std::string::npos);
}

// --version: the version, the commit the program was built from (12 hex digits, "+changes" for a changed work
// tree, "unknown" outside git) and the licence that LICENSE holds.
TEST(Cli, VersionNamesCommitAndLicence) {
  const auto result = run_softbody("--version");
  EXPECT_EQ(result.exit_status, 0);
  EXPECT_EQ(result.output.rfind("softbody 0.", 0), 0u) << result.output;
  const std::regex commit(R"(\(commit ([0-9a-f]{12}(\+changes)?|unknown), build [0-9a-f]{16}\))");
  EXPECT_TRUE(std::regex_search(result.output, commit)) << result.output;
  EXPECT_NE(result.output.find("GPL-3.0-or-later"), std::string::npos) << result.output;
  std::ifstream licence(std::string(SOFTBODY_SOURCE_DIR) + "/LICENSE");
  std::string first_line;
  std::getline(licence, first_line);
  EXPECT_NE(first_line.find("GNU GENERAL PUBLIC LICENSE"), std::string::npos) << first_line;
}

TEST(Cli, UnknownFlagAndMissingSceneAreBadInput) {
  EXPECT_EQ(run_softbody("simulate scenes/bounce.json --frobnicate").exit_status, 2);
  EXPECT_EQ(run_softbody("simulate").exit_status, 2);
  EXPECT_EQ(run_softbody("").exit_status, 2);
}

struct CliCase {
  const char* arguments;
  const char* message;
};

class CliBadInput : public ::testing::TestWithParam<CliCase> {};

// Each bad input: exit status 2 and a single "error:" line naming file, key and expectation.
TEST_P(CliBadInput, ExitsTwoWithOneClearLine) {
  const auto result =
      run_softbody(std::string("simulate ") + GetParam().arguments + " --csv build/cli_test_should_not_exist.csv");
  EXPECT_EQ(result.exit_status, 2) << result.output;
  EXPECT_EQ(result.output.rfind("error: ", 0), 0u) << result.output;
  EXPECT_EQ(std::count(result.output.begin(), result.output.end(), '\n'), 1) << result.output;
  EXPECT_NE(result.output.find(GetParam().message), std::string::npos) << result.output;
  EXPECT_FALSE(std::ifstream("build/cli_test_should_not_exist.csv").good()) << "no output file on bad input";
}

INSTANTIATE_TEST_SUITE_P(
    Cli, CliBadInput,
    ::testing::Values(
        CliCase{"scenes/no_such_scene.json", "scenes/no_such_scene.json: cannot open the scene file"},
        CliCase{"scenes/bounce.json --set bodies.0.stifness=3", "scenes/bounce.json: bodies.0.stifness: unknown key"},
        CliCase{"scenes/bounce.json --set bodies.0.mass=-1",
                "scenes/bounce.json: bodies.0.mass: expected a finite number > 0"},
        CliCase{"scenes/bounce.json --set solver.dt=0", "scenes/bounce.json: solver.dt: expected a finite number > 0"},
        CliCase{"scenes/bounce.json --set fps=0", "scenes/bounce.json: fps: expected an integer in 1..1000"},
        CliCase{"scenes/bounce.json --set bodies.0.damping=NaN",
                "bodies.0.damping: expected a number >= 0, got string \"NaN\""},
        CliCase{"scenes/bounce.json --set bodies.0.mesh=nowhere.obj",
                "bodies.0.mesh: mesh file scenes/nowhere.obj does not exist"},
        CliCase{"scenes/bounce.json --set bodies.0.mesh=../tests/data/open_box.obj", "is not closed: 4 boundary edges"},
        CliCase{"scenes/bounce.json --set bodies.0.mesh=../tests/data/flipped_face.obj", "inconsistent winding"},
        CliCase{"scenes/bounce.json --set bodies.0.mesh=../tests/data/degenerate_face.obj", "is degenerate"},
        CliCase{"scenes/bounce.json --set bodies.0=3", "bodies.0: expected an object"}),
    [](const auto& param) { return "case" + std::to_string(param.index); });

// Runs `simulate ARGUMENTS`, expects it to diverge (exit 3) and returns its output.
std::string diverged_output(const std::string& arguments) {
  const auto result = run_softbody("simulate " + arguments);
  EXPECT_EQ(result.exit_status, 3) << result.output;
  return result.output;
}

// Runs `simulate ARGUMENTS --csv ...`, expects it to succeed with an output that `pattern` matches; returns the
// pattern's groups (empty where it did not match).
std::vector<std::string> simulate_and_match(const std::string& arguments, const std::string& pattern) {
  const auto result = run_softbody("simulate " + arguments + " --csv build/cli_test_matched.csv");
  EXPECT_EQ(result.exit_status, 0) << result.output;
  std::smatch match;
  if (!std::regex_search(result.output, match, std::regex(pattern))) {
    ADD_FAILURE() << "no match for " << pattern << " in " << result.output;
    return {};
  }
  return std::vector<std::string>(match.begin() + 1, match.end());
}

// vbd's start (steps of dt/16 doubling back) and its impacts (steps of 0.52 ms here) take steps within the driver's:
// the summary counts them beside the frame steps, the only figure it gave before.
TEST(Cli, SimulateCountsVbdsOwnSteps) {
  const auto own =
      simulate_and_match("scenes/bounce_smooth.json --set solver.integrator=vbd --set duration=1.2",
                         R"(36 steps of 0.03333 s \(vbd; (\d+) of its own: shorter at its start and around impacts\))");
  ASSERT_EQ(own.size(), 1u);
  // The impact alone takes more than a hundred 0.52 ms steps (about 0.1 s of it).
  EXPECT_GT(std::stoi(own[0]), 136);
  // At full steps throughout (the breathing's start, docs/physics/integrators.md) only the frame steps are counted.
  const auto breathing = run_softbody(
      "simulate scenes/breathing.json --set solver.integrator=vbd --set solver.substeps=auto --set duration=0.5 --csv "
      "build/cli_test_vbd_steps.csv");
  ASSERT_EQ(breathing.exit_status, 0) << breathing.output;
  EXPECT_NE(breathing.output.find("15 steps of 0.03333 s (vbd), "), std::string::npos) << breathing.output;
}

// With "iterations": "converge" the summary gives the sweeps per step the run took: on the bounce's smooth flight and
// impact of icosphere:3 fewer than the default 4 (2.59 on this machine), never fewer than 2. With "auto" it also says
// that vbd's own steps follow the volume's error.
TEST(Cli, SimulateCountsVbdsSweepsUntilConverged) {
  struct Case {
    const char* iterations;
    const char* summary;  // the run's summary line, its sweeps per step captured
    double fewer_than;    // sweeps per step
  };
  const Case cases[] = {
      {"converge",
       R"(36 steps of 0.03333 s \(vbd; \d+ of its own: shorter at its start and around impacts; ([0-9.]+) sweeps per )"
       R"(step \(converge\)\))",
       4.0},
      {"auto",
       R"(36 steps of 0.03333 s \(vbd; \d+ of its own: shorter at its start, around impacts and where the volume's )"
       R"(error needed it; ([0-9.]+) sweeps per step \(auto\)\))",
       32.5}};  // at most 32 per step
  for (const Case& c : cases) {
    const auto sweeps = simulate_and_match(
        std::string(
            "scenes/bounce_smooth.json --set solver.integrator=vbd --set duration=1.2 --set solver.iterations=") +
            c.iterations,
        c.summary);
    ASSERT_EQ(sweeps.size(), 1u) << c.iterations;
    EXPECT_GE(std::stod(sweeps[0]), 2.0) << c.iterations;
    EXPECT_LT(std::stod(sweeps[0]), c.fewer_than) << c.iterations;
  }
}

// Runs `simulate` with `changed` and with `shipped` (the same scene as it ships): the first run's output holds `note`,
// the second's holds no `mark` (the note's wording).
void expect_noted_only_when_changed(const std::string& changed, const std::string& shipped, const std::string& note,
                                    const std::string& mark) {
  const auto with = run_softbody("simulate " + changed + " --csv build/cli_test_noted.csv");
  ASSERT_EQ(with.exit_status, 0) << with.output;
  EXPECT_NE(with.output.find(note), std::string::npos) << with.output;
  const auto without = run_softbody("simulate " + shipped + " --csv build/cli_test_noted.csv");
  ASSERT_EQ(without.exit_status, 0) << without.output;
  EXPECT_EQ(without.output.find(mark), std::string::npos) << without.output;
}

// scenes/colliders.json (a friction floor: a projection after the step) at one vbd step per frame diverged after
// 1.1 s, its ball crushed, with nothing said beforehand; the steps are kept, and a note says what the contact needs.
TEST(Cli, SubstepsLongerThanTheContactTravelLimitAreNoted) {
  expect_noted_only_when_changed(
      "scenes/colliders.json --set solver.substeps=1 --set duration=0.04", "scenes/colliders.json --set duration=0.04",
      "note: solver.substeps = 1: steps of 0.03333 s, longer than the contact travel limit 0.0005006 s (a tenth of the "
      "shortest edge per step) that a contact after the step needs",
      "longer than the contact travel limit");
  // Run on, it diverges, and the message names the limit instead of only "estimated stable: any dt for vbd".
  EXPECT_NE(diverged_output("scenes/colliders.json --set solver.substeps=1 --set duration=2 --csv "
                            "build/cli_test_noted.csv")
                .find("estimated stable: any dt for vbd; its given substeps are longer than the contact travel limit "
                      "dt <= 0.000501 s that a contact after the step needs"),
            std::string::npos);
}

// A solver key the scene's integrator does not read is said as a note (it was silently ignored): not an error, as a
// scene may carry several integrators' keys for --set to switch between.
TEST(Cli, SolverKeysTheIntegratorDoesNotReadAreNoted) {
  const auto result = run_softbody(
      "simulate scenes/bounce_smooth.json --set duration=0.1 --set solver.substeps=8 --set solver.iterations=3 "
      "--set solver.impact_phase=1 --csv build/cli_test_unused_keys.csv");
  ASSERT_EQ(result.exit_status, 0) << result.output;
  EXPECT_NE(result.output.find("note: scenes/bounce_smooth.json: solver.substeps is not used by rk4 (only by xpbd and "
                               "vbd)"),
            std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("solver.iterations is not used by rk4 (only by vbd)"), std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("solver.impact_phase is not used by rk4 (only by vbd)"), std::string::npos)
      << result.output;
  const auto vbd = run_softbody(
      "simulate scenes/bounce_smooth.json --set duration=0.1 --set solver.integrator=vbd --set solver.substeps=2 "
      "--set solver.iterations=3 --csv build/cli_test_unused_keys.csv");
  ASSERT_EQ(vbd.exit_status, 0) << vbd.output;
  EXPECT_EQ(vbd.output.find("is not used"), std::string::npos) << vbd.output;
}

// A body partly in the floor runs, with a note: the contact pushes it out (one under the floor is refused:
// tests/hostile_scene_test.cpp).
TEST(Cli, ABodyStartingPartlyInTheFloorIsNoted) {
  expect_noted_only_when_changed("scenes/bounce.json --set floor.height=2.5 --set duration=0.1",
                                 "scenes/bounce.json --set duration=0.1",
                                 "note: scenes/bounce.json: bodies.0 starts 0.5 m into the floor (its lowest vertex at "
                                 "y = 2 m, the floor at 2.5 m): the contact pushes it out in the first steps",
                                 "into the floor");
}

// scenes/pile.json with its second pillow moved into the first: they rose together, tangled, with no word of why.
// Now a note before the run; the pile as shipped has none.
TEST(Cli, BodiesStartingInsideEachOtherAreNoted) {
  const auto shares = simulate_and_match(
      "scenes/pile.json --set 'bodies.1.position=[0.05,1.0,0.02]' --set duration=0.04",
      R"(note: scenes/pile.json: bodies.0 and bodies.1 start inside each other \(about ([0-9.]+) % of the )"
      R"(first's vertices inside the second, ([0-9.]+) % of the second's inside the first\))");
  ASSERT_EQ(shares.size(), 2u);
  EXPECT_GT(std::stod(shares[0]), 5.0);
  EXPECT_GT(std::stod(shares[1]), 5.0);
  const auto pile = run_softbody("simulate scenes/pile.json --set duration=0.04 --csv build/cli_test_overlap.csv");
  ASSERT_EQ(pile.exit_status, 0) << pile.output;
  EXPECT_EQ(pile.output.find("inside each other"), std::string::npos) << pile.output;
}

// scenes/colliders.json's ball placed at the centre of its sphere collider stayed there, held against the
// collider's inside, without a word; now a note. The scene as shipped has none.
TEST(Cli, ABodyStartingInsideAColliderIsNoted) {
  expect_noted_only_when_changed(
      "scenes/colliders.json --set 'bodies.0.position=[-1.55,2.1,0]' --set duration=0.04",
      "scenes/colliders.json --set duration=0.04",
      "note: scenes/colliders.json: bodies.0 starts inside colliders.0 (642 of its 642 vertices)", "starts inside");
}

TEST(Cli, SimulateWritesTheContractColumns) {
  const auto result = run_softbody("simulate scenes/bounce.json --set duration=0.1 --csv build/cli_test_bounce.csv");
  ASSERT_EQ(result.exit_status, 0) << result.output;
  EXPECT_NE(result.output.find("steps/s"), std::string::npos) << result.output;
  std::ifstream csv(std::string(SOFTBODY_SOURCE_DIR) + "/build/cli_test_bounce.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "frame,time,body,com_x,com_y,com_z,vel_x,vel_y,vel_z,volume,kinetic_energy,total_energy,min_y");
  int rows = 0;
  for (std::string line; std::getline(csv, line);) ++rows;
  EXPECT_EQ(rows, 4) << "frames 0..3 at 30 fps over 0.1 s";
}

TEST(Cli, InfoExpectsACostPerSimulatedSecondForEachIntegrator) {
  const auto result = run_softbody("info scenes/bounce.json");
  ASSERT_EQ(result.exit_status, 0) << result.output;
  // steps per simulated second x vertices x the measured ns per vertex step: symplectic at its auto dt on
  // the bounce ball (4 kg) takes 68 steps a frame, 2040 a second, x 642 vertices x 26 ns = 0.0341 s.
  EXPECT_NE(result.output.find("68                     about 0.0341 s"), std::string::npos) << result.output;
  for (const char* integrator : {"euler", "verlet", "rk4", "rk45", "xpbd"}) {
    const std::size_t line = result.output.find(std::string("\n  ") + integrator + " ");
    ASSERT_NE(line, std::string::npos) << integrator;
    const std::string text = result.output.substr(line + 1, result.output.find('\n', line + 1) - line - 1);
    EXPECT_NE(text.find(" about "), std::string::npos) << text;
  }
}

// vbd's line: on the smooth floor one step per 1/30 s frame in flight, priced as steps x sweeps x vertices x 155 ns
// (30 x 4 x 642 x 155 ns = 0.0119 s), and the impacts' steps, the frame halved until ω h ≤ solver.impact_phase
// (0.5 / (1/2 ms) = 1 ms: 1/30 s / 64 = 0.52 ms), priced per 0.1 s of impact (192 x 4 x 642 x 155 ns = 0.0764 s)
// and per impact of the ball's gas.
TEST(Cli, InfoPricesVbdInFlightAndNamesItsImpactSteps) {
  const auto result = run_softbody("info scenes/bounce_smooth.json --set solver.integrator=vbd");
  ASSERT_EQ(result.exit_status, 0) << result.output;
  const std::size_t line = result.output.find("\n  vbd ");
  ASSERT_NE(line, std::string::npos) << result.output;
  const std::string text = result.output.substr(line + 1, result.output.find('\n', line + 1) - line - 1);
  EXPECT_NE(text.find("no limit"), std::string::npos) << text;
  EXPECT_NE(text.find("1 step "), std::string::npos) << text;
  EXPECT_NE(text.find("about 0.0119 s in flight"), std::string::npos) << text;
  EXPECT_NE(text.find("impacts take steps of 0.52 ms while they last, about 0.0764 s per 0.1 s of impact"),
            std::string::npos)
      << text;
  // The ball's impact, estimated from its gas (sim::gas_impact_duration: 0.181 s), at those steps: 347 x 4 x 642 x
  // 155 ns = 0.138 s.
  EXPECT_NE(text.find("body 0's impacts last about 0.18 s (its gas: pi sqrt(m / (2 pi R P))), about 0.138 s each"),
            std::string::npos)
      << text;
  EXPECT_EQ(result.output.find("damp body"), std::string::npos) << "the bounce's dampers take its breathing out";
  EXPECT_EQ(result.output.find("starts at its full step"), std::string::npos) << "so its start follows the first swing";
}

// With "iterations": "auto", simulate says where vbd's steps damp out a breathing that the model keeps ringing
// (scenes/breathing.json, damping ratio 0.0015, at one step per frame), which "auto" cannot follow (3.5 % off over its
// 2 s); not on the bounce, whose dampers take the breathing out themselves.
TEST(Cli, SimulateSaysWhereVbdsAutoDampsABreathingOut) {
  const auto ringing = run_softbody(
      "simulate scenes/breathing.json --set solver.integrator=vbd --set solver.iterations=auto --set "
      "solver.substeps=auto "
      "--set duration=0.1 --csv build/cli_test_vbd_auto_breathing.csv");
  ASSERT_EQ(ringing.exit_status, 0) << ringing.output;
  EXPECT_NE(ringing.output.find("note: solver.iterations = auto: vbd's steps of "), std::string::npos)
      << ringing.output;
  EXPECT_NE(ringing.output.find("damp body 0's breathing out"), std::string::npos) << ringing.output;
  const auto bounce = run_softbody(
      "simulate scenes/bounce_smooth.json --set solver.integrator=vbd --set solver.iterations=auto --set duration=0.1 "
      "--csv build/cli_test_vbd_auto_bounce.csv");
  ASSERT_EQ(bounce.exit_status, 0) << bounce.output;
  EXPECT_EQ(bounce.output.find("breathing out"), std::string::npos) << bounce.output;
}

// With "iterations": "auto" the same range, and the line after says that its steps shorten where the volume needs it
// and, where solver.impact_phase is not given, which impact steps it takes.
TEST(Cli, InfoSaysVbdsAutoHoldsItsOwnError) {
  const auto result =
      run_softbody("info scenes/bounce_smooth.json --set solver.integrator=vbd --set solver.iterations=auto");
  ASSERT_EQ(result.exit_status, 0) << result.output;
  EXPECT_NE(result.output.find("(30 steps/s x 2 to 32 sweeps (auto) x 642 vertices x 155 ns)"), std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("vbd holds its own error (\"iterations\": \"auto\"): its impacts' steps keep omega h <= "
                               "0.25 (solver.impact_phase is not given: 0.5 without \"auto\"), and its steps shorten "
                               "further"),
            std::string::npos)
      << result.output;
  // Its impacts' steps: ω h ≤ 0.25 at ω = 1/(2 ms), 1/30 s / 128 = 0.26 ms.
  EXPECT_NE(result.output.find("impacts take steps of 0.26 ms while they last"), std::string::npos) << result.output;
  // A phase given is the user's, and the line does not claim one.
  const auto given = run_softbody(
      "info scenes/bounce_smooth.json --set solver.integrator=vbd --set solver.iterations=auto --set "
      "solver.impact_phase=0.5");
  ASSERT_EQ(given.exit_status, 0) << given.output;
  EXPECT_NE(given.output.find("impacts take steps of 0.52 ms while they last"), std::string::npos) << given.output;
  EXPECT_NE(given.output.find("vbd holds its own error (\"iterations\": \"auto\"): its steps shorten further"),
            std::string::npos)
      << given.output;
}

// With "iterations": "converge" the sweeps per step range from 2 to 32, and so does the price: 30 x 2 x 642 x 155 ns =
// 0.00597 s to 30 x 32 x 642 x 155 ns = 0.0955 s in flight.
TEST(Cli, InfoPricesVbdsSweepsUntilConvergedAsARange) {
  const auto result =
      run_softbody("info scenes/bounce_smooth.json --set solver.integrator=vbd --set solver.iterations=converge");
  ASSERT_EQ(result.exit_status, 0) << result.output;
  EXPECT_NE(result.output.find("about 0.00597 to 0.0955 s in flight (30 steps/s x 2 to 32 sweeps (converge) x 642 "
                               "vertices x 155 ns)"),
            std::string::npos)
      << result.output;
}

// scenes/breathing.json's dampers (c = 0.01) leave its breathing ringing for seconds (ζ = 0.0015 at 148 rad/s), which
// BDF2 at one step per frame (ω h = 4.9) damps at a ratio of 0.15: info prints the mode and says so.
TEST(Cli, InfoWarnsWhereVbdsStepsDampABreathingTheModelKeeps) {
  const auto result = run_softbody("info scenes/breathing.json --set solver.integrator=vbd");
  ASSERT_EQ(result.exit_status, 0) << result.output;
  EXPECT_NE(result.output.find("breathing mode (the whole body swelling) 148 rad/s"), std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("vbd's steps of 0.0333 s damp body 0's breathing at a ratio of 0.15"), std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("take rk4 or rk45"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("so at these steps vbd starts at its full step"), std::string::npos) << result.output;
}

// Without a floor, a collider or contact between bodies no contact travel limit bounds the automatic steps: the note
// says so instead of naming a limit of "inf s".
TEST(Cli, AutoSubstepsWithoutContactNameNoTravelLimit) {
  const struct {
    const char* integrator;
    const char* note;
  } cases[] = {{"vbd", "solver.substeps = auto: 1 step per frame (h = 0.03333 s; no contact in the scene limits it)"},
               {"xpbd",
                "substeps per frame (h = 0.002564 s: within the carried form's limit; no contact in the scene limits "
                "it)"}};
  for (const auto& c : cases) {
    const auto info = run_softbody(std::string("info scenes/breathing.json --set solver.integrator=") + c.integrator +
                                   " --set solver.substeps=auto");
    ASSERT_EQ(info.exit_status, 0) << info.output;
    EXPECT_NE(info.output.find(c.note), std::string::npos) << info.output;
    EXPECT_EQ(info.output.find("inf s"), std::string::npos) << info.output;
    if (std::string(c.integrator) == "vbd") {
      EXPECT_NE(info.output.find("this scene: vbd, dt = 0.03333 s (1 step per frame)"), std::string::npos)
          << info.output;
    }
  }
}

TEST(Cli, DivergedRunExitsThreeAndKeepsFramesBefore) {
  // Far beyond forward Euler's stable step for this stiffness: blows up within a few frames.
  const std::string output = diverged_output(
      "scenes/bounce.json --set bodies.0.stiffness=1e6 --set solver.dt=1e-3 --csv build/cli_test_diverged.csv");
  EXPECT_NE(output.find("diverged"), std::string::npos) << output;
  std::ifstream csv(std::string(SOFTBODY_SOURCE_DIR) + "/build/cli_test_diverged.csv");
  ASSERT_TRUE(csv.good());
  std::string line, last;
  while (std::getline(csv, line)) last = line;
  EXPECT_EQ(last.find("nan"), std::string::npos) << "no frame of a diverged state: " << last;
  EXPECT_EQ(last.find("inf"), std::string::npos) << last;
}

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// --profile prints the time of each phase that ran and changes nothing in the results.
TEST(Cli, ProfilePrintsThePhasesThatRanAndLeavesTheCsvAlone) {
  const std::filesystem::path dir = testing_support::scratch_dir("cli_profile");
  const std::string plain = (dir / "plain.csv").string(), profiled = (dir / "profiled.csv").string();
  const auto without = run_softbody("simulate scenes/bounce.json --set duration=0.2 --csv " + plain);
  const auto with = run_softbody("simulate scenes/bounce.json --set duration=0.2 --profile --csv " + profiled);
  ASSERT_EQ(without.exit_status, 0) << without.output;
  ASSERT_EQ(with.exit_status, 0) << with.output;
  EXPECT_EQ(without.output.find("profile:"), std::string::npos) << without.output;
  EXPECT_NE(with.output.find("profile:"), std::string::npos) << with.output;
  // The bounce: one body with gas on the paper's floor, forward Euler (no constraint sweeps, no body contact).
  for (const char* phase : {"\nsetup ", "\nstep ", "\n  integrate ", "\n    forces ", "\n    gas ",
                            "\n  floor contact ", "\n  guard ", "\nframe guard ", "\ncsv write "}) {
    EXPECT_NE(with.output.find(phase), std::string::npos) << phase << " in\n" << with.output;
  }
  for (const char* phase : {"\n    constraint sweeps ", "\n  body contact ", "\nrender "}) {
    EXPECT_EQ(with.output.find(phase), std::string::npos) << phase << " in\n" << with.output;
  }
  const std::string bytes = file_bytes(plain);
  EXPECT_NE(bytes.find("\n6,0.2"), std::string::npos) << "frames 0..6 at 30 fps";
  EXPECT_EQ(bytes, file_bytes(profiled));
}

TEST(Cli, ProfileIsPrintedWhenTheRunDiverges) {
  const std::filesystem::path dir = testing_support::scratch_dir("cli_profile_diverged");
  const auto result =
      run_softbody("simulate scenes/bounce.json --set bodies.0.stiffness=1e6 --set solver.dt=1e-3 --profile --csv " +
                   (dir / "diverged.csv").string());
  EXPECT_EQ(result.exit_status, 3) << result.output;
  EXPECT_NE(result.output.find("profile:"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("\n  guard "), std::string::npos) << result.output;
}

// An output path that is one of the run's inputs (the scene file, a mesh file, by inode: a hard link too) is
// refused before anything is written, and the input is left as it was.
TEST(Cli, OutputsThatAreTheRunsInputsAreRefused) {
  namespace fs = std::filesystem;
  const fs::path dir = testing_support::scratch_dir("cli_outputs_onto_inputs");
  fs::copy_file(std::string(SOFTBODY_SOURCE_DIR) + "/tests/data/cube_quads.obj", dir / "cube.obj");
  fs::copy_file(dir / "cube.obj", dir / "frame_0002.obj");  // what `export` names its frame 2
  {
    std::ofstream scene(dir / "s.json");
    scene << R"({"duration": 0.1, "bodies": [ { "mesh": "cube.obj" } ]})";
  }
  fs::create_hard_link(dir / "s.json", dir / "link.json");
  const std::string scene_text = file_bytes((dir / "s.json").string());
  const std::string mesh_text = file_bytes((dir / "cube.obj").string());
  const std::string scene = (dir / "s.json").string();
  const struct {
    std::string arguments, message;
  } cases[] = {
      {"simulate " + scene + " --csv " + scene, "--csv " + scene + ": is the scene file (" + scene + ")"},
      {"simulate " + scene + " --csv " + (dir / "link.json").string(), ": is the scene file"},
      {"simulate " + scene + " --csv " + (dir / "cube.obj").string(), ": is the mesh file of bodies.0"},
      {"export " + scene + " -o " + dir.string() + " --set bodies.0.mesh=frame_0002.obj",
       "-o " + (dir / "frame_0002.obj").string() + ": is the mesh file of bodies.0"},
  };
  for (const auto& c : cases) {
    const auto result = run_softbody(c.arguments);
    EXPECT_EQ(result.exit_status, 2) << c.arguments << ": " << result.output;
    const std::size_t error = result.output.find("error: ");  // after the mesh's notes (its quads triangulated)
    ASSERT_NE(error, std::string::npos) << result.output;
    EXPECT_EQ(result.output.find('\n', error), result.output.size() - 1) << result.output;
    EXPECT_NE(result.output.find(c.message, error), std::string::npos) << result.output;
  }
  EXPECT_EQ(file_bytes(scene), scene_text);
  EXPECT_EQ(file_bytes((dir / "cube.obj").string()), mesh_text);
  EXPECT_EQ(file_bytes((dir / "frame_0002.obj").string()), mesh_text);
  EXPECT_FALSE(fs::exists(dir / "frame_0000.obj"));
}

}  // namespace
