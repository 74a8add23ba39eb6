// Outputs under hostile conditions: devices, FIFOs and standard output written through (never replaced),
// temporaries of killed runs removed, no mix of two runs' frames, SIGINT / SIGTERM keeping every complete
// frame (the CSV's rows included) with exit 128 + the signal.
#include <signal.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

#include "background_run.hpp"
#include "core/errors.hpp"
#include "output/atomic_file.hpp"
#include "output/csv_sink.hpp"
#include "output/folder_lock.hpp"
#include "output/frame_pattern.hpp"
#include "test_helpers.hpp"

namespace {

namespace fs = std::filesystem;
using testing_support::run_shell;
using testing_support::run_softbody;
using testing_support::scratch_dir;

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// A process id that no process has now: a child that has exited and been reaped.
pid_t dead_pid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ::waitpid(child, nullptr, 0);
  return child;
}

// Whether a lock's or a temporary's process still runs: this one does, a sleeping child does until it is killed, and
// a child that ended does not, reaped or not (a zombie). (A process in its exit, PF_EXITING, is too brief to catch.)
TEST(OutputSafety, ProcessRunsOnlyWhileTheProcessHasNotEnded) {
  EXPECT_TRUE(output::process_runs(::getpid()));
  const pid_t sleeper = ::fork();
  ASSERT_GE(sleeper, 0);
  if (sleeper == 0) {
    ::pause();
    ::_exit(0);
  }
  EXPECT_TRUE(output::process_runs(sleeper));
  ::kill(sleeper, SIGKILL);
  bool ended = false;
  for (int k = 0; k < 500 && !ended; ++k) {  // a zombie until reaped below
    ended = !output::process_runs(sleeper);
    if (!ended) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  EXPECT_TRUE(ended) << "a killed child must not count as running before it is reaped";
  int status = 0;
  ::waitpid(sleeper, &status, 0);
  EXPECT_FALSE(output::process_runs(sleeper));
}

TEST(OutputSafety, DevicesAreWrittenThroughNotReplaced) {
  output::write_file_atomically("/dev/null", "rows\n");
  struct stat info {};
  ASSERT_EQ(::stat("/dev/null", &info), 0);
  EXPECT_TRUE(S_ISCHR(info.st_mode)) << "/dev/null must stay a character device";
}

TEST(OutputSafety, FifosAreWrittenThroughNotReplaced) {
  const fs::path fifo = scratch_dir("fifo_output") / "rows.csv";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] { received = read_text(fifo); });
  output::write_file_atomically(fifo, "frame,time\n0,0\n");
  reader.join();
  EXPECT_EQ(received, "frame,time\n0,0\n");
  EXPECT_TRUE(fs::is_fifo(fifo)) << "the FIFO must not be replaced by a regular file";
}

TEST(OutputSafety, CsvDashGoesToStandardOutput) {
  const auto result = run_shell("(cd " SOFTBODY_SOURCE_DIR " && " SOFTBODY_EXE
                                " simulate scenes/bounce.json --set duration=0.1 --csv - 2>/dev/null)");
  EXPECT_EQ(result.exit_status, 0) << result.output;
  EXPECT_EQ(result.output.rfind(std::string(output::kCsvHeader) + "\n", 0), 0u) << result.output.substr(0, 200);
  EXPECT_EQ(std::count(result.output.begin(), result.output.end(), '\n'), 1 + 4) << "header and frames 0..3";
  EXPECT_FALSE(fs::exists(fs::path(SOFTBODY_SOURCE_DIR) / "-"));
}

// Whether process `pid`'s main thread is inside open() or openat() (a FIFO's open waits there for a reader).
bool opening_a_file(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/syscall");
  long number = -1;
  in >> number;
#ifdef SYS_open
  if (number == SYS_open) return true;
#endif
  return number == SYS_openat;
}

