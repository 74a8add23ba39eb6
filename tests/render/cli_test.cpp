// The render command as users run it: exit statuses and messages, the video, and the promise that the
// simulation side never needs OpenGL.
#include <gtest/gtest.h>

#include <signal.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "background_run.hpp"
#include "output/frame_pattern.hpp"
#include "output/png_codec.hpp"
#include "test_context.hpp"
#include "test_helpers.hpp"

namespace {

using testing_support::CommandResult;
using testing_support::run_shell;

// Single-quoted for the shell (test paths hold no quote). Built with += : GCC 12 at -O3 reports a false
// -Wrestrict on "'" + std::string.
std::string quoted(const std::filesystem::path& path) {
  std::string text = "'";
  text += path.string();
  text += "'";
  return text;
}

std::string render_command(const std::filesystem::path& out, const std::string& extra = "") {
  return quoted(SOFTBODY_EXE) + " render " +
         quoted(std::filesystem::path(SOFTBODY_TEST_SCENES_DIR) / "render_track.json") + " -o " + quoted(out) + " " +
         extra;
}

int count_frame_files(const std::filesystem::path& dir) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().filename().string().rfind("frame_", 0) == 0) ++count;
  }
  return count;
}

TEST(RenderCommand, OddWidthIsBadInputNamingTheKey) {
  const std::filesystem::path out = render_test::fresh_output_dir("cli_odd_width");
  const CommandResult result = run_shell(render_command(out, "--set render.width=161"));
  EXPECT_EQ(result.exit_status, 2) << result.output;
  EXPECT_NE(result.output.find("render.width"), std::string::npos) << result.output;
  EXPECT_EQ(count_frame_files(out), 0);
}

