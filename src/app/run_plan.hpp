// The frame options every scene command shares: which frames (--frames) and where their states come from
// (--from-cache), turned into a frames::RunPlan.
#pragma once

#include <memory>
#include <string>

#include <CLI/CLI.hpp>

#include "app/prepared_run.hpp"
#include "frames/frame_loop.hpp"
#include "output/state_cache.hpp"

namespace app {

struct FrameOptions {
  std::string frames;      // --frames A-B,...: empty = all
  std::string from_cache;  // --from-cache DIR: empty = simulate
};

// Adds --frames and --from-cache to a subcommand.
void add_frame_options(CLI::App& command, FrameOptions& options);

// Adds --resume to a subcommand; check_resume_options() refuses it with --frames or --from-cache (a resumed
// run continues a whole run).
void add_resume_option(CLI::App& command, bool& resume);
void check_resume_options(bool resume, const FrameOptions& options);

// The plan of `run` for these options. With --from-cache, the cache's manifest is read and checked against
// the scene (its hash and last frame) and every chosen frame's starting state must be in the cache (a missing
// one is refused, naming the file). Keeps what the plan points to.
class PlannedFrames {
 public:
  PlannedFrames(const PreparedRun& run, const FrameOptions& options);
  PlannedFrames(const PlannedFrames&) = delete;  // plan() points into this object
  PlannedFrames& operator=(const PlannedFrames&) = delete;
  const frames::RunPlan& plan() const { return plan_; }
  bool from_cache() const { return cache_ != nullptr; }

 private:
  struct Cache;
  std::shared_ptr<Cache> cache_;
  frames::Checkpoints checkpoints_;
  frames::RunPlan plan_;
};

}  // namespace app