// A CSV FIFO that no process reads: SIGTERM while simulate waits to open it, or during the run (after which it
// does not wait at all), ends the run with the stop request's status, 143, naming the FIFO, which stays a FIFO.
TEST(OutputSafety, SigtermWhileACsvFifoHasNoReaderExits143) {
  const fs::path dir = scratch_dir("csv_fifo_sigterm");
  const fs::path fifo = dir / "rows.csv";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::string words = "interrupted: SIGTERM: stopped while " + fifo.string() +
                            " (a FIFO or device) waited for its reader; it was not written whole";
  {
    testing_support::BackgroundRun run(
        {"simulate", "scenes/bounce.json", "--set", "duration=0.1", "--csv", fifo.string()}, dir);
    // Still opening 200 ms later: the FIFO, not a file read during setup.
    const auto waiting_for_a_reader = [&] {
      if (!opening_a_file(run.pid())) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(200));
      return opening_a_file(run.pid());
    };
    ASSERT_TRUE(run.wait_until(waiting_for_a_reader, std::chrono::seconds(60))) << run.errors();
    run.signal(SIGTERM);
    EXPECT_EQ(run.wait_for_exit(std::chrono::seconds(20)), std::optional<int>(143)) << run.errors();
    EXPECT_NE(run.errors().find(words), std::string::npos) << run.errors();
  }
  {
    testing_support::BackgroundRun run(
        {"simulate", "scenes/bounce.json", "--set", "duration=10000", "--csv", fifo.string()}, dir);
    std::this_thread::sleep_for(std::chrono::milliseconds(3000));
    run.signal(SIGTERM);
    EXPECT_EQ(run.wait_for_exit(std::chrono::seconds(20)), std::optional<int>(143)) << run.errors();
    EXPECT_NE(run.errors().find(words), std::string::npos) << run.errors();
  }
  EXPECT_TRUE(fs::is_fifo(fifo));
}

// `--csv - | head -c 100`: like other Unix tools, simulate ends by SIGPIPE when its reader has gone, silently
// (a shell reports 141); where SIGPIPE is ignored, the write fails with one line and exit status 1.
TEST(OutputSafety, CsvToAPipeWhoseReaderLeftEndsLikeAUnixTool) {
  const fs::path dir = scratch_dir("csv_sigpipe");
  const std::string simulate = "cd " SOFTBODY_SOURCE_DIR " && " SOFTBODY_EXE
                               " simulate scenes/bounce.json --set fps=1000 --set duration=1 --set "
                               "bodies.0.mesh=icosphere:1 --csv - 2>" +
                               (dir / "errors.txt").string() + " | head -c 100 >/dev/null; echo ${PIPESTATUS[0]}";
  struct sigaction before {};
  struct sigaction action {};
  action.sa_handler = SIG_DFL;
  sigemptyset(&action.sa_mask);
  ASSERT_EQ(::sigaction(SIGPIPE, &action, &before), 0);  // what a shell gives the programs it starts
  const auto killed = run_shell("bash -c '" + simulate + "'");
  EXPECT_EQ(killed.output, "141\n");
  EXPECT_EQ(read_text(dir / "errors.txt"), "");
  action.sa_handler = SIG_IGN;  // inherited by the shell and softbody
  ASSERT_EQ(::sigaction(SIGPIPE, &action, nullptr), 0);
  const auto failed = run_shell("bash -c '" + simulate + "'");
  ASSERT_EQ(::sigaction(SIGPIPE, &before, nullptr), 0);
  EXPECT_EQ(failed.output, "1\n");
  EXPECT_EQ(read_text(dir / "errors.txt"), "error: standard output: write failed (Broken pipe)\n");
}

TEST(OutputSafety, StaleTemporariesOfKilledRunsAreRemovedByTheNextRun) {
  const fs::path dir = scratch_dir("stale_temporaries");
  const pid_t dead = dead_pid();
  const fs::path stale_csv = dir / (".simulation.csv.tmp" + std::to_string(dead));
  const fs::path stale_mesh = dir / "meshes" / (".frame_0001.obj.tmp" + std::to_string(dead));
  const fs::path live = dir / (".simulation.csv.tmp" + std::to_string(::getpid()));  // this process runs
  fs::create_directories(dir / "meshes");
  for (const fs::path& p : {stale_csv, stale_mesh, live}) std::ofstream(p) << "half a file";
  const std::string quick = " --set duration=0.1 ";
  EXPECT_EQ(
      run_softbody("simulate scenes/bounce.json" + quick + "--csv " + (dir / "simulation.csv").string()).exit_status,
      0);
  EXPECT_EQ(run_softbody("export scenes/bounce.json" + quick + "-o " + (dir / "meshes").string()).exit_status, 0);
  EXPECT_FALSE(fs::exists(stale_csv));
  EXPECT_FALSE(fs::exists(stale_mesh));
  EXPECT_TRUE(fs::exists(live)) << "a temporary whose writer still runs is kept";
}