TEST(RenderCommand, BadGlBackendIsBadInputAndWritesNothing) {
  const std::filesystem::path out = render_test::fresh_output_dir("cli_backend") / "never";
  const CommandResult scene_key = run_shell(render_command(out, "--set render.backend=vulkan"));
  EXPECT_EQ(scene_key.exit_status, 2) << scene_key.output;
  EXPECT_NE(scene_key.output.find("render.backend"), std::string::npos) << scene_key.output;
  const CommandResult environment = run_shell("SOFTBODY_GL=vulkan " + render_command(out));
  EXPECT_EQ(environment.exit_status, 2) << environment.output;
  EXPECT_NE(environment.output.find("error: SOFTBODY_GL: expected"), std::string::npos) << environment.output;
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(RenderCommand, ExplicitFigureFramesAreCheckedAgainstTheRun) {
  const std::filesystem::path out = render_test::fresh_output_dir("cli_figure_list") / "never";
  // render_track.json has frames 0..10.
  for (const char* list : {"[3,3]", "[-1]", "[0,11]", "[]"}) {
    const CommandResult result =
        run_shell(render_command(out, std::string("--set 'render.figure_frames=") + list + "'"));
    EXPECT_EQ(result.exit_status, 2) << list << ": " << result.output;
    EXPECT_NE(result.output.find("render.figure_frames"), std::string::npos) << result.output;
  }
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(RenderCommand, SceneWithoutCameraKeepsTheBodyInEveryFrame) {
  // The framing camera: the body's pixels in every frame, none of them on the picture's border.
  const std::filesystem::path out = render_test::fresh_output_dir("cli_no_camera");
  const std::filesystem::path scene = out / "no_camera.json";
  {
    std::ifstream in(std::filesystem::path(SOFTBODY_TEST_SCENES_DIR) / "render_track.json");
    std::string text((std::istreambuf_iterator<char>(in)), {});
    text.replace(text.find("\"camera\""), std::string::npos, "\"output\": { \"pattern\": \"frame_%04d.png\" } }\n");
    std::ofstream(scene) << text;
  }
  const CommandResult result = run_shell(quoted(SOFTBODY_EXE) + " render " + quoted(scene) + " -o " + quoted(out));
  ASSERT_EQ(result.exit_status, 0) << result.output;
  EXPECT_NE(result.output.find("a pass over the run"), std::string::npos) << result.output;
  // And tightly: the body's pixels over all frames span most of the picture in one direction (the swept box
  // fills 1 - 2 × 12 % of it where it is tightest: 0.78 here; the default camera, 9 m away: 0.57).
  int left = 1 << 20, right = -1, top = 1 << 20, bottom = -1, width = 0, height = 0;
  for (int i = 0; i <= 10; ++i) {
    const softbody::Image frame = output::read_png(out / output::frame_file_name("frame_%04d.png", i));
    width = frame.width;
    height = frame.height;
    long body = 0, on_border = 0;
    for (int y = 0; y < frame.height; ++y) {
      for (int x = 0; x < frame.width; ++x) {
        const std::uint8_t* p = frame.pixel(x, y);
        if (!(p[0] > 60 && p[0] > 2 * p[1] + 20 && p[0] > 2 * p[2] + 20)) continue;  // the red body
        ++body;
        if (x == 0 || y == 0 || x == frame.width - 1 || y == frame.height - 1) ++on_border;
        left = std::min(left, x), right = std::max(right, x), top = std::min(top, y), bottom = std::max(bottom, y);
      }
    }
    EXPECT_GT(body, 200) << "frame " << i;
    EXPECT_EQ(on_border, 0) << "frame " << i;
  }
  const double span = std::max(double(right - left + 1) / width, double(bottom - top + 1) / height);
  std::printf("framing camera: the body's pixels span %.2f of the picture\n", span);
  EXPECT_GT(span, 0.6);
}

TEST(RenderCommand, VideoHasAsManyFramesAsThePngSequence) {
  if (run_shell("ffprobe -version").exit_status != 0) GTEST_SKIP() << "ffprobe is not installed";
  const std::filesystem::path out = render_test::fresh_output_dir("cli_video");
  const std::filesystem::path video = out / "track.mp4";
  const CommandResult result = run_shell(render_command(out, "--video " + quoted(video)));
  ASSERT_EQ(result.exit_status, 0) << result.output;
  const CommandResult probe = run_shell(
      "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
      "stream=nb_read_frames,width,height,pix_fmt -of csv=p=0 " +
      quoted(video));
  ASSERT_EQ(probe.exit_status, 0) << probe.output;
  EXPECT_EQ(count_frame_files(out), 11);
  EXPECT_EQ(probe.output, "160,120,yuv420p,11\n");
}

TEST(RenderCommand, VideoWithoutPngsWritesNoFrames) {
  if (run_shell("ffmpeg -version").exit_status != 0) GTEST_SKIP() << "ffmpeg is not installed";
  const std::filesystem::path out = render_test::fresh_output_dir("cli_no_png");
  const CommandResult result = run_shell(render_command(out, "--no-png --video " + quoted(out / "v.mp4")));
  ASSERT_EQ(result.exit_status, 0) << result.output;
  EXPECT_EQ(count_frame_files(out), 0);
  EXPECT_TRUE(std::filesystem::exists(out / "v.mp4"));
  EXPECT_TRUE(std::filesystem::exists(out / "figure.png"));
}

TEST(RenderCommand, MissingFfmpegIsAClearFailureAndLeavesNoVideo) {
  const std::filesystem::path out = render_test::fresh_output_dir("cli_no_ffmpeg");
  const CommandResult result =
      run_shell("PATH=/nonexistent " + render_command(out, "--video " + quoted(out / "v.mp4")));
  EXPECT_EQ(result.exit_status, 1) << result.output;
  EXPECT_NE(result.output.find("ffmpeg"), std::string::npos) << result.output;
  EXPECT_FALSE(std::filesystem::exists(out / "v.mp4"));
}

TEST(RenderCommand, DivergedRunKeepsItsValidFramesAndWritesNoVideo) {
  // A time step far too large for the stiffness: the run diverges after a few frames (exit status 3).
  const std::filesystem::path out = render_test::fresh_output_dir("cli_diverged");
  const CommandResult result = run_shell(
      render_command(out, "--set solver.dt=0.01 --set bodies.0.stiffness=1e6 --video " + quoted(out / "v.mp4")));
  EXPECT_EQ(result.exit_status, 3) << result.output;
  const int frames = count_frame_files(out);
  EXPECT_GE(frames, 1);
  EXPECT_LT(frames, 11);
  for (const auto& entry : std::filesystem::directory_iterator(out)) {
    const std::string name = entry.path().filename().string();
    EXPECT_EQ(name.rfind("frame_", 0), 0u) << "left behind: " << name;  // no video, figure or temporary
  }
  for (int i = 0; i < frames; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", i);
    EXPECT_NO_THROW(output::read_png(out / name)) << name;
  }
}

// SIGINT (as Ctrl-C sends it) during a long render: exit 130, the message gives the number of complete
// frames, exactly those frames are there and each decodes; no video, figure or temporary is left. Without a
// figure the frames are drawn from the start; with one, the signal comes during the silent pass that finds
// the figure's moments (a 10,000 s run), before any frame is drawn: 0 complete.
TEST(RenderCommand, SigintKeepsOnlyCompleteFramesAndSaysHowMany) {
  for (const bool with_figure : {false, true}) {
    const std::filesystem::path out = render_test::fresh_output_dir(with_figure ? "cli_sigint_pass" : "cli_sigint");
    const std::string figure = with_figure ? "" : "--set render.figure_frames=0 ";
    const CommandResult result =
        run_shell("timeout --preserve-status -s INT 4 " +
                  render_command(out, figure + "--set duration=10000 --video " + quoted(out / "v.mp4")));
    EXPECT_EQ(result.exit_status, 130) << result.output;
    const std::size_t at = result.output.find("interrupted: SIGINT: stopped after ");
    ASSERT_NE(at, std::string::npos) << result.output;
    const int frames = std::stoi(result.output.substr(at + 35));
    if (with_figure)
      EXPECT_EQ(frames, 0) << result.output;
    else
      EXPECT_GT(frames, 0) << result.output;
    EXPECT_EQ(count_frame_files(out), frames);
    for (const auto& entry : std::filesystem::directory_iterator(out)) {
      const std::string name = entry.path().filename().string();
      EXPECT_EQ(name.rfind("frame_", 0), 0u) << "left behind: " << name;
    }
    for (int i = 0; i < frames; ++i) {
      char name[32];
      std::snprintf(name, sizeof name, "frame_%04d.png", i);
      EXPECT_NO_THROW(output::read_png(out / name)) << name;
    }
  }
}

// A frame far longer than the test waits (909,091 euler steps of a 10,242-vertex ball: 16 minutes measured by
// simulate; see tests/stop_request_test.cpp): SIGTERM ends the render within one step of the simulation. Drawn
// directly (no figure), frame 0 is written and frame 1, stepping on the worker thread, is dropped; with a
// figure, the signal comes during the silent pass (after setup's note), before anything is drawn.
TEST(RenderCommand, SigtermEndsAFrameInProgressWithinAStep) {
  for (const bool with_figure : {false, true}) {
    SCOPED_TRACE(with_figure ? "silent pass" : "overlapped frames");
    const std::filesystem::path out =
        render_test::fresh_output_dir(with_figure ? "cli_sigterm_pass" : "cli_sigterm_step");
    testing_support::BackgroundRun run(
        {"render", "scenes/bounce.json", "-o", out.string(), "--set", "duration=1", "--set", "fps=1", "--set",
         "bodies.0.mesh=icosphere:5", "--set", "solver.dt=1.1e-6", "--set", "render.width=160", "--set",
         "render.height=120", "--set", std::string("render.figure_frames=") + (with_figure ? "4" : "0")},
        testing_support::scratch_dir(with_figure ? "cli_sigterm_pass_log" : "cli_sigterm_step_log"));
    const auto started = [&] {
      return with_figure ? run.errors().find("note: ") != std::string::npos
                         : std::filesystem::exists(out / "frame_0000.png");
    };
    ASSERT_TRUE(run.wait_until(started, std::chrono::seconds(60))) << run.errors();
    run.signal(SIGTERM);
    const std::optional<int> status = run.wait_for_exit(std::chrono::seconds(60));  // liveness, not speed
    ASSERT_TRUE(status) << "still running 60 s after SIGTERM: " << run.errors();
    EXPECT_EQ(*status, 143) << run.errors();
    const std::string expected = with_figure ? "stopped after 0 complete frames" : "stopped after 1 complete frames";
    EXPECT_NE(run.errors().find("interrupted: SIGTERM: " + expected), std::string::npos) << run.errors();
    std::vector<std::string> files;
    for (const auto& entry : std::filesystem::directory_iterator(out))
      files.push_back(entry.path().filename().string());
    EXPECT_EQ(files, with_figure ? std::vector<std::string>{} : std::vector<std::string>{"frame_0000.png"});
    if (!with_figure) {
      EXPECT_NO_THROW(output::read_png(out / "frame_0000.png"));
    }
    std::printf("[ measured ] render (%s): exit %.2f s after SIGTERM\n", with_figure ? "silent pass" : "overlapped",
                run.seconds_to_exit());
  }
}

TEST(RenderCommand, RerunRemovesFramesLeftByALongerRun) {
  const std::filesystem::path out = render_test::fresh_output_dir("cli_stale");
  ASSERT_TRUE(std::filesystem::copy_file(std::filesystem::path(SOFTBODY_GOLDEN_DIR) / "ball_in_the_air.png",
                                         out / "frame_0011.png"));
  const CommandResult result = run_shell(render_command(out));
  ASSERT_EQ(result.exit_status, 0) << result.output;
  EXPECT_EQ(count_frame_files(out), 11);
}

TEST(SimulationSide, CoreLibraryCallsNoOpenGl) {
  // The libraries below the renderer (base, sim, mesh, scene and the pipeline: setup, frames, outputs) and so
  // `softbody simulate` must work where no GL context can be made. Structural check: no object in them references
  // an OSMesa, EGL or GL function (`nm -u` lists the symbols they need from elsewhere).
  const CommandResult symbols = run_shell(std::string("nm -u --format=just-symbols ") + SOFTBODY_NON_GL_LIBRARIES);
  ASSERT_EQ(symbols.exit_status, 0) << symbols.output;
  ASSERT_NE(symbols.output.find("png_"), std::string::npos) << "nm listed nothing useful";
  std::size_t line_start = 0;
  while (line_start < symbols.output.size()) {
    const std::size_t line_end = symbols.output.find('\n', line_start);
    const std::string symbol = symbols.output.substr(line_start, line_end - line_start);
    const bool gl_call =
        symbol.rfind("OSMesa", 0) == 0 ||
        (symbol.size() > 3 && symbol.rfind("egl", 0) == 0 && std::isupper(static_cast<unsigned char>(symbol[3]))) ||
        (symbol.size() > 2 && symbol.rfind("gl", 0) == 0 && std::isupper(static_cast<unsigned char>(symbol[2])));
    EXPECT_FALSE(gl_call) << "a library below the renderer needs " << symbol;
    if (line_end == std::string::npos) break;
    line_start = line_end + 1;
  }
}

TEST(SimulationSide, SimulateRunsWithoutADisplayOrRenderer) {
  // With GALLIUM_DRIVER naming no driver, Mesa 22's OSMesa cannot make a context (`render` crashes in
  // OSMesaCreateContextAttribs), so a `simulate` that made one would fail here.
  const std::filesystem::path out = render_test::fresh_output_dir("cli_simulate");
  const CommandResult result = run_shell("DISPLAY= GALLIUM_DRIVER=none " + quoted(SOFTBODY_EXE) + " simulate " +
                                         quoted(std::filesystem::path(SOFTBODY_TEST_SCENES_DIR) / "render_track.json") +
                                         " --csv " + quoted(out / "track.csv"));
  EXPECT_EQ(result.exit_status, 0) << result.output;
  EXPECT_TRUE(std::filesystem::exists(out / "track.csv"));
}

}  // namespace

namespace {

std::string file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// A farm chunk: frames drawn from a state cache (every 4th state kept, the rest simulated again from the one
// before) are byte-identical to the same frames of a full render, and a chunk touches no other frame file.
TEST(RenderCommand, FramesFromTheStateCacheAreTheFullRendersBytes) {
  const std::filesystem::path full = render_test::fresh_output_dir("cli_cache_full");
  const std::filesystem::path chunk = render_test::fresh_output_dir("cli_cache_chunk");
  const std::filesystem::path cache = render_test::fresh_output_dir("cli_cache_states");
  ASSERT_EQ(run_shell(render_command(full)).exit_status, 0);
  const std::string scene = quoted(std::filesystem::path(SOFTBODY_TEST_SCENES_DIR) / "render_track.json");
  const CommandResult simulate =
      run_shell(quoted(SOFTBODY_EXE) + " simulate " + scene + " --csv " + quoted(cache / "sim.csv") + " --cache " +
                quoted(cache) + " --cache-every 4");
  ASSERT_EQ(simulate.exit_status, 0) << simulate.output;
  const CommandResult render = run_shell(render_command(chunk, "--from-cache " + quoted(cache) + " --frames 3-6,9"));
  ASSERT_EQ(render.exit_status, 0) << render.output;
  EXPECT_EQ(count_frame_files(chunk), 5);
  for (int frame : {3, 4, 5, 6, 9}) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", frame);
    EXPECT_EQ(file_bytes(chunk / name), file_bytes(full / name)) << name;
  }
  // The cache of another scene is refused with exit status 2, naming the manifest.
  const CommandResult other =
      run_shell(render_command(chunk, "--from-cache " + quoted(cache) + " --set gravity=[0,-5,0]"));
  EXPECT_EQ(other.exit_status, 2) << other.output;
  EXPECT_NE(other.output.find("a cache of another scene"), std::string::npos) << other.output;
}

// What a folder holds besides frame files: their names, sorted.
std::vector<std::string> other_files(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("frame_", 0) != 0) names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  return names;
}

