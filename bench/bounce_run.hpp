// The issue-13 bounce for one integrator, floor contact and step (or Bullet's btSoftBody), recorded every 1/60 s.
#pragma once

#include <string>
#include <vector>

#include "core/vec.hpp"
#include "sim/model/settings.hpp"
#include "sim/step/world.hpp"

namespace bench {

// Every recorded run samples at this interval from t = 0; every fixed step measured divides it.
constexpr double kBounceSampleInterval_s = 1.0 / 60;

// What one run of scenes/bounce.json as issue 13 sets it up (k 1000 N/m, c 1 N·s/m, nRT 50 J, 1 kg, thrown
// sideways at 2 m/s from 2 m above the floor) varies.
struct BounceSetup {
  int level = 3;  // icosphere subdivision level
  sim::IntegratorKind integrator = sim::IntegratorKind::Symplectic;
  sim::FloorContact contact = sim::FloorContact::Smooth;
  double dt_s = 0.0;        // 0: the integrator's automatic step (dt: "auto"; xpbd: substeps: "auto"); else
                            // the largest step <= dt_s that divides kBounceSampleInterval_s (rk45: first trial)
  double tolerance = 1e-6;  // rk45 only: solver.tolerance
};

// What a run recorded, every kBounceSampleInterval_s from t = 0 (fewer samples when it failed).
struct BounceRecord {
  std::vector<double> volume_m3;
  std::vector<softbody::Vec3> com_m;
  std::vector<std::vector<softbody::Vec3>> x_m;  // every vertex's position
  double dt_s = 0.0;                             // the step taken (rk45: the mean accepted step over the run)
  long long steps = 0;                           // accepted steps
  double wall_s = 0.0;                           // stepping only, wall clock
  double cpu_s = 0.0;   // stepping only, this thread's CPU time (what an idle core would take: the machine is shared)
  std::string failure;  // empty, or the guard's (or Bullet's non-finite state's) message
};

// The world of `setup`, with `dt: "auto"` and xpbd's `substeps: "auto"` resolved as `softbody simulate` does
// (src/app/prepared_run.cpp) and made to divide the sample interval; the step it will take goes to dt_s.
sim::World bounce_world(const BounceSetup& setup, double& dt_s);

// Steps `setup` for duration_s simulated seconds (one thread), sampling as above.
BounceRecord record_bounce(const BounceSetup& setup, double duration_s);

// Bullet's btSoftBody (bench/bullet_pressure_body.hpp) on the same triangles, rest positions, start velocity,
// mass, gas (kPR = nRT), gravity and floor, at fixed steps of dt_s. Its own model: its links are Bullet's
// position-based ones at their default stiffness, not our springs, and it runs in single precision.
BounceRecord record_bullet_bounce(int level, double dt_s, double duration_s);

}  // namespace bench
