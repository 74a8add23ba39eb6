// Stress sweep: building each case's world, running it, classifying how it ended, CSV and gnuplot maps.
#include "analysis/stress.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>

#include "analysis/stable_dt.hpp"
#include "core/errors.hpp"
#include "mesh/generators.hpp"
#include "sim/step/diagnostics.hpp"
#include "sim/step/diverged.hpp"
#include "sim/step/stability.hpp"
#include "sim/step/world.hpp"

namespace analysis {
namespace {

using sim::IntegratorKind;
using softbody::Vec3;

constexpr double kMapDuration_s = 0.3, kGroupDuration_s = 0.5;
constexpr long long kMostSteps = 3000;  // fixed-step runs: at most this many steps (tiny dt: a short run)
constexpr long long kMostAdaptiveSteps = 20000;

// Odd meshes: a sphere squashed to 15 % height, stretched 4×, or with slivers and tiny triangles
// (every seventh vertex moved 90 % of the way towards a neighbour).
mesh::TriMesh shape_mesh(const std::string& shape) {
  if (shape == "flattened" || shape == "elongated" || shape == "tiny-triangles") {
    mesh::TriMesh m = mesh::icosphere(2);
    if (shape == "flattened")
      for (Vec3& p : m.vertices) p.y() *= 0.15;
    if (shape == "elongated")
      for (Vec3& p : m.vertices) p.x() *= 4.0;
    if (shape == "tiny-triangles") {
      std::vector<bool> moved(m.vertices.size(), false);
      for (const auto& t : m.triangles) {
        if (t[0] % 7 != 0 || moved[t[0]]) continue;
        m.vertices[t[0]] += 0.9 * (m.vertices[t[1]] - m.vertices[t[0]]);
        moved[t[0]] = true;
      }
    }
    return m;
  }
  return mesh::generate(shape);
}

sim::World build_case_world(const StressCase& c) {
  const mesh::TriMesh m = shape_mesh(c.shape);
  double lowest = std::numeric_limits<double>::infinity();
  for (const Vec3& p : m.vertices) lowest = std::min(lowest, p.y());
  const double clearance = c.drop_speed_m_per_s > 0.0 ? 1.0 : 0.05;  // m between the floor and the body
  std::vector<Vec3> x0;
  for (const Vec3& p : m.vertices) x0.push_back(p + Vec3(0.0, clearance - lowest, 0.0));
  sim::Solver solver;
  solver.integrator = c.integrator;
  solver.tolerance = 1e-4;
  solver.retry = c.retry;
  sim::Body body = sim::build_body(x0, m.triangles, 1.0);
  body.params = {c.stiffness_N_per_m, c.damping_N_s_per_m, c.pressure_J};
  sim::World world = sim::one_body_world(Vec3(0.0, -9.81, 0.0), sim::Floor{}, solver, std::move(body), x0,
                                         Vec3(0.0, -c.drop_speed_m_per_s, 0.0));
  shake(world, 0.3);
  return world;
}

// The dt a case runs at: fixed, or a factor of the estimate (no limit: 1/120 s; none: 1e-4 s).
double case_dt(const StressCase& c, double estimate) {
  if (c.dt_s > 0.0) return c.dt_s;
  if (estimate == sim::StabilityEstimate::kUnlimited) return c.dt_factor / 120.0;
  if (estimate == 0.0) return c.dt_factor * 1e-4;
  return c.dt_factor * estimate;
}

bool state_is_finite(const sim::World& world) {
  for (std::size_t i = 0; i < world.state.x.size(); ++i) {
    if (!world.state.x[i].allFinite() || !world.state.v[i].allFinite()) return false;
  }
  for (std::size_t b = 0; b < world.model.bodies.size(); ++b) {
    const sim::BodyDiagnostics d = sim::diagnose(world.model, world.state, b);
    if (!std::isfinite(d.total_J()) || !std::isfinite(d.volume_m3) || !d.com_m.allFinite()) return false;
  }
  return true;
}

// Runs the case to its end; throws what the world throws.
void run_world(sim::World& world, StressResult& r, double duration_s) {
  if (world.adaptive()) {
    world.state.next_dt_s = r.dt_s;
    for (int chunk = 1; chunk <= 50 && world.state.steps < kMostAdaptiveSteps; ++chunk) {
      world.advance_to(chunk * duration_s / 50.0);
      r.deepest_penetration_m = std::max(r.deepest_penetration_m, world.workspace.deepest_floor_penetration_m);
    }
  } else {
    const long long steps = std::min(kMostSteps, static_cast<long long>(std::ceil(duration_s / r.dt_s)));
    for (long long s = 0; s < steps; ++s) {
      world.step(r.dt_s);
      r.deepest_penetration_m = std::max(r.deepest_penetration_m, world.workspace.deepest_floor_penetration_m);
    }
  }
}

}  // namespace

std::string to_string(Outcome outcome) {
  switch (outcome) {
    case Outcome::Stable: return "stable";
    case Outcome::Guarded: return "guarded";
    case Outcome::Failed: return "failed";
  }
  return "?";
}

std::vector<StressCase> stress_cases(bool quick) {
  std::vector<StressCase> cases;
  const std::vector<double> stiffness =
      quick ? std::vector<double>{1e2, 1e4, 1e6} : std::vector<double>{1e1, 1e2, 1e3, 1e4, 1e5, 1e6};
  std::vector<double> dts;
  for (int i = 0; i <= (quick ? 4 : 12); ++i) dts.push_back(1e-6 * std::pow(10.0, i * (quick ? 1.0 : 1.0 / 3.0)));
  for (const sim::IntegratorInfo& listed : sim::kIntegrators) {
    const IntegratorKind integrator = listed.kind;
    // A position-based integrator (xpbd) also at a frame's and a quarter frame's substep of 1/60 s frames.
    std::vector<double> integrator_dts = dts;
    if (listed.position_based) {
      integrator_dts.push_back(1.0 / 240.0);
      integrator_dts.push_back(1.0 / 60.0);
    }
    for (double damping : quick ? std::vector<double>{0.5} : std::vector<double>{0.5, 0.0}) {
      for (double k : stiffness) {
        for (double dt : integrator_dts) {
          StressCase c{"map", "icosphere:1", integrator, k, damping, 30.0};
          c.dt_s = dt;
          cases.push_back(c);
        }
      }
    }
    const std::vector<double> factors = quick ? std::vector<double>{1.0} : std::vector<double>{0.5, 1.0, 2.0, 8.0};
    for (double f : factors) {
      auto add = [&](StressCase c) {
        c.integrator = integrator;
        c.dt_factor = f;
        cases.push_back(c);
      };
      for (int level = 0; level <= (quick ? 3 : 5); ++level) add({"mesh", "icosphere:" + std::to_string(level)});
      for (double p : {0.0, 1.0, 30.0, 1e3, 1e5}) add({"pressure", "icosphere:2", integrator, 3000.0, 0.5, p});
      for (double c : {0.0, 0.05, 1.0, 30.0, 1000.0}) add({"damping", "icosphere:2", integrator, 3000.0, c, 30.0});
      for (double v : {5.0, 20.0, 50.0}) add({"drop", "icosphere:2", integrator, 3000.0, 0.5, 30.0, v});
      add({"drop", "icosphere:2", integrator, 3e5, 5.0, 300.0, 50.0});
      for (const char* shape : {"flattened", "elongated", "tiny-triangles", "cube:3", "torus:16,8"}) {
        add({"odd", shape});
      }
      if (integrator != IntegratorKind::Rk45) {
        StressCase retry{"retry", "icosphere:2", integrator, 3000.0, 0.5, 30.0, 20.0, true};
        add(retry);
      }
    }
  }
  return cases;
}

StressResult run_stress_case(const StressCase& spec) {
  StressResult r;
  r.spec = spec;
  const auto start = std::chrono::steady_clock::now();
  try {
    sim::World world = build_case_world(spec);
    r.vertices = static_cast<int>(world.state.x.size());
    r.estimate_dt_s = sim::estimate_stability(world.model, world.state).stable_dt(spec.integrator);
    r.dt_s = case_dt(spec, r.estimate_dt_s);
    r.shortest_edge_m = sim::body_stats(world.model.bodies[0], world.state.x).edge_min_m;
    try {
      run_world(world, r, spec.group == "map" ? kMapDuration_s : kGroupDuration_s);
      r.outcome = state_is_finite(world) ? Outcome::Stable : Outcome::Failed;
      if (r.outcome == Outcome::Failed) r.message = "silent non-finite state";
    } catch (const sim::DivergedError& e) {
      r.message = e.what();
      // A clear stop names the body and what went wrong (then the message gives the stable dt too); an
      // adaptive step that underflowed without a finding of the guard's says nothing of either.
      const sim::DivergenceReport& report = e.report();
      const bool clear = report.finding.kind != sim::DivergenceKind::StepUnderflow && report.finding.body == 0 &&
                         !report.finding.what.empty();
      r.outcome = clear ? Outcome::Guarded : Outcome::Failed;
    }
    if (r.penetrated_within_estimate()) {
      r.outcome = Outcome::Failed;
      char text[160];
      std::snprintf(text, sizeof text,
                    "tunnelled: a vertex went %.3g m into the floor in one step (shortest edge %.3g m)",
                    r.deepest_penetration_m, r.shortest_edge_m);
      r.message = text;
    }
    r.steps = world.state.steps;
    r.simulated_s = world.state.time_s;
  } catch (const std::exception& e) {
    r.outcome = Outcome::Failed;
    r.message = std::string("exception: ") + e.what();
  }
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

void write_stress_csv(const std::vector<StressResult>& results, const std::filesystem::path& file) {
  std::ofstream out(file);
  out << "group,shape,vertices,integrator,stiffness,damping,pressure,drop_speed,retry,dt,estimate_dt,"
         "dt_over_estimate,outcome,guarded_within_estimate,steps,simulated_s,wall_s,deepest_penetration,shortest_edge,"
         "message\n";
  for (const StressResult& r : results) {
    const StressCase& c = r.spec;
    std::string message = r.message;
    for (char& ch : message)
      if (ch == '"') ch = '\'';
    char row[512];
    std::snprintf(
        row, sizeof row, "%s,\"%s\",%d,%s,%.6g,%.6g,%.6g,%.6g,%d,%.6g,%.6g,%.6g,%s,%d,%lld,%.6g,%.4g,%.6g,%.6g,",
        c.group.c_str(), c.shape.c_str(), r.vertices, sim::to_string(c.integrator).c_str(), c.stiffness_N_per_m,
        c.damping_N_s_per_m, c.pressure_J, c.drop_speed_m_per_s, c.retry ? 1 : 0, r.dt_s, r.estimate_dt_s,
        r.dt_s / r.estimate_dt_s, to_string(r.outcome).c_str(), r.guarded_within_estimate() ? 1 : 0, r.steps,
        r.simulated_s, r.wall_s, r.deepest_penetration_m, r.shortest_edge_m);
    out << row << '"' << message << "\"\n";
  }
  if (!out) throw std::runtime_error("cannot write " + file.string());
}

std::vector<std::filesystem::path> write_stability_maps(const std::vector<StressResult>& results,
                                                        const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> written;
  const std::filesystem::path script = dir / "stability_maps.gp";
  std::ofstream gp(script);
  gp << "set terminal pngcairo size 720,540 font ',11'\nset logscale xy\nset format x '10^{%L}'\n"
        "set format y '10^{%L}'\nset xlabel 'spring stiffness k [N/m]'\nset ylabel 'time step dt [s]'\n"
        "set key outside bottom center horizontal\nset xrange [3:3e6]\nset yrange [5e-7:2e-2]\n";
  for (const sim::IntegratorInfo& listed : sim::kIntegrators) {
    const IntegratorKind integrator = listed.kind;
    const std::string name = sim::to_string(integrator);
    // One data file per series: gnuplot skips empty blocks of a multi-block file and renumbers the rest.
    auto data = [&](const std::string& series) { return dir / ("stability_map_" + name + "_" + series + ".dat"); };
    for (Outcome o : {Outcome::Stable, Outcome::Guarded, Outcome::Failed}) {
      std::ofstream out(data(to_string(o)));
      out << "# stiffness [N/m], dt [s]: " << to_string(o) << " runs of the map group, c > 0\n";
      for (const StressResult& r : results) {
        if (r.spec.group == "map" && r.spec.integrator == integrator && r.spec.damping_N_s_per_m > 0 &&
            r.outcome == o) {
          out << r.spec.stiffness_N_per_m << " " << r.dt_s << "\n";
        }
      }
    }
    std::ofstream estimate(data("estimate"));
    estimate << "# stiffness [N/m], estimated stable dt [s]\n";
    for (const StressResult& r : results) {
      if (r.spec.group == "map" && r.spec.integrator == integrator && r.spec.damping_N_s_per_m > 0 &&
          r.spec.dt_s == 1e-6 && std::isfinite(r.estimate_dt_s) && r.estimate_dt_s > 0) {
        estimate << r.spec.stiffness_N_per_m << " " << r.estimate_dt_s << "\n";
      }
    }
    estimate.close();
    const std::filesystem::path png = dir / ("stability_map_" + name + ".png");
    gp << "set output '" << png.string() << "'\nset title '" << name
       << ": icosphere:1, 1 kg, c = 0.5 N s/m, nRT = 30 J, floor, 0.3 s'\n"
       << "plot '" << data("stable").string() << "' with points pt 7 ps 1.2 lc rgb '#2e8b57' title 'stable', '"
       << data("guarded").string() << "' with points pt 9 ps 1.4 lc rgb '#e69f00' title 'stopped by the guard', '"
       << data("failed").string() << "' with points pt 2 ps 2 lc rgb '#d00000' title 'failed', '"
       << data("estimate").string() << "' with lines lw 2 lc rgb '#1f3a93' title 'estimated stable dt'\n";
    written.push_back(png);
  }
  gp.close();
  const std::string command = "gnuplot '" + script.string() + "' 2>/dev/null";
  if (std::system(command.c_str()) != 0) {
    std::fprintf(stderr, "warning: gnuplot failed or is missing; the maps' data and script are in %s\n", dir.c_str());
    return {};
  }
  return written;
}

}  // namespace analysis