// A rerun into the folder of a longer earlier run (11 frames, a figure, a video) that fails: what is left is
// its own frames only, each decoding, none numbered past its own end, and no earlier figure or video.
TEST(RenderCommand, AFailedRerunAfterALongerRunLeavesOnlyItsOwnFrames) {
  const std::filesystem::path out = render_test::fresh_output_dir("cli_rerun_fails");
  const std::string video = "--video " + quoted(out / "v.mp4");
  ASSERT_EQ(run_shell(render_command(out, video)).exit_status, 0);
  ASSERT_EQ(count_frame_files(out), 11);
  ASSERT_EQ(other_files(out), (std::vector<std::string>{".softbody-video", "figure.png", "v.mp4"}));
  const CommandResult failed =
      run_shell(render_command(out, "--set duration=0.5 --set solver.dt=0.01 --set bodies.0.stiffness=1e6 " + video));
  ASSERT_EQ(failed.exit_status, 3) << failed.output;
  EXPECT_NE(failed.output.find("removed an earlier run's outputs before writing: 11 frame files, figure.png, "),
            std::string::npos)
      << failed.output;
  const int frames = count_frame_files(out);
  EXPECT_GE(frames, 1);
  EXPECT_LE(frames, 6);  // 0.5 s at 10 frames per second: frames 0..5 at most
  for (int i = 0; i < frames; ++i)
    EXPECT_NO_THROW(output::read_png(out / output::frame_file_name("frame_%04d.png", i)));
  EXPECT_EQ(other_files(out), std::vector<std::string>{});
}

