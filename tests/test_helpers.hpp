// Shared test helpers: scenes from JSON text, small hand-built worlds, running the CLI.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene.hpp"
#include "sim/step/world.hpp"

namespace testing_support {

// A scene from JSON text (comments allowed), validated as if read from `tests/<name>.json`.
scene::Scene scene_from_text(const std::string& json_text);

// The message of the InputError that reading the scene `json_text` throws ("" when it reads).
std::string scene_refusal(const std::string& json_text);

// The world of a scene given as JSON text.
sim::World world_from_text(const std::string& json_text);

// Runs the scene given as JSON text frame by frame at the step its solver asks for ("auto" resolved as the program
// resolves it), calling `at_frame(time_s, world)` after each frame (if given); returns the world at the end.
sim::World run_scene_frames(const std::string& json_text,
                            const std::function<void(double, const sim::World&)>& at_frame = nullptr);

// Runs the scene given as JSON text step by step at the step its solver asks for ("auto" resolved as the program
// resolves it), calling `after_step(world)` after every step; an adaptive integrator instead goes to every tick of a
// 0.1 ms clock over the first `adaptive_span_s`. `prepare(world)` (if given) adjusts the world before the step is
// resolved.
void run_scene_steps(const std::string& json_text, const std::function<void(const sim::World&)>& after_step,
                     const std::function<void(sim::World&)>& prepare = nullptr, double adaptive_span_s = 0.1);

// Σ over bodies of Σ m_i v_i [kg·m/s].
softbody::Vec3 total_momentum(const sim::World& world);

// Runs `n` steps of `dt`.
void run_steps(sim::World& world, long long n, double dt);

struct CommandResult {
  int exit_status = -1;
  std::string output;  // stdout and stderr together
};

// Runs a shell command line, capturing its stdout and stderr together.
CommandResult run_shell(const std::string& command);

// Runs the softbody executable with `arguments` (shell words), from the source directory.
CommandResult run_softbody(const std::string& arguments);

// A fresh, empty folder for one test's files under the build tree: <build>/test_scratch/<name>.<pid>
// (ctest runs tests in parallel processes, so each gets its own).
std::filesystem::path scratch_dir(const std::string& name);

// A path under the tests' data folder.
std::string data_path(const std::string& name);

}  // namespace testing_support
