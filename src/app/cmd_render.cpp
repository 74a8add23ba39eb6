// `softbody render SCENE [-o DIR] [--set ...] [--video FILE.mp4] [--no-png]`: simulate and render every
// frame off-screen into PNG files (frame 0 is the initial state), figure.png and optionally a video.
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <vector>

#include "app/commands.hpp"
#include "app/output_settings.hpp"
#include "app/prepared_run.hpp"
#include "app/progress.hpp"
#include "app/resume.hpp"
#include "app/run_camera.hpp"
#include "app/run_plan.hpp"
#include "core/errors.hpp"
#include "core/profile.hpp"
#include "frames/frame_loop.hpp"
#include "frames/overlapped_frame_loop.hpp"
#include "frames/stop_request.hpp"
#include "output/atomic_file.hpp"
#include "output/figure_frames.hpp"
#include "output/folder_lock.hpp"
#include "output/frame_pattern.hpp"
#include "output/motion_track.hpp"
#include "output/png_codec.hpp"
#include "output/run_manifest.hpp"
#include "output/video_record.hpp"
#include "render/gl_context.hpp"
#include "render/render_sink.hpp"
#include "render/renderer.hpp"
#include "render/settings.hpp"
#include "scene/frame_pattern_check.hpp"
#include "setup/scene_hash.hpp"