// A new whole run into a folder with a longer earlier run's meshes, which diverges part way: what is left
// are its own frames only, not its first frames followed by the earlier run's later ones.
TEST(OutputSafety, ARunThatFailsLeavesNoMixOfTwoRuns) {
  const fs::path dir = scratch_dir("no_mix");
  ASSERT_EQ(run_softbody("export scenes/bounce.json --set duration=0.5 -o " + dir.string()).exit_status, 0);
  int earlier = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    std::ofstream(entry.path()) << "# the earlier run\n";
    ++earlier;
  }
  ASSERT_EQ(earlier, 16);  // frames 0..15 of 0.5 s at 30 frames per second; the failing run's are 0..9 at most
  const auto failed = run_softbody(
      "export scenes/bounce.json --set duration=0.3 --set bodies.0.stiffness=1e6 "
      "--set solver.dt=1e-3 -o " +
      dir.string());
  ASSERT_EQ(failed.exit_status, 3) << failed.output;
  EXPECT_NE(failed.output.find(dir.string() + ": removed an earlier run's outputs before writing: 16 frame files"),
            std::string::npos)
      << failed.output;
  int left = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    EXPECT_EQ(read_text(entry.path()).find("# the earlier run"), std::string::npos) << entry.path();
    ++left;
  }
  EXPECT_LT(left, earlier);
}

// The frame number in a file name, for any output.pattern, and no other file taken for a frame.
TEST(OutputSafety, FrameFilesAreFoundByTheirPattern) {
  EXPECT_EQ(output::frame_index_of("frame_%04d.png", "frame_0012.png"), std::optional<int>(12));
  EXPECT_EQ(output::frame_index_of("frame_%04d.png", "frame_12345.png"), std::optional<int>(12345));
  EXPECT_EQ(output::frame_index_of("take2_%d.png", "take2_7.png"), std::optional<int>(7));
  EXPECT_EQ(output::frame_index_of("100%%_%03d.png", "100%_042.png"), std::optional<int>(42));
  for (const std::string other : {"frame_12.png", "frame_0012.png.tmp1", ".frame_0012.png.tmp1", "figure.png",
                                  "frame_.png", "frame_0012.obj", "frame_x012.png"}) {
    EXPECT_FALSE(output::frame_index_of("frame_%04d.png", other)) << other;
  }
  const fs::path dir = scratch_dir("frame_files");
  for (const std::string name : {"frame_0000.png", "frame_0007.png", "frame_2000.png", "figure.png", "notes.txt"})
    std::ofstream(dir / name) << "x";
  EXPECT_EQ(output::remove_frame_files(dir, "frame_%04d.png"), 3);
  EXPECT_TRUE(fs::exists(dir / "figure.png"));
  EXPECT_TRUE(fs::exists(dir / "notes.txt"));
}

// One run at a time holds a folder: another is refused, naming the folder and who holds it; runs of the same
// identity (the chunks of one render) share it, others do not; once every holder let go, the lock file is gone
// and the folder is free. The lock is per open file, so two locks of one process conflict as two processes' do.
TEST(OutputSafety, AFolderLockKeepsOtherRunsOut) {
  using output::FolderLock;
  const fs::path dir = scratch_dir("folder_lock");
  const auto refused = [&](const std::string& identity, FolderLock::Sharing sharing) {
    try {
      FolderLock lock(dir, identity, sharing, "a test");
    } catch (const softbody::InputError& e) {
      EXPECT_NE(std::string(e.what()).find(dir.string() + ": another softbody run is writing into this folder"),
                std::string::npos)
          << e.what();
      EXPECT_NE(std::string(e.what()).find("pid " + std::to_string(::getpid()) + ": the first"), std::string::npos)
          << e.what();
      return true;
    }
    return false;
  };
  {
    const FolderLock whole(dir, "run A", FolderLock::Sharing::Exclusive, "the first");
    EXPECT_TRUE(refused("run A", FolderLock::Sharing::Exclusive));
    EXPECT_TRUE(refused("run A", FolderLock::Sharing::SameRunOnly));
  }
  EXPECT_FALSE(fs::exists(dir / output::kFolderLockName));
  {
    const FolderLock chunk(dir, "run A", FolderLock::Sharing::SameRunOnly, "the first");
    {
      const FolderLock same_run(dir, "run A", FolderLock::Sharing::SameRunOnly, "the second");
      EXPECT_TRUE(refused("run B", FolderLock::Sharing::SameRunOnly));
      EXPECT_TRUE(refused("run A", FolderLock::Sharing::Exclusive));
    }
    EXPECT_TRUE(fs::exists(dir / output::kFolderLockName)) << "the first chunk still holds it";
    EXPECT_TRUE(refused("run B", FolderLock::Sharing::SameRunOnly));
  }
  EXPECT_FALSE(fs::exists(dir / output::kFolderLockName));
  EXPECT_FALSE(refused("run B", FolderLock::Sharing::Exclusive));
}

