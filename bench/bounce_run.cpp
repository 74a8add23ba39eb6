// Builds, steps and samples the issue-13 bounce for bench_large_steps: ours per integrator, and Bullet's.
#include "bounce_run.hpp"

#include <chrono>
#include <cmath>
#include <ctime>
#include <exception>
#include <numeric>

#include "bullet_pressure_body.hpp"
#include "scene/scene_json.hpp"
#include "setup/build_world.hpp"
#include "sim/forces/energy.hpp"
#include "sim/forces/forces.hpp"
#include "sim/step/step_plan.hpp"

namespace bench {

namespace {

using softbody::Vec3;

const std::string kBounceScene = std::string(SOFTBODY_SOURCE_DIR) + "/scenes/bounce.json";

scene::Scene bounce_scene(const BounceSetup& setup) {
  scene::Scene s = scene::load_scene(
      kBounceScene, {"bodies.0.stiffness=1000", "bodies.0.damping=1", "bodies.0.pressure=50", "bodies.0.mass=1",
                     "fps=60", "solver.threads=1", "bodies.0.mesh=icosphere:" + std::to_string(setup.level)});
  s.floor->contact = setup.contact;
  s.solver.integrator = setup.integrator;
  s.solver.tolerance = setup.tolerance;
  return s;
}

// The largest step <= dt_s that divides the sample interval.
double sample_aligned(double dt_s) {
  return kBounceSampleInterval_s / std::ceil(kBounceSampleInterval_s / dt_s * (1.0 - 1e-9));
}

// As "dt": "auto" in frames of the sample interval (xpbd: its automatic substeps).
double automatic_dt(sim::World& world) {
  world.model.solver.dt_auto = true;
  const sim::StepPlan plan = sim::resolve_step(world.model, world.state, kBounceSampleInterval_s, kBounceScene);
  return plan.substeps > 0 ? plan.dt_s : sample_aligned(plan.dt_s);
}

void sample(const std::vector<Vec3>& x, const std::vector<sim::Triangle>& faces, const Vec3& com, BounceRecord& r) {
  r.volume_m3.push_back(sim::enclosed_volume(faces, x));
  r.com_m.push_back(com);
  r.x_m.push_back(x);
}

void sample(const sim::World& world, BounceRecord& r) {
  const sim::Body& body = world.model.bodies[0];
  const auto x = world.model.of(body, world.state.x);
  sample(std::vector<Vec3>(x.begin(), x.end()), body.topology.faces, sim::centre_of_mass(body, x), r);
}

// Wall and this thread's CPU seconds spent since construction, added to a record by stop().
class StepTimer {
 public:
  StepTimer() : wall_(std::chrono::steady_clock::now()), cpu_(thread_cpu_s()) {}
  void stop(BounceRecord& r) const {
    r.wall_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_).count();
    r.cpu_s += thread_cpu_s() - cpu_;
  }

 private:
  static double thread_cpu_s() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
  }
  std::chrono::steady_clock::time_point wall_;
  double cpu_;
};

}  // namespace

sim::World bounce_world(const BounceSetup& setup, double& dt_s) {
  const scene::Scene s = bounce_scene(setup);
  std::vector<std::string> notes;
  sim::World world = setup::build_world(s, notes);
  dt_s = setup.dt_s > 0.0 ? sample_aligned(setup.dt_s) : automatic_dt(world);
  world.model.solver.dt_s = dt_s;
  world.state.next_dt_s = dt_s;
  return world;
}

BounceRecord record_bounce(const BounceSetup& setup, double duration_s) {
  BounceRecord r;
  sim::World world = bounce_world(setup, r.dt_s);
  const bool adaptive = world.adaptive();
  const long steps_per_sample = std::lround(kBounceSampleInterval_s / r.dt_s);
  const long samples = std::lround(duration_s / kBounceSampleInterval_s);
  sample(world, r);
  try {
    for (long s = 1; s <= samples; ++s) {
      const StepTimer timer;
      if (adaptive) {
        world.advance_to(static_cast<double>(s) * kBounceSampleInterval_s);
      } else {
        for (long k = 0; k < steps_per_sample; ++k) world.step(r.dt_s);
      }
      timer.stop(r);
      sample(world, r);
    }
  } catch (const std::exception& e) {
    r.failure = e.what();
  }
  r.steps = world.state.steps;
  if (adaptive && r.steps > 0) r.dt_s = world.state.time_s / static_cast<double>(r.steps);
  return r;
}

BounceRecord record_bullet_bounce(int level, double dt_s, double duration_s) {
  BounceSetup setup;
  setup.level = level;
  const scene::Scene s = bounce_scene(setup);
  std::vector<std::string> notes;
  const sim::World ours = setup::build_world(s, notes);
  BulletBodySpec spec;
  spec.vertices_m = ours.state.x;
  spec.triangles = ours.model.bodies.at(0).topology.faces;
  spec.mass_kg = s.bodies.at(0).mass_kg;
  spec.pressure = s.bodies.at(0).pressure_J;
  spec.gravity_m_per_s2 = s.gravity_m_per_s2.y();
  spec.floor_height_m = s.floor->height_m;
  spec.velocity_m_per_s = s.bodies.at(0).velocity_m_per_s;
  BulletPressureBody bullet(spec);

  BounceRecord r;
  r.dt_s = dt_s;
  const std::vector<double> masses = bullet.node_masses_kg();
  const double total_mass = std::accumulate(masses.begin(), masses.end(), 0.0);
  auto sample_bullet = [&] {
    const std::vector<Vec3> x = bullet.node_positions_m();
    Vec3 weighted = Vec3::Zero();
    for (std::size_t i = 0; i < x.size(); ++i) weighted += masses[i] * x[i];
    sample(x, spec.triangles, weighted / total_mass, r);  // Σ m_i x_i / M [m]
    for (const Vec3& p : x) {
      if (!p.allFinite()) return false;
    }
    return true;
  };
  sample_bullet();
  const long steps_per_sample = std::lround(kBounceSampleInterval_s / dt_s);
  const long samples = std::lround(duration_s / kBounceSampleInterval_s);
  for (long k = 1; k <= samples; ++k) {
    const StepTimer timer;
    for (long j = 0; j < steps_per_sample; ++j) bullet.step(dt_s);
    timer.stop(r);
    r.steps += steps_per_sample;
    if (!sample_bullet()) {
      r.failure = "non-finite node position";
      break;
    }
  }
  return r;
}

}  // namespace bench
