// Finding where a killed run continues.
#include "app/resume.hpp"

#include <algorithm>
#include <cstdio>

#include "core/errors.hpp"
#include "output/atomic_file.hpp"
#include "setup/scene_hash.hpp"

namespace app {

ResumableRun::ResumableRun(const PreparedRun& run, std::filesystem::path store,
                           const std::function<bool(int)>& frame_done, const std::filesystem::path& output_dir)
    : store_(std::move(store)), scene_hash_(setup::simulation_hash(run.scene)) {
  output::remove_stale_temporaries(output_dir.empty() ? "." : output_dir);
  output::remove_stale_temporaries(store_);
  const int last_frame = run.clock.frame_count;
  std::error_code ec;
  if (std::filesystem::exists(store_ / "cache.json", ec)) {
    const output::CacheManifest manifest = output::read_manifest(store_, scene_hash_);  // refuses another scene
    if (manifest.last_frame == last_frame) {
      // The last frame whose state is stored and whose outputs, and all before, are complete.
      int done = -1;
      while (done < last_frame && frame_done(done + 1)) ++done;
      for (int k = done; k >= 0; --k) {
        if (output::has_cached_state(store_, k)) {
          after_ = std::min(k, last_frame - 1);  // at least the last frame is made again: the run's end runs
          break;
        }
      }
    }
  }
  sink_ = std::make_unique<output::StateCacheSink>(store_, scene_hash_, 1, last_frame, run.scene.fps,
                                                   /*keep=*/after_ >= 0);
  if (after_ < 0) return;
  std::fprintf(stderr, "note: --resume: frames 0..%d are complete; continuing from frame %d's stored state\n", after_,
               after_);
  plan_.frames = frames::FrameSelection::parse(std::to_string(after_ + 1) + "-", last_frame, "--resume");
  checkpoints_.latest_at_or_before = [after = after_](int) { return after; };
  checkpoints_.load = [this, &run](int frame) {
    return output::read_cached_state(store_, frame, scene_hash_, run.world.model);
  };
  plan_.checkpoints = &checkpoints_;
}

void ResumableRun::remove_store() const { std::filesystem::remove_all(store_); }

}  // namespace app
