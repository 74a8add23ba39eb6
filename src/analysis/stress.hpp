// The stability stress sweep: many short runs over stiffness, dt, mesh, pressure, damping, impact speed
// and odd meshes for every integrator; each must end stable or be stopped by the divergence guard.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace analysis {

struct StressCase {
  std::string group;  // "map" (dt × stiffness grid), "mesh", "pressure", "damping", "drop", "odd", "retry"
  std::string shape;  // a generator spec, or "flattened", "elongated", "tiny-triangles"
  sim::IntegratorKind integrator = sim::IntegratorKind::Euler;
  double stiffness_N_per_m = 3000.0;
  double damping_N_s_per_m = 0.5;
  double pressure_J = 30.0;
  double drop_speed_m_per_s = 0.0;  // downward speed at the start; > 0 starts 1 m above the floor
  bool retry = false;               // solver.retry
  double dt_s = 0.0;                // > 0: this dt; 0: dt_factor × the estimate
  double dt_factor = 1.0;
};

enum class Outcome { Stable, Guarded, Failed };
std::string to_string(Outcome outcome);

struct StressResult {
  StressCase spec;
  int vertices = 0;
  double dt_s = 0.0;
  double estimate_dt_s = 0.0;  // the stable-dt estimate for the case's integrator (inf: no limit)
  Outcome outcome = Outcome::Failed;
  long long steps = 0;
  double simulated_s = 0.0;
  double wall_s = 0.0;
  double deepest_penetration_m = 0.0;  // deepest a vertex got into the floor in one step, before it was put back
  double shortest_edge_m = 0.0;        // the body's shortest rest edge: the travel limit's unit
  std::string message;                 // the guard's message, or what failed
  // The estimate's promise broken: stopped by the guard at a dt at or below the estimated stable dt
  // (fixed-step runs; rk45 chooses its own steps). The sweep counts these as failures of the estimate.
  bool guarded_within_estimate() const {
    return outcome == Outcome::Guarded && !spec_adaptive() && dt_s <= estimate_dt_s;
  }
  bool spec_adaptive() const { return spec.integrator == sim::IntegratorKind::Rk45; }
  // The travel limit's promise broken on an impact: a dropped body, at a dt the estimate calls stable (which
  // includes the contact limit of a tenth of the shortest edge per step at the speed of the fall,
  // sim/step/stability.hpp), had a vertex go more than kDeepPenetrationEdges edges into the floor in one step: the
  // step carried it through, and the projection crushed the body. (Other groups record the depth only: a gas
  // of 1e5 J that blows the body up drives vertices faster than any speed the estimate sees at the start.)
  bool penetrated_within_estimate() const {
    return spec.group == "drop" && !spec_adaptive() && dt_s <= estimate_dt_s &&
           deepest_penetration_m > kDeepPenetrationEdges * shortest_edge_m;
  }
  static constexpr double kDeepPenetrationEdges = 0.5;  // 5 × the travel limit's tenth of an edge
};

// The sweep: the full one (≥ 1000 runs) or a quick subset for ctest's `stress` label.
std::vector<StressCase> stress_cases(bool quick);

// Builds and runs one case; never throws (whatever goes wrong is the result's Failed outcome).
StressResult run_stress_case(const StressCase& spec);

// stress.csv, one row per run.
void write_stress_csv(const std::vector<StressResult>& results, const std::filesystem::path& file);

// stability_map_<integrator>.png per integrator (gnuplot), from the "map" group: dt against stiffness,
// stable / guarded / failed, with the estimate drawn over it. Returns the files written (none without gnuplot).
std::vector<std::filesystem::path> write_stability_maps(const std::vector<StressResult>& results,
                                                        const std::filesystem::path& dir);

}  // namespace analysis
