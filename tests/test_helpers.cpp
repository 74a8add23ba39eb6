// Shared test helpers.
#include "test_helpers.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>

#include "core/errors.hpp"
#include "frames/frame_clock.hpp"
#include "scene/scene_json.hpp"
#include "setup/build_world.hpp"
#include "sim/step/diagnostics.hpp"
#include "sim/step/step_plan.hpp"

namespace testing_support {

scene::Scene scene_from_text(const std::string& json_text) {
  const std::filesystem::path file = std::filesystem::path(SOFTBODY_SOURCE_DIR) / "tests" / "inline.json";
  return scene::scene_from_json(scene::parse_scene_text(json_text, file), file);
}

std::string scene_refusal(const std::string& json_text) {
  try {
    scene_from_text(json_text);
  } catch (const softbody::InputError& error) {
    return error.what();
  }
  return "";
}

sim::World world_from_text(const std::string& json_text) {
  std::vector<std::string> notes;
  return setup::build_world(scene_from_text(json_text), notes);
}

sim::World run_scene_frames(const std::string& json_text,
                            const std::function<void(double, const sim::World&)>& at_frame) {
  const scene::Scene scene = scene_from_text(json_text);
  std::vector<std::string> notes;
  sim::World world = setup::build_world(scene, notes);
  sim::resolve_step(world.model, world.state, 1.0 / scene.fps, "test");
  const frames::FrameClock clock = frames::plan_frames(scene.duration_s, scene.fps, world.model.solver.dt_s);
  for (int frame = 1; frame <= clock.frame_count; ++frame) {
    if (world.adaptive()) {
      world.advance_to(frame * clock.frame_interval_s);
    } else {
      run_steps(world, clock.steps_per_frame, clock.dt_s);
    }
    if (at_frame) at_frame(frame * clock.frame_interval_s, world);
  }
  return world;
}

void run_scene_steps(const std::string& json_text, const std::function<void(const sim::World&)>& after_step,
                     const std::function<void(sim::World&)>& prepare, double adaptive_span_s) {
  const scene::Scene scene = scene_from_text(json_text);
  std::vector<std::string> notes;
  sim::World world = setup::build_world(scene, notes);
  if (prepare) prepare(world);
  sim::resolve_step(world.model, world.state, 1.0 / scene.fps, "test");
  if (world.adaptive()) {
    constexpr double kTick_s = 1e-4;
    const auto ticks = static_cast<int>(std::lround(adaptive_span_s / kTick_s));
    for (int tick = 1; tick <= ticks; ++tick) {
      world.advance_to(tick * kTick_s);
      after_step(world);
    }
    return;
  }
  const frames::FrameClock clock = frames::plan_frames(scene.duration_s, scene.fps, world.model.solver.dt_s);
  const long long steps = static_cast<long long>(clock.frame_count) * clock.steps_per_frame;
  for (long long s = 0; s < steps; ++s) {
    world.step(clock.dt_s);
    after_step(world);
  }
}

softbody::Vec3 total_momentum(const sim::World& world) {
  softbody::Vec3 p = softbody::Vec3::Zero();
  for (std::size_t b = 0; b < world.model.bodies.size(); ++b)
    p += sim::diagnose(world.model, world.state, b).momentum_kg_m_per_s;
  return p;
}

void run_steps(sim::World& world, long long n, double dt) {
  for (long long i = 0; i < n; ++i) world.step(dt);
}

CommandResult run_shell(const std::string& command) {
  CommandResult result;
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) result.output += buffer.data();
  const int status = ::pclose(pipe);
  result.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

CommandResult run_softbody(const std::string& arguments) {
  return run_shell("cd " SOFTBODY_SOURCE_DIR " && " SOFTBODY_EXE " " + arguments);
}

std::filesystem::path scratch_dir(const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::path(SOFTBODY_TEST_SCRATCH_DIR) / (name + "." + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

std::string data_path(const std::string& name) { return std::string(SOFTBODY_TEST_DATA) + "/" + name; }

}  // namespace testing_support
