// build/bench_large_steps: the bounce of issue 13 at large steps: wall time per simulated second, Newton
// iterations, and the volume and centre of mass against a converged run, per integrator, level and dt.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "scene/scene_json.hpp"
#include "setup/build_world.hpp"
#include "sim/energy.hpp"
#include "sim/forces.hpp"
#include "sim/integrators/newton_euler.hpp"
#include "sim/stability.hpp"
#include "sim/world.hpp"

namespace {

using softbody::Vec3;

constexpr double kSampleInterval_s = 1.0 / 60;  // every dt measured divides it

// scenes/bounce.json as issue 13 measures it: friction floor, k 1000 N/m, c 1 N·s/m, nRT 50 J, 1 kg.
sim::World bounce_world(int level, sim::IntegratorKind integrator, double dt_s) {
  scene::Scene s = scene::load_scene(std::string(SOFTBODY_SOURCE_DIR) + "/scenes/bounce.json",
                                     {"floor.contact=friction", "bodies.0.stiffness=1000", "bodies.0.damping=1",
                                      "bodies.0.pressure=50", "bodies.0.mass=1",
                                      "bodies.0.mesh=icosphere:" + std::to_string(level)});
  s.solver.integrator = integrator;
  s.solver.dt_s = dt_s;
  std::vector<std::string> notes;
  return setup::build_world(s, notes);
}

struct Trajectory {
  std::vector<double> volume_m3;  // every kSampleInterval_s, from t = 0
  std::vector<Vec3> com_m;
  double wall_s = 0.0;            // stepping only
  long long steps = 0;
  sim::NewtonEuler::Statistics newton;
};

void sample(const sim::World& world, Trajectory& t) {
  const sim::Body& body = world.model.bodies[0];
  t.volume_m3.push_back(sim::enclosed_volume(body.topology.faces, world.model.of(body, world.state.x)));
  t.com_m.push_back(sim::centre_of_mass(body, world.model.of(body, world.state.x)));
}

Trajectory run(int level, sim::IntegratorKind integrator, double dt_s, double duration_s) {
  sim::World world = bounce_world(level, integrator, dt_s);
  Trajectory t;
  sample(world, t);
  const auto steps_per_sample = std::lround(kSampleInterval_s / dt_s);
  const auto samples = std::lround(duration_s / kSampleInterval_s);
  for (long s = 0; s < samples; ++s) {
    const auto start = std::chrono::steady_clock::now();
    for (long k = 0; k < steps_per_sample; ++k) world.step(dt_s);
    t.wall_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    t.steps += steps_per_sample;
    sample(world, t);
  }
  if (integrator == sim::IntegratorKind::Newton) {
    t.newton = dynamic_cast<const sim::NewtonEuler&>(*world.workspace.integrator).statistics();
  }
  return t;
}

// The converged run: symplectic Euler at its automatic dt (0.7 × the estimated stable step), made to divide
// the sample interval.
Trajectory reference_run(int level, double duration_s, double& dt_s) {
  const sim::World probe = bounce_world(level, sim::IntegratorKind::Symplectic, 1e-4);
  const sim::StabilityEstimate estimate = sim::estimate_stability(probe.model, probe.state);
  const double stable = sim::kAutoDtSafety * estimate.stable_dt(sim::IntegratorKind::Symplectic);
  dt_s = kSampleInterval_s / std::ceil(kSampleInterval_s / stable);
  return run(level, sim::IntegratorKind::Symplectic, dt_s, duration_s);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App cli("bench_large_steps: the bounce at large steps against a converged run (issue 13)");
  std::vector<int> levels{3, 5};
  std::vector<std::string> integrators{"newton", "implicit"};
  std::vector<int> steps_per_second{60, 240};
  double duration_s = 3.0;
  bool reference = true;
  cli.add_option("--levels", levels, "icosphere levels")->delimiter(',');
  cli.add_option("--integrators", integrators, "integrators")->delimiter(',');
  cli.add_option("--rates", steps_per_second, "steps per second (dt = 1/rate; must divide 60 or be a multiple)")
      ->delimiter(',');
  cli.add_option("--duration", duration_s, "simulated seconds");
  cli.add_flag("!--no-reference", reference, "skip the converged run (no errors reported)");
  CLI11_PARSE(cli, argc, argv);

  std::printf("integrator level dt_s steps wall_s_per_sim_s us_per_step newton_per_step newton_most halvings "
              "unconverged worst_volume_error end_volume_ratio worst_com_error_m\n");
  for (int level : levels) {
    Trajectory truth;
    double reference_dt = 0.0;
    if (reference) {
      truth = reference_run(level, duration_s, reference_dt);
      std::printf("reference %d %.4g %lld %.4g %.2f - - - - 0 1 0\n", level, reference_dt, truth.steps,
                  truth.wall_s / duration_s, 1e6 * truth.wall_s / static_cast<double>(truth.steps));
    }
    for (const std::string& name : integrators) {
      const std::optional<sim::IntegratorKind> integrator = sim::integrator_named(name);
      if (!integrator) {
        std::fprintf(stderr, "error: --integrators: expected integrator names, got %s\n", name.c_str());
        return 2;
      }
      for (int rate : steps_per_second) {
        const double dt = 1.0 / rate;
        const Trajectory t = run(level, *integrator, dt, duration_s);
        double worst_volume = 0.0, worst_com = 0.0;
        for (std::size_t s = 0; reference && s < t.volume_m3.size(); ++s) {
          worst_volume = std::max(worst_volume, std::abs(t.volume_m3[s] / truth.volume_m3[s] - 1.0));
          worst_com = std::max(worst_com, (t.com_m[s] - truth.com_m[s]).norm());
        }
        const double end_ratio = reference ? t.volume_m3.back() / truth.volume_m3.back() : NAN;
        const double per_step = t.newton.steps > 0 ? static_cast<double>(t.newton.iterations) / static_cast<double>(t.newton.steps) : 0.0;
        std::printf("%s %d %.4g %lld %.4g %.1f %.2f %d %lld %lld %.4f %.4f %.4f\n", name.c_str(), level, dt, t.steps,
                    t.wall_s / duration_s, 1e6 * t.wall_s / static_cast<double>(t.steps), per_step,
                    t.newton.most_iterations, t.newton.halvings, t.newton.unconverged_steps, worst_volume, end_ratio,
                    worst_com);
        std::fflush(stdout);
      }
    }
  }
  return 0;
}