// The earlier run's video goes with its frames even when the rerun makes no video or another one: a whole run
// records the video it wrote into its folder (.softbody-video), and the next whole run removes it, saying so,
// if it still holds the bytes recorded. A video the user has replaced since, or one outside the folder, stays.
TEST(RenderCommand, ARerunRemovesTheEarlierRunsVideoOfAnotherName) {
  const std::filesystem::path out = render_test::fresh_output_dir("cli_rerun_other_video");
  const std::filesystem::path elsewhere = render_test::fresh_output_dir("cli_rerun_other_video_elsewhere");
  const std::string fails = "--set duration=0.5 --set solver.dt=0.01 --set bodies.0.stiffness=1e6";
  ASSERT_EQ(run_shell(render_command(out, "--video " + quoted(out / "v.mp4"))).exit_status, 0);
  const CommandResult failed = run_shell(render_command(out, fails));
  ASSERT_EQ(failed.exit_status, 3) << failed.output;
  EXPECT_NE(failed.output.find("removed an earlier run's outputs before writing: 11 frame files, figure.png, " +
                               (out / "v.mp4").string()),
            std::string::npos)
      << failed.output;
  EXPECT_EQ(other_files(out), std::vector<std::string>{});
  // Replaced by the user after the run: not the recorded video any more.
  ASSERT_EQ(run_shell(render_command(out, "--video " + quoted(out / "w.mp4"))).exit_status, 0);
  std::ofstream(out / "w.mp4") << "the user's own file";
  ASSERT_EQ(run_shell(render_command(out, fails)).exit_status, 3);
  EXPECT_EQ(other_files(out), std::vector<std::string>{"w.mp4"});
  // Outside the folder: not this folder's output.
  ASSERT_EQ(run_shell(render_command(out, "--video " + quoted(elsewhere / "x.mp4"))).exit_status, 0);
  ASSERT_EQ(run_shell(render_command(out, fails)).exit_status, 3);
  EXPECT_TRUE(std::filesystem::exists(elsewhere / "x.mp4"));
}