// The chunk that wrote its pid into the lock file may end while other chunks of its run go on holding the folder:
// another run is then refused at once, as when the writer still runs (it waited 5 s for a holder that had gone).
TEST(OutputSafety, AnotherRunIsRefusedAtOnceWhileChunksWhoseFirstEndedHoldTheFolder) {
  using output::FolderLock;
  const fs::path dir = scratch_dir("folder_lock_first_chunk_ended");
  int locked[2], joined[2];
  ASSERT_EQ(::pipe(locked), 0);
  ASSERT_EQ(::pipe(joined), 0);
  const pid_t first = ::fork();
  if (first == 0) {
    const FolderLock chunk(dir, "run A", FolderLock::Sharing::SameRunOnly, "the first chunk");
    char byte = 1;
    if (::write(locked[1], &byte, 1) != 1 || ::read(joined[0], &byte, 1) != 1) ::_exit(1);
    ::_exit(0);  // ends holding it: the kernel lets go of its lock, the file keeps naming it
  }
  char byte = 0;
  ASSERT_EQ(::read(locked[0], &byte, 1), 1);
  const FolderLock second(dir, "run A", FolderLock::Sharing::SameRunOnly, "the second chunk");
  ASSERT_EQ(::write(joined[1], &byte, 1), 1);
  int status = -1;
  ASSERT_EQ(::waitpid(first, &status, 0), first);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  for (const auto& [identity, sharing] :
       {std::pair{"run B", FolderLock::Sharing::SameRunOnly}, std::pair{"run A", FolderLock::Sharing::Exclusive}}) {
    const auto start = std::chrono::steady_clock::now();
    try {
      const FolderLock other(dir, identity, sharing, "another run");
      ADD_FAILURE() << identity << " took the folder that a chunk of run A holds";
    } catch (const softbody::InputError& e) {
      EXPECT_NE(std::string(e.what()).find(dir.string() + ": another softbody run is writing into this folder"),
                std::string::npos)
          << e.what();
    }
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0) << identity;
  }
  for (const int fd : {locked[0], locked[1], joined[0], joined[1]}) ::close(fd);
}

struct Interrupted {
  int exit_status = -1;
  std::string errors;
};

// Starts softbody with `arguments`, sends `signal` once it has run `after_ms`, and waits for it.
Interrupted interrupt(const std::vector<std::string>& arguments, int signal, int after_ms, const fs::path& dir) {
  testing_support::BackgroundRun run(arguments, dir);
  std::this_thread::sleep_for(std::chrono::milliseconds(after_ms));
  run.signal(signal);
  const std::optional<int> status = run.wait_for_exit(std::chrono::seconds(600));
  return {status.value_or(-1), run.errors()};
}

// The number N in "after N complete frames".
int complete_frames(const std::string& errors) {
  const std::size_t at = errors.find("stopped after ");
  return at == std::string::npos ? -1 : std::stoi(errors.substr(at + 14));
}

// A run far too long to end by itself: the signal is what ends it.
const std::vector<std::string> kLongRun{"scenes/bounce.json", "--set", "duration=10000", "--set",
                                        "bodies.0.mesh=icosphere:2"};

TEST(OutputSafety, SigintDuringSimulateKeepsTheRowsOfCompleteFrames) {
  const fs::path dir = scratch_dir("sigint_simulate");
  std::vector<std::string> arguments{"simulate"};
  arguments.insert(arguments.end(), kLongRun.begin(), kLongRun.end());
  arguments.insert(arguments.end(), {"--csv", (dir / "rows.csv").string()});
  const Interrupted run = interrupt(arguments, SIGINT, 1500, dir);
  EXPECT_EQ(run.exit_status, 130) << run.errors;
  EXPECT_NE(run.errors.find("interrupted: SIGINT: stopped after "), std::string::npos) << run.errors;
  const int frames = complete_frames(run.errors);
  ASSERT_GT(frames, 0) << run.errors;
  // The CSV: the header, then one row per complete frame (one body), frames 0 .. N-1 in order.
  std::istringstream csv(read_text(dir / "rows.csv"));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, output::kCsvHeader);
  int rows = 0;
  while (std::getline(csv, line)) {
    EXPECT_EQ(line.substr(0, line.find(',')), std::to_string(rows));
    ++rows;
  }
  EXPECT_EQ(rows, frames);
}

