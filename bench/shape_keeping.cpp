// build/bench_shape_keeping: how well a body keeps its shape: a scene run to its end, and the largest deviation
// of each body from its initial shape once its rigid motion is removed (analysis/shape_deviation.hpp), relative
// to its size, at the end and the largest over the frames. Used for issue 17's "shapes that stay" figures.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "analysis/shape_deviation.hpp"
#include "core/errors.hpp"
#include "scene/scene_json.hpp"
#include "setup/build_world.hpp"
#include "sim/forces/forces.hpp"
#include "sim/step/step_plan.hpp"
#include "sim/step/world.hpp"

namespace {

using softbody::Vec3;

// The deviation of body b now from its shape in `initial` (all bodies' vertices).
analysis::ShapeDeviation deviation_of(const sim::World& world, std::size_t b, const std::vector<Vec3>& initial) {
  const sim::Body& body = world.model.bodies[b];
  return analysis::shape_deviation(world.model.of(body, std::span<const Vec3>(initial)),
                                   world.model.of(body, std::span<const Vec3>(world.state.x)), body.masses.kg);
}

int run(const std::string& scene_file, const std::vector<std::string>& overrides) {
  scene::Scene s = scene::load_scene(scene_file, overrides);
  std::vector<std::string> notes;
  sim::World world = setup::build_world(s, notes);
  for (const std::string& note : notes) std::printf("note: %s\n", note.c_str());
  const double frame_s = 1.0 / s.fps;
  double dt = sim::resolve_step(world.model, world.state, frame_s, scene_file).dt_s;
  const long steps_per_frame = std::max(1L, static_cast<long>(std::ceil(frame_s / dt - 1e-9)));
  dt = frame_s / static_cast<double>(steps_per_frame);
  const std::vector<Vec3> initial = world.state.x;
  const long frames = std::lround(s.duration_s * s.fps);
  std::vector<double> largest(world.model.bodies.size(), 0.0);
  const auto start = std::chrono::steady_clock::now();
  for (long frame = 1; frame <= frames; ++frame) {
    if (world.adaptive()) {
      world.advance_to(static_cast<double>(frame) * frame_s);
    } else {
      for (long k = 0; k < steps_per_frame; ++k) world.step(dt);
    }
    for (std::size_t b = 0; b < world.model.bodies.size(); ++b) {
      largest[b] = std::max(largest[b], deviation_of(world, b, initial).relative());
    }
  }
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("scene %s, %s, dt %.3g s, %.1f s simulated in %.1f s wall\n", scene_file.c_str(),
              sim::to_string(world.model.solver.integrator).c_str(), dt, s.duration_s, wall_s);
  for (std::size_t b = 0; b < world.model.bodies.size(); ++b) {
    const sim::Body& body = world.model.bodies[b];
    const analysis::ShapeDeviation end = deviation_of(world, b, initial);
    const double volume =
        sim::enclosed_volume(body.topology.faces, world.model.of(body, std::span<const Vec3>(world.state.x)));
    const double volume0 =
        sim::enclosed_volume(body.topology.faces, world.model.of(body, std::span<const Vec3>(initial)));
    std::printf(
        "body %zu: %d vertices, %zu bending links (k_b %.4g N/m, k %.4g N/m); size %.4g m; at the end "
        "largest deviation %.4f of the size (RMS %.4f), volume %.3f of the initial; largest over the frames %.4f\n",
        b, body.vertex_count, body.topology.bending_links.size(), body.params.bending_N_per_m,
        body.params.stiffness_N_per_m, end.body_size_m, end.relative(), end.rms_m / end.body_size_m, volume / volume0,
        largest[b]);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Run a scene and measure how far each body ends from its initial shape (rigid motion removed)"};
  std::string scene_file;
  std::vector<std::string> overrides;
  app.add_option("scene", scene_file, "Scene file")->required();
  app.add_option("--set", overrides, "KEY=VALUE overrides, as for softbody");
  CLI11_PARSE(app, argc, argv);
  try {
    return run(scene_file, overrides);
  } catch (const softbody::InputError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
}
