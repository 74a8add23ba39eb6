// `softbody export SCENE [-o DIR] [--format obj|ply|pc2|mdd] [--set ...]`: the simulated mesh of every frame,
// or per body one mesh and a point cache of its positions; and the colliders: a static one once
// (output/collider_export.hpp), a keyframed one per frame or as a point cache (output/moving_collider_export.hpp).
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "app/commands.hpp"
#include "app/output_settings.hpp"
#include "app/prepared_run.hpp"
#include "app/progress.hpp"
#include "app/resume.hpp"
#include "app/run_plan.hpp"
#include "core/errors.hpp"
#include "core/profile.hpp"
#include "frames/stop_request.hpp"
#include "output/atomic_file.hpp"
#include "output/collider_export.hpp"
#include "output/folder_lock.hpp"
#include "output/frame_pattern.hpp"
#include "output/mesh_exporter.hpp"
#include "output/moving_collider_export.hpp"
#include "output/point_cache.hpp"
#include "output/run_manifest.hpp"
#include "setup/scene_hash.hpp"

namespace app {
namespace {

enum class ExportFormat { Obj, Ply, Pc2, Mdd };

struct ExportOptions {
  SceneOptions scene;
  FrameOptions frames;
  bool resume = false;
  std::string dir;
  ExportFormat format = ExportFormat::Obj;
  bool profile = false;
  bool progress_lines = false;
};

frames::Progress export_progress(const ExportOptions& options) {
  return options.progress_lines ? progress_lines() : frames::Progress{};
}

// Refuses collider files that would overwrite an input (checked before anything is written).
void refuse_colliders_onto_inputs(const std::filesystem::path& dir, std::size_t colliders, const std::string& extension,
                                  const std::vector<output::InputFile>& inputs) {
  for (std::size_t i = 0; i < colliders; ++i) {
    output::refuse_output_onto_inputs(output::collider_path(dir, i, extension), inputs, "-o");
  }
}

// Says on standard error what an earlier run left that a new one removed, if anything.
void note_removed(const std::filesystem::path& dir, int frame_files, int collider_files) {
  std::string removed;
  if (frame_files > 0) removed = std::to_string(frame_files) + " frame files";
  if (collider_files > 0) removed += (removed.empty() ? "" : ", ") + std::to_string(collider_files) + " collider files";
  if (!removed.empty())
    std::fprintf(stderr, "note: %s: removed an earlier run's outputs before writing: %s\n", dir.c_str(),
                 removed.c_str());
}

// --format pc2 | mdd: DIR/body<N>.obj and DIR/body<N>.pc2 (.mdd), written when the run ends.
int run_point_cache_export(const ExportOptions& options, output::PointCacheFormat format) {
  if (options.resume) {
    throw softbody::InputError("--resume: a point cache is written whole at the end; export it again instead");
  }
  // SIGINT / SIGTERM end setup after its phase in progress (nothing written) and the run within one step;
  // the caches then hold every complete frame.
  frames::stop_on_signals();
  PreparedRun run = softbody::profiled(softbody::ProfilePhase::setup, [&] { return prepare_run(options.scene); });
  const PlannedFrames planned(run, options.frames);
  const frames::FrameSelection& chosen = planned.plan().frames;
  if (chosen.count() != chosen.last() - chosen.first() + 1) {
    throw softbody::InputError("--frames: a point cache holds frames one after another (one range), got " +
                               options.frames.frames);
  }
  const std::filesystem::path dir =
      options.dir.empty() ? run.scene.output.dir / "meshes" : std::filesystem::path(options.dir);
  output::PointCacheExporter exporter(dir, format);
  const std::vector<output::InputFile> inputs = scene_inputs(run.scene);
  // The files written at the end, one pair per body: none may be an input.
  for (int body = 0; body < static_cast<int>(run.world.model.bodies.size()); ++body) {
    output::refuse_output_onto_inputs(exporter.mesh_path(body), inputs, "-o");
    output::refuse_output_onto_inputs(exporter.cache_path(body), inputs, "-o");
  }
  refuse_colliders_onto_inputs(dir, run.world.model.colliders.size(), ".obj", inputs);
  output::ColliderCacheExporter collider_caches(dir, run.world.model.colliders, format);
  for (const std::size_t collider : collider_caches.moving())
    output::refuse_output_onto_inputs(collider_caches.cache_path(collider), inputs, "-o");
  // One run at a time writes into the folder; the files are written whole at the end, so chunks would replace
  // each other's: none share it.
  const output::FolderLock lock(
      dir,
      run_identity("export", run.scene,
                   export_output_settings(format == output::PointCacheFormat::Pc2 ? "pc2" : "mdd")),
      output::FolderLock::Sharing::Exclusive, "export " + run.scene.source.string());
  output::remove_stale_temporaries(dir);  // a killed run's half-written cache
  // An earlier run's colliders: a cache of one that is static now would move its mesh on import.
  note_removed(dir, 0, output::remove_collider_files(dir, std::vector<std::string>{".obj", ".pc2", ".mdd"}, inputs));
  output::write_colliders(dir, run.world.model.colliders, ".obj");  // static: once, before the frames
  std::vector<frames::FrameSink*> sinks = {&exporter, &collider_caches};
  const frames::RunStats stats =
      frames::run_frames(run.world, run.clock, sinks, export_progress(options), planned.plan());
  print_run_summary(run, stats,
                    "wrote " + exporter.mesh_path(0).string() + ", " + exporter.cache_path(0).filename().string() +
                        (exporter.body_count() > 1 ? " .. body" + std::to_string(exporter.body_count() - 1) : "") +
                        " (frames " + std::to_string(chosen.first()) + ".." + std::to_string(chosen.last()) + ")");
  return 0;
}

// A whole new run: an earlier run's meshes, collider frames (whatever their numbers) and static colliders (whatever
// their indices) go first, so that a run that fails or is interrupted leaves only its own files, never a mix of two
// runs, and a collider that was static then and is keyframed now leaves no collider_<N> file behind (nor one the
// scene no longer has). Says how many went.
void remove_earlier_meshes(const std::filesystem::path& dir, const std::string& pattern,
                           const std::string& collider_extension, const std::vector<output::InputFile>& inputs) {
  const int frames = output::remove_frame_files(dir, pattern) + output::remove_collider_frames(dir, collider_extension);
  note_removed(dir, frames, output::remove_collider_files(dir, std::vector<std::string>{collider_extension}, inputs));
}

int run_export(const ExportOptions& options) {
  if (options.format == ExportFormat::Pc2) return run_point_cache_export(options, output::PointCacheFormat::Pc2);
  if (options.format == ExportFormat::Mdd) return run_point_cache_export(options, output::PointCacheFormat::Mdd);
  const output::MeshFormat mesh_format =
      options.format == ExportFormat::Obj ? output::MeshFormat::Obj : output::MeshFormat::Ply;
  // SIGINT / SIGTERM end setup after its phase in progress (nothing written) and the run within one step
  // (the frame in progress dropped); the outputs hold every complete frame.
  frames::stop_on_signals();
  PreparedRun run = softbody::profiled(softbody::ProfilePhase::setup, [&] { return prepare_run(options.scene); });
  check_resume_options(options.resume, options.frames);
  const PlannedFrames planned(run, options.frames);
  const std::filesystem::path dir =
      options.dir.empty() ? run.scene.output.dir / "meshes" : std::filesystem::path(options.dir);
  output::MeshExporter exporter(dir, mesh_format);
  output::refuse_numbered_outputs_onto_inputs(
      dir, run.clock.frame_count, [&](int i) { return exporter.frame_path(i).filename(); }, scene_inputs(run.scene),
      "-o");
  const std::string collider_extension = mesh_format == output::MeshFormat::Obj ? ".obj" : ".ply";
  refuse_colliders_onto_inputs(dir, run.world.model.colliders.size(), collider_extension, scene_inputs(run.scene));
  output::ColliderFrameExporter collider_frames(dir, run.world.model.colliders, collider_extension);
  for (const std::size_t collider : output::moving_colliders(run.world.model.colliders)) {
    const std::string pattern = output::collider_frame_pattern(collider, collider_extension);
    output::refuse_numbered_outputs_onto_inputs(
        dir, run.clock.frame_count, [&](int i) { return output::frame_file_name(pattern, i); }, scene_inputs(run.scene),
        "-o");
  }
  // One run at a time writes into the folder; the chunks of one export (--frames, same scene and format)
  // share it.
  const std::string format = mesh_format == output::MeshFormat::Obj ? "obj" : "ply";
  const output::FolderLock lock(dir, run_identity("export", run.scene, export_output_settings(format)),
                                planned.plan().frames.everything() ? output::FolderLock::Sharing::Exclusive
                                                                   : output::FolderLock::Sharing::SameRunOnly,
                                "export " + run.scene.source.string());
  output::remove_stale_temporaries(dir);
  if (!options.resume && planned.plan().frames.everything())
    remove_earlier_meshes(dir, exporter.frame_pattern(), collider_extension, scene_inputs(run.scene));
  output::write_colliders(dir, run.world.model.colliders, collider_extension);  // static: once, before the frames
  std::unique_ptr<ResumableRun> resumable;
  output::RunManifest manifest;
  std::vector<frames::FrameSink*> sinks = {&exporter, &collider_frames};
  if (options.resume) {
    // The manifest of the run to continue vouches for the meshes it wrote (size and checksum); a mesh it does
    // not vouch for is made again with all after it.
    const std::filesystem::path store = dir / ".softbody-resume", manifest_path = store / "frames.manifest";
    const std::string scene_hash = setup::hash_text(setup::simulation_hash(run.scene));
    manifest = output::RunManifest::read(manifest_path, scene_hash);
    std::error_code ec;
    if (manifest.intact() && std::filesystem::exists(store / "cache.json", ec))
      manifest.check_settings(export_output_settings(format));  // a run to continue: its format must be this
    const auto frame_done = [&](int frame) {
      if (!manifest.vouches_for(dir, exporter.frame_path(frame).filename().string())) return false;
      for (const std::filesystem::path& path : collider_frames.frame_paths(frame)) {
        if (!manifest.vouches_for(dir, path.filename().string())) return false;
      }
      return true;
    };
    resumable = std::make_unique<ResumableRun>(run, store, frame_done, dir);
    if (resumable->resumed_after() < 0)
      remove_earlier_meshes(dir, exporter.frame_pattern(), collider_extension, scene_inputs(run.scene));  // a new run
    std::vector<std::string> kept;
    for (int frame = 0; frame <= resumable->resumed_after(); ++frame) {
      kept.push_back(exporter.frame_path(frame).filename().string());
      for (const std::filesystem::path& path : collider_frames.frame_paths(frame))
        kept.push_back(path.filename().string());
    }
    manifest.start(manifest_path, scene_hash, export_output_settings(format), kept);
    const auto add_to_manifest = [&manifest](const std::filesystem::path& path, std::string_view bytes) {
      manifest.add(path.filename().string(), bytes);
    };
    exporter.after_each_file(add_to_manifest);
    collider_frames.after_each_file(add_to_manifest);
    sinks.push_back(&resumable->store_sink());
  }
  const frames::RunStats stats = frames::run_frames(run.world, run.clock, sinks, export_progress(options),
                                                    resumable ? resumable->plan() : planned.plan());
  if (resumable) resumable->remove_store();
  const frames::FrameSelection& chosen = planned.plan().frames;
  print_run_summary(run, stats,
                    "wrote " + exporter.frame_path(chosen.first()).string() + " .. " +
                        exporter.frame_path(chosen.last()).filename().string());
  return 0;
}

}  // namespace

Action register_export(CLI::App& parent) {
  auto options = std::make_shared<ExportOptions>();
  CLI::App* command = parent.add_subcommand(
      "export",
      "Run a scene and write the simulated mesh of every frame (OBJ or PLY), numbered like the PNGs, "
      "or per body one mesh and a point cache (PC2 or MDD)");
  add_scene_options(*command, options->scene);
  command->add_option("-o,--output", options->dir, "Output folder (default: <output.dir>/meshes)")->type_name("DIR");
  const std::map<std::string, ExportFormat> formats{
      {"obj", ExportFormat::Obj}, {"ply", ExportFormat::Ply}, {"pc2", ExportFormat::Pc2}, {"mdd", ExportFormat::Mdd}};
  command
      ->add_option("--format", options->format,
                   "obj (text, one object per body) or ply (binary, all bodies in one), one file per frame; "
                   "pc2 or mdd: per body DIR/body<N>.obj and a point cache DIR/body<N>.pc2 (.mdd) of every frame")
      ->transform(CLI::CheckedTransformer(formats, CLI::ignore_case))
      ->default_str("obj");
  add_frame_options(*command, options->frames);
  add_resume_option(*command, options->resume);
  add_profile_option(*command, options->profile);
  command->add_flag("--progress-lines", options->progress_lines,
                    "After each frame print \"progress DONE TOTAL\" on stdout, one line each (for programs that run "
                    "softbody, such as the Blender add-on)");
  command->footer(
      "Point caches (--format pc2 | mdd), for Blender's Mesh Cache modifier, Maya and Houdini:\n"
      "  DIR/body<N>.obj is the body's mesh at the first frame exported (vertex order = the cache's), DIR/body<N>.pc2\n"
      "  (little-endian, \"POINTCACHE2\", start frame = the first frame, one sample per frame) or DIR/body<N>.mdd\n"
      "  (big-endian, the simulated time of each frame) its positions, in the scene's units (m, y up).\n"
      "  The frames (all, or one --frames range) are kept in memory (12 bytes per vertex per frame) and the files\n"
      "  written whole at the end (also when the run diverges: the frames before it).\n"
      "Colliders, N the collider's index in the scene's \"colliders\", in world coordinates: a mesh as its triangles,\n"
      "  a box, sphere or capsule tessellated as rendered, a plane as a 20 m square around its point nearest the "
      "origin.\n"
      "  A static one: DIR/collider_<N>.obj (.ply with --format ply), written once.\n"
      "  A keyframed one (\"keys\"): DIR/collider_<N>_%04d.obj (.ply) per frame, numbered like the frames; with\n"
      "  --format pc2 | mdd, DIR/collider_<N>.obj (its surface at the first frame) and DIR/collider_<N>.pc2 (.mdd).");
  return [options] {
    const ProfiledRun profiled(options->profile);
    return run_export(*options);
  };
}

}  // namespace app