// simulate --resume journals its rows, each with a checksum: a row damaged on disk after an interrupted run (6
// bytes overwritten) is not copied into the CSV; the resumed run makes that frame again, and the CSV is byte for
// byte an uninterrupted run's.
TEST(OutputSafety, ResumedSimulateDropsADamagedJournalRow) {
  const fs::path dir = scratch_dir("resume_damaged_row");
  const std::string scene = "scenes/bounce.json --set duration=1 --set bodies.0.mesh=icosphere:3 --set solver.dt=1e-5";
  ASSERT_EQ(run_softbody("simulate " + scene + " --csv " + (dir / "reference.csv").string()).exit_status, 0);
  const fs::path csv = dir / "rows.csv", journal = dir / "rows.csv.resume" / "rows.csv";
  {
    testing_support::BackgroundRun run(
        {"simulate", "scenes/bounce.json", "--set", "duration=1", "--set", "bodies.0.mesh=icosphere:3", "--set",
         "solver.dt=1e-5", "--csv", csv.string(), "--resume"},
        dir);
    const auto journalled_rows = [&] {
      const std::string text = read_text(journal);
      return std::count(text.begin(), text.end(), '\n');
    };
    ASSERT_TRUE(run.wait_until([&] { return journalled_rows() >= 5; }, std::chrono::seconds(60))) << run.errors();
    run.signal(SIGINT);
    ASSERT_EQ(run.wait_for_exit(std::chrono::seconds(60)), std::optional<int>(130)) << run.errors();
  }
  std::string text = read_text(journal);
  std::size_t row = 0;
  for (int line = 0; line < 2; ++line) row = text.find('\n', row) + 1;  // the row of frame 2
  ASSERT_EQ(text.compare(row, 2, "2,"), 0) << text.substr(row, 40);
  text.replace(row + 30, 6, text.compare(row + 30, 6, "777777") == 0 ? "555555" : "777777");
  std::ofstream(journal, std::ios::binary) << text;
  const auto resumed = run_softbody("simulate " + scene + " --csv " + csv.string() + " --resume");
  ASSERT_EQ(resumed.exit_status, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("frames 0..1 are complete"), std::string::npos) << resumed.output;
  EXPECT_EQ(read_text(csv), read_text(dir / "reference.csv"));
}

// export --resume keeps a mesh only if the run's manifest vouches for its bytes: a mesh with 6 bytes overwritten
// after SIGINT is made again, and the meshes end as an uninterrupted run's; a resume in another format is refused
// with exit status 2 naming export.format.
TEST(OutputSafety, ResumedExportRemakesADamagedMesh) {
  const fs::path dir = scratch_dir("resume_damaged_mesh");
  const std::string scene = "scenes/bounce.json --set duration=1 --set bodies.0.mesh=icosphere:3 --set solver.dt=1e-5";
  ASSERT_EQ(run_softbody("export " + scene + " -o " + (dir / "reference").string()).exit_status, 0);
  const fs::path out = dir / "meshes";
  {
    testing_support::BackgroundRun run(
        {"export", "scenes/bounce.json", "--set", "duration=1", "--set", "bodies.0.mesh=icosphere:3", "--set",
         "solver.dt=1e-5", "-o", out.string(), "--resume"},
        dir);
    ASSERT_TRUE(run.wait_until([&] { return fs::exists(out / "frame_0004.obj"); }, std::chrono::seconds(60)))
        << run.errors();
    run.signal(SIGINT);
    ASSERT_EQ(run.wait_for_exit(std::chrono::seconds(60)), std::optional<int>(130)) << run.errors();
  }
  std::string mesh = read_text(out / "frame_0002.obj");
  mesh.replace(mesh.size() / 2, 6, "777777");
  std::ofstream(out / "frame_0002.obj", std::ios::binary) << mesh;
  const auto other = run_softbody("export " + scene + " -o " + out.string() + " --format ply --resume");
  EXPECT_EQ(other.exit_status, 2) << other.output;
  EXPECT_NE(other.output.find("--resume: export.format is ply now but obj in the run it continues"), std::string::npos)
      << other.output;
  const auto resumed = run_softbody("export " + scene + " -o " + out.string() + " --resume");
  ASSERT_EQ(resumed.exit_status, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("frames 0..1 are complete"), std::string::npos) << resumed.output;
  int files = 0;
  for (const auto& entry : fs::directory_iterator(dir / "reference")) {
    EXPECT_EQ(read_text(out / entry.path().filename()), read_text(entry.path())) << entry.path().filename();
    ++files;
  }
  EXPECT_EQ(files, 31);
  EXPECT_FALSE(fs::exists(out / ".softbody-resume"));
}

