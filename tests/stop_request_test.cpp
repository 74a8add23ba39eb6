// SIGINT / SIGTERM as real signals to real softbody processes: a frame far longer than any test waits still
// ends within one step (exit 128 + the signal, the frames complete before it kept, the one in progress
// dropped), and a long setup phase ends the run when it ends, with nothing written.
#include <signal.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

#include "background_run.hpp"
#include "mesh/generators.hpp"
#include "output/atomic_file.hpp"
#include "output/csv_sink.hpp"
#include "output/mesh_file_writer.hpp"
#include "test_helpers.hpp"

namespace {

namespace fs = std::filesystem;
using testing_support::BackgroundRun;
using testing_support::scratch_dir;

// Liveness bounds, not speed goals: the frames and phases below take many times longer than these (measured
// figures at each scene), so a stop that waits for them to end fails the test instead of hanging it.
constexpr auto kStartBound = std::chrono::seconds(60);  // until the run shows it is stepping
constexpr auto kStopBound = std::chrono::seconds(60);   // from the signal to the exit

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// One frame of a second on a 10,242-vertex ball (icosphere:5): at dt = 1.1e-6 s (rounded to 1/909,091 s, with
// a note that marks the end of setup) frame 1 is 909,091 euler steps, measured at 925 steps/s on the 2-core
// machine: 16 minutes; rk45 at a tolerance of 1e-12 takes about 51,000 steps at 90 steps/s for it: 9 minutes.
std::vector<std::string> one_long_frame(const std::string& integrator) {
  return {"scenes/bounce.json",
          "--set",
          "duration=1",
          "--set",
          "fps=1",
          "--set",
          "bodies.0.mesh=icosphere:5",
          "--set",
          "solver.integrator=" + integrator,
          "--set",
          "solver.dt=1.1e-6",
          "--set",
          "solver.tolerance=1e-12"};
}

// `command` SCENE ARGUMENTS... MORE...
std::vector<std::string> command_line(const std::string& command, const std::vector<std::string>& scene,
                                      const std::vector<std::string>& more) {
  std::vector<std::string> arguments{command};
  arguments.insert(arguments.end(), scene.begin(), scene.end());
  arguments.insert(arguments.end(), more.begin(), more.end());
  return arguments;
}

// The number N in "stopped after N complete frames" (-1: not there).
int complete_frames(const std::string& errors) {
  const std::size_t at = errors.find("stopped after ");
  return at == std::string::npos ? -1 : std::stoi(errors.substr(at + 14));
}

// Sends `signal` and waits for the exit: its status, or a failure if it still runs kStopBound later.
int stop(BackgroundRun& run, int signal, const std::string& what) {
  run.signal(signal);
  const std::optional<int> status = run.wait_for_exit(kStopBound);
  EXPECT_TRUE(status) << "still running " << kStopBound.count() << " s after the signal: " << run.errors();
  if (status) std::printf("[ measured ] %s: exit %.2f s after the signal\n", what.c_str(), run.seconds_to_exit());
  return status.value_or(-1);
}

// simulate --cache writes frame 0's state as soon as frame 0 is done: from then on the run steps frame 1.
// SIGTERM must end it within a step: exit 143, one complete frame, the CSV with frame 0's row only and the
// cache with frame 0's state only. rk45 is stopped inside its own step loop (sim::advance_to).
TEST(StopRequest, SigtermEndsSimulateWithinAStepNotAFrame) {
  for (const std::string integrator : {"euler", "rk45"}) {
    SCOPED_TRACE(integrator);
    const fs::path dir = scratch_dir("stop_simulate_" + integrator);
    BackgroundRun run(command_line("simulate", one_long_frame(integrator),
                                   {"--csv", (dir / "rows.csv").string(), "--cache", (dir / "cache").string()}),
                      dir);
    ASSERT_TRUE(run.wait_until([&] { return fs::exists(dir / "cache" / "state_000000.bin"); }, kStartBound))
        << run.errors();
    ASSERT_EQ(stop(run, SIGTERM, "simulate " + integrator), 143) << run.errors();
    EXPECT_NE(run.errors().find("interrupted: SIGTERM: stopped after 1 complete frames"), std::string::npos)
        << run.errors();
    std::istringstream csv(read_text(dir / "rows.csv"));
    std::string header, row, more;
    std::getline(csv, header);
    std::getline(csv, row);
    EXPECT_EQ(header, output::kCsvHeader);
    EXPECT_EQ(row.rfind("0,0,0,", 0), 0u) << "frame 0's row: " << row;
    EXPECT_FALSE(std::getline(csv, more)) << "a row of the frame in progress: " << more;
    EXPECT_FALSE(fs::exists(dir / "cache" / "state_000001.bin"));
  }
}

// export, meshes and point caches: frame 0 is written (the OBJ appears at once; the PC2 holds it at the end),
// frame 1 is dropped. The OBJ run is signalled once frame_0000.obj exists, the PC2 run once setup's note is out
// (frame 0 is always handed out before the loop looks at the request, so 1 complete frame either way).
TEST(StopRequest, SigtermEndsExportWithinAStepNotAFrame) {
  for (const std::string format : {"obj", "pc2"}) {
    SCOPED_TRACE(format);
    const fs::path dir = scratch_dir("stop_export_" + format);
    BackgroundRun run(
        command_line("export", one_long_frame("euler"), {"--format", format, "-o", (dir / "out").string()}), dir);
    const bool started =
        format == "obj" ? run.wait_until([&] { return fs::exists(dir / "out" / "frame_0000.obj"); }, kStartBound)
                        : run.wait_until([&] { return run.errors().find("note: ") != std::string::npos; }, kStartBound);
    ASSERT_TRUE(started) << run.errors();
    ASSERT_EQ(stop(run, SIGTERM, "export " + format), 143) << run.errors();
    EXPECT_EQ(complete_frames(run.errors()), 1) << run.errors();
    std::vector<std::string> files;
    for (const auto& entry : fs::directory_iterator(dir / "out")) files.push_back(entry.path().filename().string());
    std::sort(files.begin(), files.end());
    if (format == "obj") {
      EXPECT_EQ(files, std::vector<std::string>{"frame_0000.obj"});
    } else {
      ASSERT_EQ(files, (std::vector<std::string>{"body0.obj", "body0.pc2"}));
      const std::string cache = read_text(dir / "out" / "body0.pc2");
      ASSERT_GE(cache.size(), 32u);
      std::int32_t samples = 0;
      std::memcpy(&samples, cache.data() + 28, 4);  // PC2 header: the sample count at byte 28
      EXPECT_EQ(samples, 1);
    }
  }
}

// A long setup phase: a 10,242-vertex ball remeshed into a proxy of about 20,000 vertices takes 8 s of the
// 2-core machine (measured, simulate with duration 0.001). SIGINT 0.5 s in lands in setup (the remesh, unless
// the machine is slow enough to be still generating the ball): the run ends when that phase ends, with exit
// 130, the phase named, and no CSV; a run that missed the request would go on to simulate 10,000 s.
TEST(StopRequest, SigintDuringSetupEndsItAfterThePhaseAndWritesNothing) {
  const fs::path dir = scratch_dir("stop_setup");
  BackgroundRun run({"simulate", "scenes/bounce.json", "--set", "duration=10000", "--set", "bodies.0.mesh=icosphere:5",
                     "--set", "bodies.0.resolution=20000", "--csv", (dir / "rows.csv").string()},
                    dir);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  ASSERT_EQ(stop(run, SIGINT, "simulate setup"), 130) << run.errors();
  // The phase the signal came in, and not a later one: the remesh (or, on a slow start, generating the ball).
  const std::string after_remesh =
      "interrupted: SIGINT: stopped during setup, after remeshing bodies.0 into its "
      "simulation proxy; nothing was written";
  const std::string after_generating =
      "interrupted: SIGINT: stopped during setup, after generating icosphere:5; "
      "nothing was written";
  EXPECT_TRUE(run.errors().find(after_remesh) != std::string::npos ||
              run.errors().find(after_generating) != std::string::npos)
      << run.errors();
  EXPECT_FALSE(fs::exists(dir / "rows.csv"));
  for (const auto& entry : fs::directory_iterator(dir)) {
    EXPECT_EQ(entry.path().filename(), "stderr.txt") << "written: " << entry.path();
  }
}

// softbody prepare --resolution: SIGINT 0.5 s in, during the remesh (about 30,000 vertices from 10,242: 11 s
// measured), ends it after the phase in progress, exit 130, and OUT is never written (nor a temporary of it).
TEST(StopRequest, SigintDuringPrepareWritesNoOutput) {
  const fs::path dir = scratch_dir("stop_prepare");
  const fs::path in = dir / "ball.obj";
  output::write_file_atomically(in, output::trimesh_to_obj(mesh::icosphere(5), "icosphere:5"));
  BackgroundRun run({"prepare", in.string(), (dir / "prepared.obj").string(), "--resolution", "30000"}, dir);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  ASSERT_EQ(stop(run, SIGINT, "prepare"), 130) << run.errors();
  EXPECT_NE(run.errors().find("interrupted: SIGINT: stopped during setup, after "), std::string::npos) << run.errors();
  EXPECT_NE(run.errors().find("; nothing was written"), std::string::npos) << run.errors();
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    EXPECT_TRUE(name == "ball.obj" || name == "stderr.txt") << "written: " << name;
  }
}

}  // namespace
