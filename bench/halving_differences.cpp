// Convergence without a reference: one integrator at fixed steps dt, dt/2, dt/4, ..., the RMS distance over
// every frame and vertex between successive runs, and the observed order log2(d_k / d_{k+1}) (issue 15's sweep).
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/errors.hpp"
#include "frames/frame_clock.hpp"
#include "scene/scene_json.hpp"
#include "setup/build_world.hpp"
#include "sim/step/world.hpp"

namespace {

using softbody::Vec3;

struct Run {
  std::vector<std::vector<Vec3>> frames;  // positions at every frame, frame 0 included
  double dt_s = 0.0;                      // the frame-aligned step used
  bool diverged = false;
  int most_folded_edges = 0;  // the largest count of inward folds over the frames (body 0)
};

// Edges of body 0 whose two faces fold inward by more than 10° (a convex shell has none; a buckled one many).
int inward_folded_edges(const sim::World& world) {
  const auto& faces = world.model.bodies[0].topology.faces;
  const std::vector<Vec3>& x = world.state.x;
  std::map<std::pair<int, int>, std::vector<std::size_t>> faces_of_edge;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int a = faces[f][k], b = faces[f][(k + 1) % 3];
      faces_of_edge[{std::min(a, b), std::max(a, b)}].push_back(f);
    }
  }
  const auto normal = [&](std::size_t f) {
    const auto& t = faces[f];
    return Vec3((x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]).normalized());
  };
  const double cos_fold = std::cos(10.0 * 3.14159265358979 / 180.0);
  int folded = 0;
  for (const auto& [edge, two] : faces_of_edge) {
    if (two.size() != 2) continue;
    const Vec3 n0 = normal(two[0]), n1 = normal(two[1]);
    const auto& t1 = faces[two[1]];
    const int opposite = t1[0] + t1[1] + t1[2] - edge.first - edge.second;  // face 1's corner off the edge
    if ((x[opposite] - x[edge.first]).dot(n0) > 0.0 && n0.dot(n1) < cos_fold) ++folded;
  }
  return folded;
}

Run run_fixed_steps(const std::string& scene_file, std::vector<std::string> overrides, const std::string& integrator,
                    double dt_s, double duration_s) {
  overrides.push_back("solver.integrator=" + integrator);
  char dt_text[32];
  std::snprintf(dt_text, sizeof dt_text, "%.17g", dt_s);  // std::to_string would round 2.5e-6 to 0.000003
  overrides.push_back(std::string("solver.dt=") + dt_text);
  const scene::Scene scene = scene::load_scene(scene_file, overrides);
  const frames::FrameClock clock = frames::plan_frames(duration_s, scene.fps, dt_s);
  std::vector<std::string> notes;
  sim::World world = setup::build_world(scene, notes);
  Run run;
  run.dt_s = clock.dt_s;
  run.frames.push_back(world.state.x);
  try {
    for (int frame = 1; frame <= clock.frame_count; ++frame) {
      for (int s = 0; s < clock.steps_per_frame; ++s) world.step(clock.dt_s);
      run.frames.push_back(world.state.x);
      run.most_folded_edges = std::max(run.most_folded_edges, inward_folded_edges(world));
    }
  } catch (const softbody::DivergedError&) {
    run.diverged = true;
  }
  return run;
}

double rms_distance(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += (a[i] - b[i]).squaredNorm();
  return std::sqrt(sum / static_cast<double>(a.size()));
}

// RMS over frames 1.. of the per-frame RMS distance (the error measure of `softbody bench accuracy`).
double trajectory_distance(const Run& a, const Run& b) {
  const std::size_t frames = std::min(a.frames.size(), b.frames.size());
  double sum = 0.0;
  for (std::size_t f = 1; f < frames; ++f) sum += std::pow(rms_distance(a.frames[f], b.frames[f]), 2);
  return frames > 1 ? std::sqrt(sum / static_cast<double>(frames - 1)) : 0.0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Successive-halving differences of one integrator at fixed steps, and the observed orders"};
  std::string scene_file, integrator = "euler";
  std::vector<std::string> overrides;
  double duration_s = 1.2, coarsest_dt_s = 4e-5;
  int runs = 4;
  app.add_option("scene", scene_file, "Scene file")->required();
  app.add_option("--integrator", integrator, "Method (as solver.integrator)")->capture_default_str();
  app.add_option("--duration", duration_s, "Simulated seconds")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--dt", coarsest_dt_s, "Coarsest step [s], then halved")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--runs", runs, "Runs (dt, dt/2, ...)")->check(CLI::Range(2, 12))->capture_default_str();
  app.add_option("--set", overrides, "KEY=VALUE overrides, as for softbody");
  CLI11_PARSE(app, argc, argv);
  try {
    std::vector<Run> sweep;
    double dt = coarsest_dt_s;
    for (int k = 0; k < runs; ++k, dt /= 2.0)
      sweep.push_back(run_fixed_steps(scene_file, overrides, integrator, dt, duration_s));
    std::printf("%s: most edges folded inward > 10 deg at any frame, finest run: %d\n", integrator.c_str(),
                sweep.back().most_folded_edges);
    double previous = 0.0;
    for (int k = 0; k + 1 < runs; ++k) {
      const double d = trajectory_distance(sweep[k], sweep[k + 1]);
      std::printf("dt %.3e vs %.3e s: RMS distance %.3e m%s", sweep[k].dt_s, sweep[k + 1].dt_s, d,
                  sweep[k].diverged || sweep[k + 1].diverged ? " (a run diverged)" : "");
      if (k > 0) std::printf(", observed order %.2f", std::log2(previous / d));
      std::printf("\n");
      previous = d;
    }
  } catch (const softbody::InputError& error) {
    std::fprintf(stderr, "error: %s\n", error.what());
    return 2;
  }
  return 0;
}