// SIGINT during a rerun into the folder of an earlier run with a video (61 frames): the earlier video and later
// frames are gone, the run's own complete frames are there. The signal comes once the rerun has removed the
// earlier frames and written its third.
TEST(RenderCommand, AnInterruptedRerunLeavesNoEarlierVideoOrFrames) {
  if (run_shell("ffmpeg -version").exit_status != 0) GTEST_SKIP() << "ffmpeg is not installed";
  const std::filesystem::path out = render_test::fresh_output_dir("cli_rerun_interrupted");
  ASSERT_EQ(run_shell(render_command(out, "--set duration=6 --video " + quoted(out / "v.mp4"))).exit_status, 0);
  ASSERT_EQ(count_frame_files(out), 61);
  testing_support::BackgroundRun run(
      {"render", std::filesystem::path(SOFTBODY_TEST_SCENES_DIR) / "render_track.json", "-o", out.string(), "--set",
       "duration=10000", "--set", "render.figure_frames=0", "--video", (out / "v.mp4").string()},
      testing_support::scratch_dir("cli_rerun_interrupted_log"));
  const auto drawing = [&] {
    return !std::filesystem::exists(out / "frame_0060.png") && std::filesystem::exists(out / "frame_0002.png");
  };
  ASSERT_TRUE(run.wait_until(drawing, std::chrono::seconds(60))) << run.errors();
  run.signal(SIGINT);
  ASSERT_EQ(run.wait_for_exit(std::chrono::seconds(60)), std::optional<int>(130)) << run.errors();
  const std::size_t at = run.errors().find("stopped after ");
  ASSERT_NE(at, std::string::npos) << run.errors();
  const int frames = std::stoi(run.errors().substr(at + 14));
  EXPECT_EQ(count_frame_files(out), frames);
  EXPECT_LT(frames, 61);
  for (int i = 0; i < frames; ++i)
    EXPECT_TRUE(std::filesystem::exists(out / output::frame_file_name("frame_%04d.png", i)));
  EXPECT_EQ(other_files(out), std::vector<std::string>{});
}

