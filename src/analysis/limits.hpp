// Estimated against measured stable dt, per integrator, on a few named bodies in free flight.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "sim/step/world.hpp"

namespace analysis {

struct LimitBody {
  std::string name;
  std::string mesh;  // generator spec (unit size, 1 kg)
  double stiffness_N_per_m, damping_N_s_per_m, pressure_J;
};

struct LimitRow {
  LimitBody body;
  sim::IntegratorKind integrator;
  bool floor;            // resting on the paper floor (else free flight)
  double estimate_dt_s;  // sim/step/stability.hpp
  double measured_dt_s;  // largest stable dt found by bisection (3 %)
  double unstable_dt_s;  // smallest unstable dt found
};

// The bodies of docs/physics/stability.md's table: scenes/bounce.json's ball, a stiff undamped breathing sphere, a
// coarse stiff ball, and the bounce ball's material on icosphere:4 (its fastest modes more than half critically
// damped).
std::vector<LimitBody> limit_bodies();

// A world of `body` alone, gravity on, every vertex shaken by 0.5 m/s (rk45: fixed steps): in free flight,
// or (`floor`) 5 cm above the paper floor, so that it lands and rests on it within the trial.
sim::World limit_world(const LimitBody& body, sim::IntegratorKind integrator, bool floor = false);

// Measures every explicit integrator (xpbd and vbd have no spring limit), in free flight and on the floor, over
// `steps` steps per trial.
std::vector<LimitRow> measure_limits(const std::vector<LimitBody>& bodies, int steps);

void write_limits_csv(const std::vector<LimitRow>& rows, const std::filesystem::path& file);

}  // namespace analysis
