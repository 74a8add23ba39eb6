// `softbody simulate SCENE [--csv FILE] [--set ...]`: run without rendering, write the CSV.
#include <memory>

#include <cstdio>
#include <optional>
#include <vector>

#include "app/commands.hpp"
#include "app/prepared_run.hpp"
#include "app/resume.hpp"
#include "app/run_plan.hpp"
#include "core/errors.hpp"
#include "core/profile.hpp"
#include "frames/stop_request.hpp"
#include "output/atomic_file.hpp"
#include "output/csv_sink.hpp"
#include "output/state_cache.hpp"
#include "setup/scene_hash.hpp"

namespace app {
namespace {

struct SimulateOptions {
  SceneOptions scene;
  FrameOptions frames;
  std::string csv_file;
  std::string cache_dir;
  int cache_every = 1;
  bool resume = false;
  bool profile = false;
};

int run_simulate(const SimulateOptions& options) {
  // SIGINT / SIGTERM end setup after its phase in progress (nothing written) and the run within one step
  // (the frame in progress dropped); the outputs hold every complete frame.
  frames::stop_on_signals();
  PreparedRun run = softbody::profiled(softbody::ProfilePhase::setup, [&] { return prepare_run(options.scene); });
  check_resume_options(options.resume, options.frames);
  const PlannedFrames planned(run, options.frames);
  const std::filesystem::path csv =
      options.csv_file.empty() ? run.scene.output.dir / "simulation.csv" : std::filesystem::path(options.csv_file);
  const bool to_stdout = csv == "-";
  if (to_stdout && options.resume)
    throw softbody::InputError("--resume keeps a journal beside the CSV: use it with a --csv FILE, not -");
  if (!to_stdout) {
    output::refuse_output_onto_inputs(csv, scene_inputs(run.scene), "--csv");
    output::remove_stale_temporaries(csv.parent_path().empty() ? "." : csv.parent_path());
  }
  // --resume: the rows go to a journal as they are made, and every frame's state beside it.
  std::unique_ptr<ResumableRun> resumable;
  std::unique_ptr<output::CsvSink> csv_sink;
  if (options.resume) {
    const std::filesystem::path store = csv.string() + ".resume", journal = store / "rows.csv";
    const int journalled = output::CsvSink::journalled_through(journal, run.world.model.bodies.size());
    resumable = std::make_unique<ResumableRun>(
        run, store, [journalled](int frame) { return frame <= journalled; }, csv.parent_path());
    csv_sink = std::make_unique<output::CsvSink>(csv, journal, resumable->resumed_after());
  } else {
    csv_sink = std::make_unique<output::CsvSink>(csv);
  }
  std::vector<frames::FrameSink*> sinks = {csv_sink.get()};
  if (resumable) sinks.push_back(&resumable->store_sink());
  std::optional<output::StateCacheSink> cache;
  if (!options.cache_dir.empty()) {
    cache.emplace(options.cache_dir, setup::simulation_hash(run.scene), options.cache_every, run.clock.frame_count,
                  run.scene.fps, /*keep=*/resumable && resumable->resumed_after() >= 0);
    sinks.push_back(&*cache);
  }
  const frames::RunStats stats =
      frames::run_frames(run.world, run.clock, sinks, {}, resumable ? resumable->plan() : planned.plan());
  if (resumable) resumable->remove_store();
  std::string written = "wrote " + (to_stdout ? std::string("the CSV to standard output") : csv.string());
  if (cache) {
    char text[256];
    std::snprintf(text, sizeof text, "; cached %d states of %.1f kB each in %s", cache->states_written(),
                  static_cast<double>(cache->bytes_per_state()) / 1e3, options.cache_dir.c_str());
    written += text;
  }
  print_run_summary(run, stats, written, to_stdout ? stderr : stdout);
  return 0;
}

}  // namespace

Action register_simulate(CLI::App& parent) {
  auto options = std::make_shared<SimulateOptions>();
  CLI::App* command =
      parent.add_subcommand("simulate", "Run a scene without rendering and write one CSV row per body per frame");
  add_scene_options(*command, options->scene);
  command
      ->add_option("--csv", options->csv_file,
                   "CSV output file (default: <output.dir>/simulation.csv; - for standard output; a device or "
                   "FIFO is written through)")
      ->type_name("FILE");
  command
      ->add_option("--cache", options->cache_dir,
                   "Also write the state of every frame to DIR (state_NNNNNN.bin and cache.json), for "
                   "`render --from-cache` and farm rendering")
      ->type_name("DIR");
  command
      ->add_option("--cache-every", options->cache_every,
                   "Keep only every Nth frame's state (and the last); frames between are simulated again from "
                   "the one before when rendered")
      ->check(CLI::Range(1, 1000000))
      ->type_name("N");
  add_frame_options(*command, options->frames);
  add_resume_option(*command, options->resume);
  add_profile_option(*command, options->profile);
  command->footer(
      "CSV columns: frame,time,body,com_x,com_y,com_z,vel_x,vel_y,vel_z,volume,kinetic_energy,total_energy,min_y\n"
      "  vel_* is the centre-of-mass velocity; total_energy = kinetic + gravitational (y relative to 0)\n"
      "  + spring + gas (-nRT ln(V/V0)). Frame 0 is the initial state.");
  return [options] {
    const ProfiledRun profiled(options->profile);
    return run_simulate(*options);
  };
}

}  // namespace app
