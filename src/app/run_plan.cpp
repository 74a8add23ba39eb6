// Frame selection and the state cache as a run plan.
#include "app/run_plan.hpp"

#include "core/errors.hpp"
#include "setup/scene_hash.hpp"

namespace app {

struct PlannedFrames::Cache {
  std::filesystem::path dir;
  std::uint64_t scene_hash = 0;
  output::CacheManifest manifest;
  const sim::Model* model = nullptr;
};

void add_frame_options(CLI::App& command, FrameOptions& options) {
  command
      .add_option("--frames", options.frames,
                  "Only these frames: A-B, A, A-, -B, or a list such as 0-9,20-29 (the frames before the first "
                  "one are simulated silently, or taken from --from-cache)")
      ->type_name("RANGES");
  command
      .add_option("--from-cache", options.from_cache,
                  "Take the states from a cache that `softbody simulate SCENE --cache DIR` wrote, instead of "
                  "simulating (frames between cached states are simulated from the nearest one before)")
      ->type_name("DIR");
}

void add_resume_option(CLI::App& command, bool& resume) {
  command.add_flag("--resume", resume,
                   "Keep a state of every frame beside the outputs, and continue from the last complete frame "
                   "when an earlier run of the same command was killed; the outputs end as an uninterrupted "
                   "run's, byte for byte");
}

void check_resume_options(bool resume, const FrameOptions& options) {
  if (resume && (!options.frames.empty() || !options.from_cache.empty())) {
    throw softbody::InputError("--resume continues a whole run: use it without --frames and --from-cache");
  }
}

PlannedFrames::PlannedFrames(const PreparedRun& run, const FrameOptions& options) {
  const int last_frame = run.clock.frame_count;
  plan_.frames = options.frames.empty() ? frames::FrameSelection::all(last_frame)
                                        : frames::FrameSelection::parse(options.frames, last_frame);
  if (options.from_cache.empty()) return;
  cache_ = std::make_shared<Cache>();
  Cache& cache = *cache_;
  cache.dir = options.from_cache;
  cache.scene_hash = setup::simulation_hash(run.scene);
  cache.manifest = output::read_manifest(cache.dir, cache.scene_hash);
  cache.model = &run.world.model;
  if (cache.manifest.last_frame != last_frame) {
    throw softbody::InputError((cache.dir / "cache.json").string() + ": the cache runs to frame " +
                               std::to_string(cache.manifest.last_frame) + ", the scene to frame " +
                               std::to_string(last_frame));
  }
  // Every chosen frame's starting state must be there: refuse a gap now rather than halfway through a render.
  for (int frame = plan_.frames.first(); frame <= plan_.frames.last(); ++frame) {
    if (!plan_.frames.contains(frame)) continue;
    const int stored = output::cached_frame_at_or_before(cache.manifest, frame);
    if (!output::has_cached_state(cache.dir, stored)) {
      throw softbody::InputError(output::cached_state_path(cache.dir, stored).string() + ": missing: frame " +
                                 std::to_string(frame) + " starts from it (the cache keeps every " +
                                 std::to_string(cache.manifest.every) + " frames" +
                                 (cache.manifest.complete ? "" : "; its run did not finish") + ")");
    }
  }
  checkpoints_.latest_at_or_before = [cache_ptr = cache_.get()](int frame) {
    return output::cached_frame_at_or_before(cache_ptr->manifest, frame);
  };
  checkpoints_.load = [cache_ptr = cache_.get()](int frame) {
    return output::read_cached_state(cache_ptr->dir, frame, cache_ptr->scene_hash, *cache_ptr->model);
  };
  plan_.checkpoints = &checkpoints_;
}

}  // namespace app