TEST(OutputSafety, SigtermDuringExportLeavesOnlyCompleteFrames) {
  const fs::path dir = scratch_dir("sigterm_export");
  std::vector<std::string> arguments{"export"};
  arguments.insert(arguments.end(), kLongRun.begin(), kLongRun.end());
  arguments.insert(arguments.end(), {"-o", (dir / "meshes").string()});
  const Interrupted run = interrupt(arguments, SIGTERM, 1500, dir);
  EXPECT_EQ(run.exit_status, 143) << run.errors;
  const int frames = complete_frames(run.errors);
  ASSERT_GT(frames, 0) << run.errors;
  int files = 0;
  for (const auto& entry : fs::directory_iterator(dir / "meshes")) {
    const std::string name = entry.path().filename().string();
    EXPECT_NE(name[0], '.') << "a temporary left: " << name;
    const std::string text = read_text(entry.path());
    EXPECT_EQ(text.back(), '\n') << name << " is cut short";
    ++files;
  }
  EXPECT_EQ(files, frames);
  char last[32];
  std::snprintf(last, sizeof last, "frame_%04d.obj", frames - 1);
  EXPECT_TRUE(fs::exists(dir / "meshes" / last));
}

TEST(OutputSafety, SigintDuringPointCacheExportWritesTheCompleteFrames) {
  const fs::path dir = scratch_dir("sigint_pc2");
  fs::create_directories(dir / "caches");
  const fs::path stale = dir / "caches" / (".body0.pc2.tmp" + std::to_string(dead_pid()));
  std::ofstream(stale) << "half a cache from a killed run";
  std::vector<std::string> arguments{"export"};
  arguments.insert(arguments.end(), kLongRun.begin(), kLongRun.end());
  arguments.insert(arguments.end(), {"--format", "pc2", "-o", (dir / "caches").string()});
  const Interrupted run = interrupt(arguments, SIGINT, 1500, dir);
  EXPECT_EQ(run.exit_status, 130) << run.errors;
  const int frames = complete_frames(run.errors);
  ASSERT_GT(frames, 0) << run.errors;
  // PC2: a 32-byte header (point count at byte 16, sample count at byte 28), then 12 bytes per point per sample.
  const std::string cache = read_text(dir / "caches" / "body0.pc2");
  ASSERT_GE(cache.size(), 32u);
  std::int32_t points = 0, samples = 0;
  std::memcpy(&points, cache.data() + 16, 4);
  std::memcpy(&samples, cache.data() + 28, 4);
  EXPECT_EQ(samples, frames);
  EXPECT_EQ(cache.size(), 32u + 12u * static_cast<std::size_t>(points) * static_cast<std::size_t>(samples));
  for (const auto& entry : fs::directory_iterator(dir / "caches")) {
    EXPECT_NE(entry.path().filename().string()[0], '.') << "a temporary left: " << entry.path();
  }
  EXPECT_FALSE(fs::exists(stale));
}

// A finished output (a video's temporary) put in place of a device is written through it, never replacing it.
TEST(OutputSafety, MoveIntoPlaceWritesThroughADevice) {
  const fs::path dir = scratch_dir("move_into_place");
  const fs::path temporary = dir / ".v.mp4.tmp1";
  std::ofstream(temporary) << "video bytes";
  output::move_into_place(temporary, "/dev/null");
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
  EXPECT_FALSE(fs::exists(temporary));
  std::ofstream(temporary) << "video bytes";
  output::move_into_place(temporary, dir / "v.mp4");  // a regular file: renamed into place
  EXPECT_EQ(read_text(dir / "v.mp4"), "video bytes");
  EXPECT_FALSE(fs::exists(temporary));
  EXPECT_TRUE(output::is_written_through("/dev/null"));
  EXPECT_FALSE(output::is_written_through(dir / "v.mp4"));
  EXPECT_FALSE(output::is_written_through(dir / "nothing.mp4"));
}

}  // namespace