// Two different runs never write one folder at once: while a run holds it, a whole run, or a chunk of another
// render (a different width), is refused with exit status 2 naming the folder; a chunk of the same render
// (--frames, same scene and settings) shares it, as a farm's chunks do. Once the run ended, the folder is free
// and no lock file is left.
TEST(RenderCommand, TwoRunsCannotWriteOneFolderButTheChunksOfOneRenderCan) {
  const std::filesystem::path out = render_test::fresh_output_dir("cli_lock");
  const std::string scene = std::filesystem::path(SOFTBODY_TEST_SCENES_DIR) / "render_track.json";
  testing_support::BackgroundRun chunk(
      {"render", scene, "-o", out.string(), "--set", "duration=1000", "--frames", "3-9999"},
      testing_support::scratch_dir("cli_lock_log"));
  ASSERT_TRUE(
      chunk.wait_until([&] { return std::filesystem::exists(out / "frame_0004.png"); }, std::chrono::seconds(60)))
      << chunk.errors();
  const CommandResult same = run_shell(render_command(out, "--set duration=1000 --frames 0-1"));
  EXPECT_EQ(same.exit_status, 0) << same.output;
  EXPECT_TRUE(std::filesystem::exists(out / "frame_0000.png"));
  const std::string held = out.string() + ": another softbody run is writing into this folder";
  for (const std::string other :
       {"--set duration=1000 --frames 0-1 --set render.width=320", "--set duration=1000", ""}) {
    const CommandResult refused = run_shell(render_command(out, other));
    EXPECT_EQ(refused.exit_status, 2) << other << ": " << refused.output;
    EXPECT_NE(refused.output.find(held), std::string::npos) << refused.output;
  }
  chunk.signal(SIGINT);
  ASSERT_EQ(chunk.wait_for_exit(std::chrono::seconds(60)), std::optional<int>(130)) << chunk.errors();
  EXPECT_FALSE(std::filesystem::exists(out / ".softbody-lock"));
  const CommandResult after = run_shell(render_command(out));
  EXPECT_EQ(after.exit_status, 0) << after.output;
  EXPECT_EQ(count_frame_files(out), 11);
}

}  // namespace

