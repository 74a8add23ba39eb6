// --resume: a run keeps a state of every frame beside its outputs, so that after a kill (SIGKILL at any
// moment) the same command continues from the last frame whose state and outputs are both complete, and
// the final outputs are the bytes an uninterrupted run writes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>

#include "app/prepared_run.hpp"
#include "frames/frame_loop.hpp"
#include "output/state_cache.hpp"

namespace app {

class ResumableRun {
 public:
  // `store`: the folder of the run's states (created if missing). `frame_done(j)`: frame j's outputs are
  // complete on disk. `output_dir`: where the outputs go; the temporaries a killed run left there and in the
  // store are removed. Refuses (softbody::InputError) a store that holds another scene's states.
  ResumableRun(const PreparedRun& run, std::filesystem::path store, const std::function<bool(int)>& frame_done,
               const std::filesystem::path& output_dir);
  ResumableRun(const ResumableRun&) = delete;  // plan() points into this object
  ResumableRun& operator=(const ResumableRun&) = delete;

  // Frames 0 .. resumed_after() are done (-1: the run starts from frame 0).
  int resumed_after() const { return after_; }
  // The frames still to make, starting from the stored state of resumed_after().
  const frames::RunPlan& plan() const { return plan_; }
  // The sink that stores every frame's state (add it after the outputs' sinks: a frame's state is stored
  // once its outputs are).
  output::StateCacheSink& store_sink() { return *sink_; }
  // The run completed: the states are not needed any more.
  void remove_store() const;

 private:
  std::filesystem::path store_;
  std::uint64_t scene_hash_ = 0;
  int after_ = -1;
  std::unique_ptr<output::StateCacheSink> sink_;
  frames::Checkpoints checkpoints_;
  frames::RunPlan plan_;
};

}  // namespace app
