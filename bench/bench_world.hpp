// The benchmark scene: scenes/bounce.json's ball at a chosen icosphere level, integrator and switches.
#pragma once

#include <string>

#include "scene/scene.hpp"
#include "sim/step/world.hpp"

namespace bench {

// What a benchmark varies on top of bounce.json (springs, dampers, pressure, gravity, paper floor).
struct BenchCase {
  int level = 3;  // icosphere subdivision level (1..6)
  sim::IntegratorKind integrator = sim::IntegratorKind::Symplectic;
  bool pressure = true;   // false: nRT = 0 (no volume or pressure pass)
  bool damping = true;    // false: c = 0 (no damper term)
  bool floor = true;      // false: no floor (no contact pass)
  bool on_floor = false;  // true: starts touching the floor (centre at y = 1 m)
  int threads = 1;        // solver.threads (large bodies' force passes)
};

// The time step used at `level`: bounce.json's 1e-4 s up to level 4, then quartered per level, because
// each level halves the edge length and quarters the vertex mass (the stiff modes speed up).
double bench_dt_s(int level);

// The scene for `c`, read from scenes/bounce.json and changed as `c` says.
scene::Scene bench_scene(const BenchCase& c);

// The world of bench_scene(c).
sim::World bench_world(const BenchCase& c);

// scenes/pile.json's bodies (three pillows and a ball, 1800 vertices) on its friction floor, either stacked
// (each resting on the one below: body–body contact in every step) or set apart in a row on the floor (the
// same bodies and floor contact, no body–body contact). Symplectic Euler at the scene's dt.
scene::Scene contact_scene(bool touching);

// The world of contact_scene(touching), advanced `settle_steps` steps so that the stack has come into contact.
sim::World contact_world(bool touching, int settle_steps);

}  // namespace bench
