// bench_peers_bullet: Bullet's btSoftBody (kPR pressure, its own links) on one of bench/peers' scenes, with one row
// per frame in softbody's CSV columns (frame,time,body,com_x,com_y,com_z,volume) for bench/csv_errors.py.
//   bench_peers_bullet SCENE.json LEVEL STEPS_PER_S POSITION_ITERATIONS CSV
// Prints the stepping thread's CPU s per simulated s. The scene gives the mesh (icosphere:LEVEL), mass, nRT (as kPR),
// start, gravity and whether there is a floor; Bullet's links and damping are its own, not the scene's springs.
#include <cmath>
#include <cstdio>
#include <ctime>
#include <exception>
#include <numeric>
#include <string>
#include <vector>

#include "bullet_pressure_body.hpp"
#include "scene/scene_json.hpp"
#include "setup/build_world.hpp"
#include "sim/forces/forces.hpp"

namespace {

using softbody::Vec3;

double thread_cpu_s() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

bench::BulletBodySpec spec_of(const scene::Scene& s, int position_iterations) {
  std::vector<std::string> notes;
  const sim::World world = setup::build_world(s, notes);
  bench::BulletBodySpec spec;
  spec.vertices_m = world.state.x;
  spec.triangles = world.model.bodies.at(0).topology.faces;
  spec.mass_kg = s.bodies.at(0).mass_kg;
  spec.pressure = s.bodies.at(0).pressure_J;
  spec.gravity_m_per_s2 = s.gravity_m_per_s2.y();
  spec.floor = s.floor.has_value();
  if (s.floor) spec.floor_height_m = s.floor->height_m;
  spec.velocity_m_per_s = s.bodies.at(0).velocity_m_per_s;
  spec.position_iterations = position_iterations;
  return spec;
}

void write_frame(std::FILE* csv, long frame, double time_s, const bench::BulletPressureBody& bullet,
                 const bench::BulletBodySpec& spec, const std::vector<double>& masses) {
  const std::vector<Vec3> x = bullet.node_positions_m();
  Vec3 weighted = Vec3::Zero();
  for (std::size_t i = 0; i < x.size(); ++i) weighted += masses[i] * x[i];
  const Vec3 com = weighted / std::accumulate(masses.begin(), masses.end(), 0.0);  // Σ m_i x_i / M [m]
  std::fprintf(csv, "%ld,%.17g,0,%.17g,%.17g,%.17g,%.17g\n", frame, time_s, com.x(), com.y(), com.z(),
               sim::enclosed_volume(spec.triangles, x));
}

int run(const std::string& scene_path, int level, long steps_per_s, int position_iterations, const std::string& out) {
  const scene::Scene s = scene::load_scene(scene_path, {"bodies.0.mesh=icosphere:" + std::to_string(level)});
  const bench::BulletBodySpec spec = spec_of(s, position_iterations);
  bench::BulletPressureBody bullet(spec);
  const std::vector<double> masses = bullet.node_masses_kg();
  const long steps_per_frame = steps_per_s / s.fps;
  if (steps_per_frame * s.fps != steps_per_s) {
    std::fprintf(stderr, "bench_peers_bullet: %ld steps/s is not a multiple of the scene's fps %d\n", steps_per_s,
                 s.fps);
    return 2;
  }
  std::FILE* csv = std::fopen(out.c_str(), "w");
  if (!csv) {
    std::fprintf(stderr, "bench_peers_bullet: cannot write %s\n", out.c_str());
    return 2;
  }
  std::fprintf(csv, "frame,time,body,com_x,com_y,com_z,volume\n");
  write_frame(csv, 0, 0.0, bullet, spec, masses);
  const long frames = std::lround(s.duration_s * s.fps);
  const double dt = 1.0 / static_cast<double>(steps_per_s);
  double cpu_s = 0.0;
  for (long f = 1; f <= frames; ++f) {
    const double start = thread_cpu_s();
    for (long k = 0; k < steps_per_frame; ++k) bullet.step(dt);
    cpu_s += thread_cpu_s() - start;
    write_frame(csv, f, static_cast<double>(f) / s.fps, bullet, spec, masses);
  }
  std::fclose(csv);
  std::printf("cpu_per_sim_s=%.6f\n", cpu_s / s.duration_s);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 6) {
    std::fprintf(stderr, "usage: bench_peers_bullet SCENE.json LEVEL STEPS_PER_S POSITION_ITERATIONS CSV\n");
    return 2;
  }
  try {
    return run(argv[1], std::stoi(argv[2]), std::stol(argv[3]), std::stoi(argv[4]), argv[5]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_peers_bullet: %s\n", e.what());
    return 2;
  }
}