namespace app {
namespace {

struct RenderOptions {
  SceneOptions scene;
  FrameOptions frames;
  std::string output_dir;
  std::string video_file;
  bool no_png = false;
  bool resume = false;
  bool profile = false;
};

// The frames of figure.png: render.figure_frames's list, or that many chosen from the motion.
std::vector<int> figure_frames(const scene::Scene& scene, const output::MotionTrack* motion, int last_frame) {
  if (!scene.render.figure_frame_list.empty()) {
    if (scene.render.figure_frame_list.back() > last_frame) {
      throw softbody::InputError(scene.source.string() + ": render.figure_frames: expected frames 0.." +
                                 std::to_string(last_frame) + ", got " +
                                 std::to_string(scene.render.figure_frame_list.back()));
    }
    return scene.render.figure_frame_list;
  }
  if (motion == nullptr || scene.render.figure_frames == 0) return {};
  std::optional<double> floor;
  if (scene.floor) floor = scene.floor->height_m;
  return output::frames_from_motion(motion->samples(), scene.render.figure_frames, floor);
}

double ms_per_frame(double total_s, int frames) { return frames > 0 ? 1000.0 * total_s / frames : 0.0; }

// One line of figures docs/performance.md and the benchmarks quote: what a frame costs, stage by stage.
void print_summary(const scene::Scene& scene, const render::Renderer& renderer, const frames::RunStats& run,
                   const render::RenderTimings& t, const std::string& backend) {
  const int n = run.frames;
  std::printf(
      "%s: %d frames %dx%d (msaa %d, shadows %s) in %.2f s: %.1f fps end to end; ms per frame: "
      "simulate %.1f, render %.1f, read-back %.1f, encode %.1f (writer thread; +%.1f writing files)",
      scene.name.c_str(), n, scene.render.width_px, scene.render.height_px, renderer.msaa_samples(),
      scene.render.shadows ? "on" : "off", run.wall_s, n / std::max(run.wall_s, 1e-9), ms_per_frame(run.step_wall_s, n),
      ms_per_frame(t.snapshot_s + t.render_s, n), ms_per_frame(t.read_back_s, n),
      ms_per_frame(t.png.encode_s, t.png.frames), ms_per_frame(t.png.store_s, t.png.frames));
  if (t.video_s > 0.0) std::printf(", video %.1f", ms_per_frame(t.video_s, n));
  std::printf("; backend %s\n", backend.c_str());
}

// "egl (auto from render.backend: OpenGL 4.5 ... on llvmpipe ... (EGL, surfaceless))".
std::string backend_words(const render::GlContext& context, const render::GlBackendRequest& request) {
  std::string words(render::gl_backend_name(context.backend()));
  if (request.backend == render::GlBackend::Auto)
    words += " (auto";
  else
    words += " (asked for";
  return words + " by " + request.source + "; " + context.description() + ")";
}

void print_written(const render::RenderOutputs& outputs, const render::RenderSink& sink, int frames) {
  if (outputs.write_frames) {
    std::printf("frames: %s (%d files)\n", (outputs.dir / outputs.pattern).string().c_str(), frames);
  }
  if (const auto figure = sink.figure_path()) std::printf("figure: %s\n", figure->string().c_str());
  if (outputs.video) std::printf("video:  %s\n", outputs.video->string().c_str());
}

// Whether `path` is a PNG file that decodes to width x height pixels.
bool decodes_at_size(const std::filesystem::path& path, int width, int height) {
  try {
    const softbody::Image image = output::read_png(path);
    return image.width == width && image.height == height;
  } catch (const std::exception&) {
    return false;
  }
}

// A whole new run: the earlier run's frames (whatever their numbers), figure and video go first, so that a run
// that fails (diverges, is interrupted) leaves only its own frames, never a mix of two runs. The earlier video
// is this run's --video file, and the one the earlier run recorded in the folder (output/video_record.hpp)
// whatever its name. A resumed run keeps its frames (`keep_frames`): its figure and video are made at the end.
// Says what went.
void remove_earlier_outputs(const render::RenderOutputs& outputs, bool keep_frames = false) {
  std::vector<std::string> removed;
  const int frames =
      outputs.write_frames && !keep_frames ? output::remove_frame_files(outputs.dir, outputs.pattern) : 0;
  if (frames > 0) removed.push_back(std::to_string(frames) + " frame files");
  std::error_code ec;
  if (std::filesystem::remove(outputs.dir / "figure.png", ec)) removed.emplace_back("figure.png");
  if (const std::string video = output::remove_recorded_video(outputs.dir); !video.empty()) removed.push_back(video);
  if (outputs.video && !output::is_written_through(*outputs.video) && std::filesystem::remove(*outputs.video, ec))
    removed.push_back(outputs.video->string());
  std::string words;
  for (const std::string& item : removed) words += (words.empty() ? "" : ", ") + item;
  if (!words.empty())
    std::fprintf(stderr, "note: %s: removed an earlier run's outputs before writing: %s\n", outputs.dir.c_str(),
                 words.c_str());
}

int run_render(const RenderOptions& options) {
  // SIGINT / SIGTERM end setup after its phase in progress (nothing written) and the run within one step of
  // the simulation (the frame in progress dropped); the outputs hold every complete frame.
  frames::stop_on_signals();
  PreparedRun run = softbody::profiled(softbody::ProfilePhase::setup,
                                       [&] { return prepare_run(options.scene, /*threads_when_auto=*/1); });
  check_resume_options(options.resume, options.frames);
  if (options.resume && options.no_png) {
    throw softbody::InputError("--resume continues from the PNG frames on disk: use it without --no-png");
  }
  const PlannedFrames planned(run, options.frames);
  const frames::FrameSelection& chosen = planned.plan().frames;
  scene::Scene& scene = run.scene;
  if (!options.output_dir.empty()) scene.output.dir = options.output_dir;
  scene::check_frame_pattern(scene.output.pattern, scene.source.string());
  const std::vector<output::InputFile> inputs = scene_inputs(scene);  // no output may replace one
  if (!options.video_file.empty()) output::refuse_output_onto_inputs(options.video_file, inputs, "--video");
  output::refuse_output_onto_inputs(scene.output.dir / "figure.png", inputs, "-o");
  output::refuse_numbered_outputs_onto_inputs(
      scene.output.dir, run.clock.frame_count,
      [&](int i) { return std::filesystem::path(output::frame_file_name(scene.output.pattern, i)); }, inputs, "-o");

  const render::GlBackendRequest backend = render::choose_gl_backend(scene.render.backend, std::getenv("SOFTBODY_GL"));
  // One run at a time writes into the folder; the chunks of one render (--frames, same scene and settings)
  // share it. Taken before the long work (the silent pass, the frames), so that a second run is refused at once.
  const output::FolderLock lock(
      scene.output.dir, run_identity("render", scene, render_output_settings(scene)),
      chosen.everything() ? output::FolderLock::Sharing::Exclusive : output::FolderLock::Sharing::SameRunOnly,
      "render " + scene.source.string());
  const std::unique_ptr<render::GlContext> context = render::create_offscreen_context(backend.backend);
  render::RenderSettings settings = render::settings_from_scene(scene);
  render::use_world_colliders(settings, run.world.model.colliders);
  const int last_frame = run.clock.frame_count;
  // A run of some frames only (a farm chunk) makes no figure.
  const bool motion_figure =
      chosen.everything() && scene.render.figure_frame_list.empty() && scene.render.figure_frames > 0;
  std::optional<output::MotionTrack> motion;
  if (!scene.camera.given || motion_figure) motion = motion_of_the_run(run, planned.plan().checkpoints);
  if (!scene.camera.given) frame_the_motion(settings, *motion);
  const std::vector<int> figure =
      chosen.everything() ? figure_frames(scene, motion ? &*motion : nullptr, last_frame) : std::vector<int>{};
  render::Renderer renderer(*context, settings);
  frames::throw_if_stop_requested_after("setting up the renderer");  // before any output is touched

  render::RenderOutputs outputs;
  outputs.dir = scene.output.dir;
  outputs.pattern = scene.output.pattern;
  outputs.write_frames = !options.no_png;
  if (!options.video_file.empty()) outputs.video = options.video_file;
  outputs.fps = scene.fps;
  // A run of some frames only (a farm chunk) neither makes the figure nor removes frames past the last one.
  outputs.figure_frames = 0;
  outputs.figure_frame_list = figure;
  outputs.last_frame = run.clock.frame_count;
  outputs.remove_stale_frames = chosen.everything();
  std::filesystem::create_directories(outputs.dir);
  output::remove_stale_temporaries(outputs.dir);
  if (!options.resume && chosen.everything()) remove_earlier_outputs(outputs);
  std::unique_ptr<ResumableRun> resumable;
  output::RunManifest manifest;
  if (options.resume) {
    // The manifest of the run to continue vouches for the frames it wrote (size and checksum); a frame it does
    // not vouch for, or that does not decode at the run's size, is made again with all after it.
    const std::filesystem::path store = outputs.dir / ".softbody-resume", manifest_path = store / "frames.manifest";
    const std::string scene_hash = setup::hash_text(setup::simulation_hash(scene));
    const OutputSettings output_settings = render_output_settings(scene);
    manifest = output::RunManifest::read(manifest_path, scene_hash);
    std::error_code ec;
    if (manifest.intact() && std::filesystem::exists(store / "cache.json", ec))
      manifest.check_settings(output_settings);  // a run to continue: its settings must be these
    const auto frame_done = [&](int frame) {
      const std::string name = output::frame_file_name(outputs.pattern, frame);
      return manifest.vouches_for(outputs.dir, name) &&
             decodes_at_size(outputs.dir / name, settings.width_px, settings.height_px);
    };
    resumable = std::make_unique<ResumableRun>(run, store, frame_done, outputs.dir);
    std::vector<std::string> kept;
    for (int frame = 0; frame <= resumable->resumed_after(); ++frame)
      kept.push_back(output::frame_file_name(outputs.pattern, frame));
    manifest.start(manifest_path, scene_hash, output_settings, kept);
    outputs.frame_stored = [&manifest](const std::filesystem::path& path, std::string_view bytes) {
      manifest.add(path.filename().string(), bytes);
    };
    if (outputs.video) output::remove_stale_temporaries(outputs.video->parent_path());
    outputs.resumed_after = resumable->resumed_after();
    remove_earlier_outputs(outputs, /*keep_frames=*/outputs.resumed_after >= 0);  // < 0: nothing to continue
    outputs.video_from_files = true;
  }
  render::RenderSink sink(renderer, outputs);

  ProgressLine progress;
  std::vector<frames::CapturingFrameSink*> sinks = {&sink};
  if (resumable) sinks.push_back(&resumable->store_sink());
  frames::RunStats stats;
  try {
    // The next frame steps on a worker thread while this one (the GL context's) renders the last.
    stats = frames::run_frames_overlapped(
        run.world, run.clock, sinks, [&](int done, int last) { progress.update(done, last); },
        resumable ? resumable->plan() : planned.plan());
  } catch (...) {
    progress.clear();
    throw;
  }
  progress.clear();
  if (resumable) resumable->remove_store();
  // The next whole run into the folder removes this video, whatever video it makes itself.
  if (outputs.video && chosen.everything()) output::record_video(outputs.dir, *outputs.video);
  print_summary(scene, renderer, stats, sink.timings(), backend_words(*context, backend));
  print_written(outputs, sink, stats.frames);
  return 0;
}

}  // namespace

Action register_render(CLI::App& parent) {
  auto options = std::make_shared<RenderOptions>();
  CLI::App* command = parent.add_subcommand(
      "render",
      "Simulate a scene and render every frame off-screen (EGL or OSMesa) to PNG files, figure.png and a video");
  add_scene_options(*command, options->scene);
  command
      ->add_option("-o,--output", options->output_dir,
                   "Output folder (default: the scene's output.dir, "
                   "else out/<scene name>)")
      ->type_name("DIR");
  command->add_option("--video", options->video_file, "Also write an H.264 MP4 (needs ffmpeg on PATH)")
      ->type_name("FILE.mp4");
  command->add_flag("--no-png", options->no_png, "Write no PNG frames (figure.png and --video still are)");
  add_frame_options(*command, options->frames);
  add_resume_option(*command, options->resume);
  add_profile_option(*command, options->profile);
  command->footer(
      "Writes DIR/frame_%04d.png (output.pattern), frame 0 being the initial state, so that\n"
      "  ffmpeg -framerate FPS -i DIR/frame_%04d.png reads them; each file appears whole (temporary name, then\n"
      "  rename). A whole new run first removes the earlier run's frames (any number), figure.png and video, and\n"
      "  says so: a run that fails or is interrupted leaves only its own frames. One run at a time writes into DIR\n"
      "  (a second one: exit status 2); the --frames chunks of one render (same scene and settings) share it.\n"
      "  DIR/figure.png shows render.figure_frames frames chosen from the motion (frame 0, the first contact, the\n"
      "  deepest compression, rest, the highest rebound, the turn back, then frames spread between), each labelled\n"
      "  with its time; render.figure_frames as a list ([0, 19, 24]) shows exactly those frames; 0: no figure.\n"
      "  A scene without camera gets one that frames the bodies' whole trajectory (floor horizon in view).\n"
      "  Either needs a silent pass over the run before drawing (from the cache with --from-cache).\n"
      "  With --frames only those frames are drawn (the states before come from --from-cache or are simulated\n"
      "  silently), no figure is made and no other frame file is touched: chunks can render side by side.\n"
      "  Size, MSAA, shadows, camera and light come from the scene's render, camera and light keys.\n"
      "  The GL backend: render.backend (auto | egl | osmesa; auto tries EGL, then OSMesa), overridden by the\n"
      "  environment variable SOFTBODY_GL when it is set; the summary line names the backend used.\n"
      "  Prints a progress line when stderr is a terminal, and a summary with the time per frame of each stage.");
  return [options] {
    const ProfiledRun profiled(options->profile);
    return run_render(*options);
  };
}

}  // namespace app