namespace {

// render --resume checks every frame it keeps against the run's manifest (size, checksum) and decodes it: after
// SIGINT, a frame cut to 500 bytes is made again, not kept. A resume with another render.width is refused with
// exit status 2 naming the key, touching nothing. The resumed frames are an uninterrupted run's, byte for byte.
TEST(RenderCommand, ResumeRemakesADamagedFrameAndRefusesOtherSettings) {
  const std::filesystem::path reference = render_test::fresh_output_dir("cli_resume_reference");
  const std::filesystem::path out = render_test::fresh_output_dir("cli_resume_damaged");
  const std::string slow = "--set duration=3 --set bodies.0.mesh=icosphere:4 --set render.figure_frames=0";
  ASSERT_EQ(run_shell(render_command(reference, slow)).exit_status, 0);
  ASSERT_EQ(count_frame_files(reference), 31);
  {
    testing_support::BackgroundRun run(
        {"render", std::filesystem::path(SOFTBODY_TEST_SCENES_DIR) / "render_track.json", "-o", out.string(), "--set",
         "duration=3", "--set", "bodies.0.mesh=icosphere:4", "--set", "render.figure_frames=0", "--resume"},
        testing_support::scratch_dir("cli_resume_damaged_log"));
    ASSERT_TRUE(
        run.wait_until([&] { return std::filesystem::exists(out / "frame_0004.png"); }, std::chrono::seconds(60)))
        << run.errors();
    run.signal(SIGINT);
    ASSERT_EQ(run.wait_for_exit(std::chrono::seconds(60)), std::optional<int>(130)) << run.errors();
  }
  ASSERT_LT(count_frame_files(out), 31);
  std::filesystem::resize_file(out / "frame_0002.png", 500);
  const std::string frame_3 = file_bytes(out / "frame_0003.png");

  const CommandResult other = run_shell(render_command(out, slow + " --set render.width=320 --resume"));
  EXPECT_EQ(other.exit_status, 2) << other.output;
  EXPECT_NE(other.output.find("--resume: render.width is 320 now but 160 in the run it continues"), std::string::npos)
      << other.output;
  EXPECT_EQ(file_bytes(out / "frame_0003.png"), frame_3);

  const CommandResult resumed = run_shell(render_command(out, slow + " --resume"));
  ASSERT_EQ(resumed.exit_status, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("frames 0..1 are complete"), std::string::npos) << resumed.output;
  ASSERT_EQ(count_frame_files(out), 31);
  for (int frame = 0; frame <= 30; ++frame) {
    const std::string name = output::frame_file_name("frame_%04d.png", frame);
    EXPECT_EQ(file_bytes(out / name), file_bytes(reference / name)) << name;
  }
  EXPECT_FALSE(std::filesystem::exists(out / ".softbody-resume"));
}

}  // namespace
