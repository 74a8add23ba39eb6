// The CLI's subcommands: each registers its options on the parser and runs when chosen.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "output/input_guard.hpp"
#include "scene/scene.hpp"

namespace app {

// Options every scene command takes: the scene file and --set overrides.
struct SceneOptions {
  std::string scene_file;
  std::vector<std::string> overrides;
};

// Adds SCENE and --set PATH=VALUE (repeatable) to a subcommand.
void add_scene_options(CLI::App& command, SceneOptions& options);

// The files a run of `scene` reads (the scene file, each body's mesh file), which no output may replace
// (output/input_guard.hpp).
std::vector<output::InputFile> scene_inputs(const scene::Scene& scene);

// Adds --profile to a subcommand (simulate, render, export).
void add_profile_option(CLI::App& command, bool& profile);

// While it lives, the phases' counters (core/profile.hpp) run when `on`; when it goes, on every path (done,
// interrupted, diverged, failed), their table goes to standard error.
class ProfiledRun {
 public:
  explicit ProfiledRun(bool on);
  ~ProfiledRun();
  ProfiledRun(const ProfiledRun&) = delete;
  ProfiledRun& operator=(const ProfiledRun&) = delete;

 private:
  bool on_;
};

// Each returns the action to run when its subcommand is chosen; the action returns the exit status.
using Action = std::function<int()>;
Action register_simulate(CLI::App& parent);
Action register_export(CLI::App& parent);
Action register_bench(CLI::App& parent);

// Makes `command` the accuracy benchmark (softbody bench accuracy, and build/bench_accuracy).
Action add_accuracy_options(CLI::App& command);
Action register_render(CLI::App& parent);
Action register_info(CLI::App& parent);
Action register_prepare(CLI::App& parent);
Action register_schema(CLI::App& parent);

}  // namespace app
