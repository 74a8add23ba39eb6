// `softbody export SCENE [-o DIR] [--format obj|ply] [--set ...]`: the simulated mesh of every frame.
#include <map>
#include <memory>
#include <vector>

#include "app/commands.hpp"
#include "app/prepared_run.hpp"
#include "app/resume.hpp"
#include "app/run_plan.hpp"
#include "frames/stop_request.hpp"
#include "output/atomic_file.hpp"
#include "output/mesh_exporter.hpp"

namespace app {
namespace {

struct ExportOptions {
  SceneOptions scene;
  FrameOptions frames;
  bool resume = false;
  std::string dir;
  output::MeshFormat format = output::MeshFormat::Obj;
};

int run_export(const ExportOptions& options) {
  PreparedRun run = prepare_run(options.scene);
  frames::stop_on_signals();  // SIGINT / SIGTERM end the run after the frame in progress, outputs complete
  check_resume_options(options.resume, options.frames);
  const PlannedFrames planned(run, options.frames);
  const std::filesystem::path dir = options.dir.empty() ? run.scene.output.dir / "meshes" : std::filesystem::path(options.dir);
  output::MeshExporter exporter(dir, options.format);
  output::remove_stale_temporaries(dir);
  if (!options.resume && planned.plan().frames.everything()) {
    // A whole new run: an earlier run's meshes go first, so that a run that fails leaves no mix of the two.
    output::remove_numbered_files(dir, run.clock.frame_count, [&](int i) { return exporter.frame_path(i).filename(); });
  }
  std::unique_ptr<ResumableRun> resumable;
  std::vector<frames::FrameSink*> sinks = {&exporter};
  if (options.resume) {
    const auto frame_done = [&exporter](int frame) {
      std::error_code ec;
      return std::filesystem::is_regular_file(exporter.frame_path(frame), ec);
    };
    resumable = std::make_unique<ResumableRun>(run, dir / ".softbody-resume", frame_done, dir);
    sinks.push_back(&resumable->store_sink());
  }
  const frames::RunStats stats =
      frames::run_frames(run.world, run.clock, sinks, {}, resumable ? resumable->plan() : planned.plan());
  if (resumable) resumable->remove_store();
  const frames::FrameSelection& chosen = planned.plan().frames;
  print_run_summary(run, stats, "wrote " + exporter.frame_path(chosen.first()).string() + " .. " +
                                    exporter.frame_path(chosen.last()).filename().string());
  return 0;
}

}  // namespace

Action register_export(CLI::App& parent) {
  auto options = std::make_shared<ExportOptions>();
  CLI::App* command = parent.add_subcommand(
      "export", "Run a scene and write the simulated mesh of every frame (OBJ or PLY), numbered like the PNGs");
  add_scene_options(*command, options->scene);
  command->add_option("-o,--output", options->dir, "Output folder (default: <output.dir>/meshes)")->type_name("DIR");
  const std::map<std::string, output::MeshFormat> formats{{"obj", output::MeshFormat::Obj}, {"ply", output::MeshFormat::Ply}};
  command->add_option("--format", options->format, "obj (text, one object per body) or ply (binary, all bodies in one)")
      ->transform(CLI::CheckedTransformer(formats, CLI::ignore_case))
      ->default_str("obj");
  add_frame_options(*command, options->frames);
  add_resume_option(*command, options->resume);
  return [options] { return run_export(*options); };
}

}  // namespace app
