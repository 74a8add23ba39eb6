// Stable-dt table: the estimate next to a bisection on the real integrators.
#include "analysis/limits.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>

#include "analysis/stable_dt.hpp"
#include "mesh/generators.hpp"
#include "sim/step/stability.hpp"

namespace analysis {

std::vector<LimitBody> limit_bodies() {
  return {{"1 kg ball", "icosphere:3", 3000.0, 0.5, 30.0},
          {"stiff undamped", "icosphere:2", 5000.0, 0.0, 100.0},
          {"coarse damped", "icosphere:1", 1e4, 2.0, 30.0},
          {"fine ball", "icosphere:4", 3000.0, 0.5, 30.0}};
}

sim::World limit_world(const LimitBody& body, sim::IntegratorKind integrator, bool floor) {
  const mesh::TriMesh m = mesh::generate(body.mesh);
  double lowest = 0.0;
  for (const sim::Vec3& p : m.vertices) lowest = std::min(lowest, p.y());
  const double lift = floor ? 0.05 - lowest : 3.0;  // m
  std::vector<sim::Vec3> x0;
  for (const sim::Vec3& p : m.vertices) x0.push_back(p + sim::Vec3(0.0, lift, 0.0));
  sim::Body limit_body = sim::build_body(x0, m.triangles, 1.0);
  limit_body.params = {body.stiffness_N_per_m, body.damping_N_s_per_m, body.pressure_J};
  sim::Solver solver;
  solver.integrator = integrator;
  sim::World world =
      sim::one_body_world(sim::Vec3(0.0, -9.81, 0.0), floor ? std::optional<sim::Floor>(sim::Floor{}) : std::nullopt,
                          solver, std::move(limit_body), x0, sim::Vec3::Zero());
  shake(world, 0.5);
  return world;
}

std::vector<LimitRow> measure_limits(const std::vector<LimitBody>& bodies, int steps) {
  std::vector<LimitRow> rows;
  for (const LimitBody& body : bodies) {
    for (bool floor : {false, true}) {
      for (sim::IntegratorKind integrator :
           {sim::IntegratorKind::Euler, sim::IntegratorKind::Symplectic, sim::IntegratorKind::Verlet,
            sim::IntegratorKind::Rk4, sim::IntegratorKind::Rk45}) {
        const sim::World world = limit_world(body, integrator, floor);
        const double estimate = sim::estimate_stability(world.model, world.state).stable_dt(integrator);
        LimitRow row{body, integrator, floor, estimate, 0.0, 0.0};
        if (estimate > 0.0) {
          const StableDtMeasurement m = measure_stable_dt([&] { return limit_world(body, integrator, floor); },
                                                          0.1 * estimate, 2.0 * estimate, steps);
          row.measured_dt_s = m.stable_dt_s;
          row.unstable_dt_s = m.unstable_dt_s;
        }
        rows.push_back(row);
      }
    }
  }
  return rows;
}

void write_limits_csv(const std::vector<LimitRow>& rows, const std::filesystem::path& file) {
  std::ofstream out(file);
  out << "body,mesh,stiffness,damping,pressure,floor,integrator,estimate_dt,measured_stable_dt,measured_unstable_dt,"
         "estimate_over_measured\n";
  for (const LimitRow& r : rows) {
    char line[400];
    std::snprintf(line, sizeof line, "%s,%s,%g,%g,%g,%s,%s,%.4g,%.4g,%.4g,%.3f\n", r.body.name.c_str(),
                  r.body.mesh.c_str(), r.body.stiffness_N_per_m, r.body.damping_N_s_per_m, r.body.pressure_J,
                  r.floor ? "paper" : "none", sim::to_string(r.integrator).c_str(), r.estimate_dt_s, r.measured_dt_s,
                  r.unstable_dt_s, r.measured_dt_s > 0 ? r.estimate_dt_s / r.measured_dt_s : 0.0);
    out << line;
  }
}

}  // namespace analysis
